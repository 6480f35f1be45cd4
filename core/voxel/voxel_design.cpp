// SPDX-License-Identifier: GPL-3.0-or-later
// Algorithm 1 (paper Section 4.1): depth-first construction with ranked children and backtracking
// to siblings and ancestors, held in an explicit stack (no recursion: WebAssembly's stack is
// small and N can be in the thousands). A level stores its children as the voxels of the new part
// only, so memory grows with N times m small lists, not with N grids.
#include <chrono>
#include <optional>
#include <sstream>

#include "desia/error.h"
#include "desia/voxel_design.h"
#include "voxel/design_internals.h"

namespace desia {

CandidateRanking parseCandidateRanking(const std::string& name) {
  if (name == "compactness") return CandidateRanking::Compactness;
  if (name == "x") return CandidateRanking::LowestX;
  if (name == "y") return CandidateRanking::LowestY;
  if (name == "z") return CandidateRanking::LowestZ;
  if (name == "-x") return CandidateRanking::HighestX;
  if (name == "-y") return CandidateRanking::HighestY;
  if (name == "-z") return CandidateRanking::HighestZ;
  throwBadInput("", "unknown ranking '" + name + "' (expected compactness, x, y, z, -x, -y or -z)");
}

const char* candidateRankingName(CandidateRanking ranking) {
  switch (ranking) {
    case CandidateRanking::Compactness: return "compactness";
    case CandidateRanking::LowestX: return "x";
    case CandidateRanking::LowestY: return "y";
    case CandidateRanking::LowestZ: return "z";
    case CandidateRanking::HighestX: return "-x";
    case CandidateRanking::HighestY: return "-y";
    case CandidateRanking::HighestZ: return "-z";
  }
  return "compactness";
}

DesignMode parseDesignMode(const std::string& name) {
  if (name == "desia") return DesignMode::Desia;
  if (name == "recursive") return DesignMode::Recursive;
  throwBadInput("", "unknown mode '" + name + "' (expected desia or recursive)");
}

const char* designModeName(DesignMode mode) { return mode == DesignMode::Recursive ? "recursive" : "desia"; }

const char* designStatusName(DesignStatus status) {
  switch (status) {
    case DesignStatus::Success: return "success";
    case DesignStatus::NotFound: return "not-found";
    case DesignStatus::LimitReached: return "limit-reached";
    case DesignStatus::Cancelled: return "cancelled";
  }
  return "not-found";
}

namespace {

using design::Candidate;
using design::DesignContext;

// The shape as one part (label 1) and its voxel count; throws for impossible requests.
VoxelGrid normalizedShape(const VoxelGrid& shape, const VoxelDesignOptions& options, int64_t* voxelCount) {
  VoxelGrid grid = shape;
  int64_t count = 0;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != 0) {
      grid.setLabelAt(i, 1);
      ++count;
    }
  }
  if (count == 0) throwBadInput("", "the shape is empty: it has no voxels");
  if (!design::isFaceConnected(grid, 1)) {
    throwBadInput("", "the shape is not face-connected: a puzzle needs one connected voxel set");
  }
  if (options.parts < 3) {
    throwBadInput("", "--parts " + std::to_string(options.parts) + ": an interlocking puzzle needs at least 3 parts");
  }
  if (static_cast<int64_t>(options.parts) * 2 > count) {
    throwBadInput("", "--parts " + std::to_string(options.parts) + " is too many for a shape of " + std::to_string(count) +
                          " voxels (each part needs at least 2 voxels, so at most " + std::to_string(count / 2) + " parts)");
  }
  if (options.candidates < 1) throwBadInput("", "--candidates must be at least 1");
  const Int3& d = options.keyDirection;
  if (std::abs(d.x) + std::abs(d.y) + std::abs(d.z) != 1) throwBadInput("", "the key direction must be an axis (+x, -y, ...)");
  *voxelCount = count;
  return grid;
}

DesignContext makeContext(const VoxelGrid& grid, const VoxelDesignOptions& options, int64_t voxelCount) {
  DesignContext context{options, {}, options.groups, voxelCount, std::mt19937_64(options.seed)};
  if (options.groups.empty()) return context;
  context.groupOf.assign(static_cast<size_t>(grid.voxelCount()), -1);
  for (size_t g = 0; g < options.groups.size(); ++g) {
    for (int64_t v : options.groups[g]) {
      if (v < 0 || v >= grid.voxelCount() || grid.labelAt(v) == 0) {
        throwBadInput("", "group " + std::to_string(g + 1) + " has voxel " + std::to_string(v) + " outside the shape");
      }
      if (context.groupOf[v] >= 0 && context.groupOf[v] != static_cast<int>(g)) {
        throwBadInput("", "groups " + std::to_string(context.groupOf[v] + 1) + " and " + std::to_string(g + 1) +
                              " share voxel " + std::to_string(v));
      }
      context.groupOf[v] = static_cast<int>(g);
    }
  }
  return context;
}

int64_t countLabel(const VoxelGrid& grid, int label) {
  int64_t count = 0;
  for (int v : grid.labels()) count += v == label ? 1 : 0;
  return count;
}

// The final check (Section 4.1 requirements, by the foundation's own tests): interlocking with
// part 1 as key, and a disassembly in the order 1, 2, ..., N.
bool verifyPuzzle(const VoxelGrid& grid, int parts, CheckReport* report) {
  const AssemblyDocument document = documentFromVoxels(grid);
  *report = checkAssembly(document);
  if (report->result.verdict != Verdict::Interlocking || report->result.key != 0) return false;
  if (!report->disassembly || !report->disassembly->complete) return false;
  for (int k = 0; k < parts; ++k) {
    if (report->disassembly->removals[k].part != k) return false;
  }
  return true;
}

struct Level {
  std::vector<Candidate> children;
  size_t next = 0;
};

class Search {
 public:
  Search(VoxelGrid grid, const VoxelDesignOptions& options, DesignContext& context)
      : grid_(std::move(grid)), options_(options), context_(context), start_(std::chrono::steady_clock::now()) {}

  VoxelDesignResult run() {
    VoxelDesignResult result;
    levels_.push_back({childrenOfCurrentNode()});
    while (true) {
      if (const auto stop = stopReason()) return finish(*stop, result);
      Level& level = levels_.back();
      if (level.next == level.children.size()) {
        if (!backtrack()) return finish(DesignStatus::NotFound, result);
        continue;
      }
      const int remainder = depth_ + 1;
      design::applyCandidate(grid_, remainder, level.children[level.next++]);
      ++depth_;
      ++progress_.nodesVisited;
      if (depth_ > progress_.bestDepth) progress_.bestDepth = depth_;
      if (!report()) return finish(DesignStatus::Cancelled, result);
      if (depth_ == options_.parts - 1) {
        if (verifyPuzzle(grid_, options_.parts, &result.verification)) {
          result.puzzle = grid_;
          return finish(DesignStatus::Success, result);
        }
        ++verificationFailures_;  // never expected: every level was checked exactly
        levels_.push_back({});
        continue;
      }
      levels_.push_back({childrenOfCurrentNode()});
    }
  }

 private:
  std::vector<Candidate> childrenOfCurrentNode() {
    const int remainder = depth_ + 1;
    const int partsLeft = options_.parts - depth_;  // parts still to make, the final remainder included
    const int target = design::targetPartSize(countLabel(grid_, remainder), partsLeft);
    if (depth_ == 0) return design::generateKeyCandidates(grid_, context_, target);
    return design::generatePartCandidates(grid_, remainder, context_, target, partsLeft - 1);
  }

  // Algorithm 1 lines 18-29: the next sibling, or the nearest ancestor's next sibling.
  bool backtrack() {
    levels_.pop_back();
    if (levels_.empty()) return false;
    design::undoCandidate(grid_, depth_);
    --depth_;
    ++backtracks_;
    return true;
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  std::optional<DesignStatus> stopReason() const {
    if (options_.timeLimitSeconds > 0 && elapsed() > options_.timeLimitSeconds) return DesignStatus::LimitReached;
    if (options_.nodeLimit > 0 && progress_.nodesVisited >= options_.nodeLimit) return DesignStatus::LimitReached;
    return std::nullopt;
  }

  bool report() {
    progress_.depth = depth_;
    progress_.targetParts = options_.parts;
    progress_.elapsedSeconds = elapsed();
    return !options_.onProgress || options_.onProgress(progress_);
  }

  VoxelDesignResult& finish(DesignStatus status, VoxelDesignResult& result) {
    progress_.depth = depth_;
    progress_.targetParts = options_.parts;
    progress_.elapsedSeconds = elapsed();
    result.status = status;
    result.progress = progress_;
    std::ostringstream message;
    const std::string reached = "the deepest node had " + std::to_string(progress_.bestDepth + 1) + " of " +
                                std::to_string(options_.parts) + " parts (" + std::to_string(progress_.nodesVisited) +
                                " nodes visited, " + std::to_string(backtracks_) + " backtracks)";
    switch (status) {
      case DesignStatus::Success:
        message << "designed and verified a " << options_.parts << "-part interlocking puzzle (" << progress_.nodesVisited
                << " nodes visited, " << backtracks_ << " backtracks)";
        break;
      case DesignStatus::NotFound:
        message << "no " << options_.parts << "-part interlocking puzzle exists in the explored space (m = "
                << options_.candidates << ", seed " << options_.seed << "): " << reached;
        break;
      case DesignStatus::LimitReached:
        message << "stopped at the " << (options_.nodeLimit > 0 && progress_.nodesVisited >= options_.nodeLimit ? "node" : "time")
                << " limit: " << reached;
        break;
      case DesignStatus::Cancelled:
        message << "cancelled: " << reached;
        break;
    }
    if (verificationFailures_ > 0) message << "; " << verificationFailures_ << " complete candidates failed verification";
    result.message = message.str();
    return result;
  }

  VoxelGrid grid_;
  const VoxelDesignOptions& options_;
  DesignContext& context_;
  std::chrono::steady_clock::time_point start_;
  std::vector<Level> levels_;
  int depth_ = 0;
  int64_t backtracks_ = 0;
  int64_t verificationFailures_ = 0;
  DesignProgress progress_;
};

}  // namespace

VoxelDesignResult designVoxelPuzzle(const VoxelGrid& shape, const VoxelDesignOptions& options) {
  int64_t voxelCount = 0;
  VoxelGrid grid = normalizedShape(shape, options, &voxelCount);
  VoxelDesignOptions effective = options;
  if (effective.minPartSize <= 0) effective.minPartSize = std::max<int>(2, static_cast<int>(voxelCount / options.parts / 4));
  DesignContext context = makeContext(grid, effective, voxelCount);
  return Search(std::move(grid), effective, context).run();
}

}  // namespace desia
