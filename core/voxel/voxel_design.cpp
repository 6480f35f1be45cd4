// SPDX-License-Identifier: GPL-3.0-or-later
// Algorithm 1 (paper Section 4.1): depth-first construction with ranked children and backtracking
// to siblings and ancestors, held in an explicit stack (no recursion: WebAssembly's stack is
// small and N can be in the thousands). A level stores its children as the voxels of the new part
// only, so memory grows with N times m small lists, not with N grids.
#include <algorithm>
#include <sstream>

#include "desia/error.h"
#include "desia/voxel.h"
#include "search/construction_search.h"
#include "search/restarts.h"
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

PartSizeBounds evenPartBounds(int64_t voxels, int parts) {
  const int64_t n = std::max(1, parts);
  const int64_t floorMean = voxels / n, ceilMean = (voxels + n - 1) / n;
  const int64_t tolerance = std::max<int64_t>(1, static_cast<int64_t>(kEvenPartsTolerance * static_cast<double>(voxels) / n));
  return {static_cast<int>(std::max<int64_t>(1, floorMean - tolerance)), static_cast<int>(ceilMean + tolerance)};
}

PartSizeSpread partSizeSpread(const VoxelGrid& puzzle) {
  const std::vector<int64_t> counts = puzzle.labelCounts();  // entry 0: empty voxels
  PartSizeSpread spread;
  if (counts.size() < 2) return spread;
  const auto [smallest, largest] = std::minmax_element(counts.begin() + 1, counts.end());
  int64_t total = 0;
  for (size_t k = 1; k < counts.size(); ++k) total += counts[k];
  spread.min = static_cast<int>(*smallest);
  spread.max = static_cast<int>(*largest);
  spread.mean = static_cast<double>(total) / static_cast<double>(counts.size() - 1);
  return spread;
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
    throwBadInput("", "parts = " + std::to_string(options.parts) + ": an interlocking puzzle needs at least 3 parts");
  }
  if (static_cast<int64_t>(options.parts) * 2 > count) {
    throwBadInput("", "parts = " + std::to_string(options.parts) + " is too many for a shape of " + std::to_string(count) +
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
  // The designer's puzzles come apart one part at a time (Section 4.1): the single-part planner
  // decides, without the complete disassembler's search for moves of several parts.
  VoxelDisassemblyOptions singleParts;
  singleParts.groupMoves = false;
  *report = checkVoxelAssembly(grid, {}, singleParts);
  if (report->result.verdict != Verdict::Interlocking || report->result.key != 0) return false;
  if (!report->disassembly || !report->disassembly->complete) return false;
  for (int k = 0; k < parts; ++k) {
    if (report->disassembly->removals[k].part != k) return false;
  }
  // What the result says of itself is what `desia check` says of it: the level and the fewest
  // moves too (the complete disassembler runs only here, once a puzzle is verified).
  report->disassembly = planVoxelDisassembly(grid, assemblyFromVoxels(grid));
  return true;
}

// The construction tree of Algorithm 1 along the current path: one level per node from the root,
// each with its ranked children (generated when first needed) and the next one to try. The grid
// always holds the current node's assembly. A search may be confined to the subtree of one node
// (the floor: a session's "finish from here"); it never ascends above it.
class VoxelConstructionTree {
 public:
  VoxelConstructionTree(VoxelGrid grid, const VoxelDesignOptions& options, DesignContext& context)
      : grid_(std::move(grid)), options_(options), context_(context), levels_(1) {
    levels_[0].seed = options.seed;
  }

  const VoxelGrid& grid() const { return grid_; }
  int depth() const { return static_cast<int>(levels_.size()) - 1; }  // parts placed
  int floorDepth() const { return static_cast<int>(floor_); }
  uint64_t floorSeed() const { return levels_[floor_].seed; }

  // Confines the tree to the current node's subtree, whose children are tried again from the best
  // ranked: what the search does from there does not depend on what a user tried before.
  void makeCurrentTheFloor() {
    floor_ = levels_.size() - 1;
    levels_.back().next = 0;
  }

  const std::vector<Candidate>& children() {
    Level& level = levels_.back();
    if (!level.generated) {
      level.children = generateChildren();
      level.generated = true;
    }
    return level.children;
  }

  VoxelGrid preview(size_t child) {
    VoxelGrid copy = grid_;
    design::applyCandidate(copy, depth() + 1, children().at(child));
    return copy;
  }

  void descend(size_t child) {
    const Candidate& candidate = children().at(child);
    levels_.back().next = std::max(levels_.back().next, child + 1);
    design::applyCandidate(grid_, depth() + 1, candidate);
    const uint64_t parentSeed = levels_.back().seed;
    levels_.emplace_back();
    levels_.back().seed = childSeed(parentSeed, child);
  }

  // Algorithm 1: the next untried child of the current node, if any.
  bool descendToNextUntriedChild() {
    if (levels_.back().next >= children().size()) return false;
    descend(levels_.back().next);
    return true;
  }

  // Back to the floor (the root unless confined) with a new seed for it: a new subtree (restarts,
  // see Search).
  void restart(uint64_t floorSeed) {
    while (ascend()) {
    }
    levels_[floor_] = Level{};
    levels_[floor_].seed = floorSeed;
  }

  // Back to the parent (its remaining children stay available); false at the floor.
  bool ascend() {
    if (levels_.size() == floor_ + 1) return false;
    levels_.pop_back();
    design::undoCandidate(grid_, depth() + 1);
    return true;
  }

 private:
  struct Level {
    std::vector<Candidate> children;
    bool generated = false;
    size_t next = 0;
    uint64_t seed = 0;  // the node's own random stream: children depend on the path only
  };

  // SplitMix64 of the parent's seed and the child's rank: a node's children do not depend on
  // which other nodes were expanded before (the step-by-step session and the search agree).
  static uint64_t childSeed(uint64_t parent, size_t child) {
    uint64_t z = parent + 0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(child) + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::vector<Candidate> generateChildren() {
    context_.random.seed(levels_.back().seed);
    const int remainder = depth() + 1;
    const int partsLeft = options_.parts - depth();  // parts still to make, the final remainder included
    if (partsLeft <= 1) return {};
    const int target = design::targetPartSize(countLabel(grid_, remainder), partsLeft);
    if (depth() == 0) return design::generateKeyCandidates(grid_, context_, target);
    return design::generatePartCandidates(grid_, remainder, context_, target, partsLeft - 1);
  }

  VoxelGrid grid_;
  const VoxelDesignOptions& options_;
  DesignContext& context_;
  std::vector<Level> levels_;
  size_t floor_ = 0;  // the level searches never ascend above
};

// The construction tree as the shared search walks it (search/construction_search.h): a step
// tries the next untried child of the current node, else goes back to the parent; a complete
// puzzle is accepted once the project's own check verified it.
class VoxelSearchTree : public search::ConstructionTree {
 public:
  // A search of `tree`'s subtree below its floor (its root unless confined); `options` gives the
  // parts and the seed.
  VoxelSearchTree(VoxelConstructionTree& tree, const VoxelDesignOptions& options, VoxelDesignResult& result)
      : tree_(tree), options_(options), result_(result), floorSeed_(tree.floorSeed()) {}

  // Attempt 0 is the tree as it stands (the floor's own seed); later attempts re-seed the floor.
  void restart(int64_t attempt) override {
    if (attempt > 0) tree_.restart(restartState(floorSeed_, attempt, floorSeed_, kVoxelRestartSalt));
  }

  // Nodes restart `attempt` may visit: the path to a complete puzzle (N - 1 nodes) plus room to
  // backtrack that grows with N, times the Luby term.
  bool budgetSpent(int64_t attempt, int64_t nodes) const override {
    const int64_t n = options_.parts - tree_.floorDepth();  // the parts the subtree still decides
    return nodes >= (n - 1) + kRestartUnitPerPart * n * lubyTerm(attempt);
  }

  search::Move step() override {
    if (tree_.descendToNextUntriedChild()) return search::Move::Entered;
    return tree_.ascend() ? search::Move::Returned : search::Move::Exhausted;
  }

  int depth() const override { return tree_.depth() + 1; }  // parts placed and the remainder
  bool complete() const override { return tree_.depth() == options_.parts - 1; }

  bool acceptComplete() override {
    if (!verifyPuzzle(tree_.grid(), options_.parts, &result_.verification)) return false;  // never expected
    result_.puzzle = tree_.grid();
    return true;
  }

  // A copy of the current node, the deepest so far, for a live view. Reads the tree, never the
  // random state or the stack, so the search is the same with or without it.
  void snapshotDeepest(DesignProgress& progress) const override {
    progress.deepestGrid = std::make_shared<const VoxelGrid>(tree_.grid());
  }

 private:
  static constexpr int64_t kRestartUnitPerPart = 8;

  VoxelConstructionTree& tree_;
  const VoxelDesignOptions& options_;
  VoxelDesignResult& result_;
  uint64_t floorSeed_;  // restarts derive their seeds from it (the user's seed for a whole design)
};

std::string reachedText(const VoxelDesignOptions& options, const DesignProgress& progress, const search::SearchCounts& counts) {
  return "the deepest node had " + std::to_string(progress.bestDepth) + " of " + std::to_string(options.parts) +
         " parts (" + std::to_string(progress.nodes) + " nodes visited, " + std::to_string(counts.backtracks) +
         " backtracks, " + std::to_string(counts.restarts) + " restarts)";
}

std::string outcomeMessage(DesignStatus status, bool nodeLimit, const VoxelDesignOptions& options,
                           const DesignProgress& progress, const search::SearchCounts& counts) {
  std::ostringstream message;
  switch (status) {
    case DesignStatus::Success:
      message << "designed and verified a " << options.parts << "-part interlocking puzzle (" << progress.nodes
              << " nodes visited, " << counts.backtracks << " backtracks, " << counts.restarts << " restarts)";
      break;
    case DesignStatus::LimitReached:
      message << "stopped at the " << (nodeLimit ? "node" : "time") << " limit: " << reachedText(options, progress, counts);
      break;
    case DesignStatus::Cancelled:
      message << "cancelled: " << reachedText(options, progress, counts);
      break;
    default:
      message << "no " << options.parts << "-part interlocking puzzle exists in the explored space (m = "
              << options.candidates << ", seed " << options.seed << "): " << reachedText(options, progress, counts);
  }
  if (counts.rejectedComplete > 0) message << "; " << counts.rejectedComplete << " complete candidates failed verification";
  return message.str();
}

DesignStatus statusOf(search::SearchEnd end) {
  switch (end) {
    case search::SearchEnd::Found: return DesignStatus::Success;
    case search::SearchEnd::NodeLimit:
    case search::SearchEnd::TimeLimit: return DesignStatus::LimitReached;
    case search::SearchEnd::Cancelled: return DesignStatus::Cancelled;
    case search::SearchEnd::Exhausted: break;
  }
  return DesignStatus::NotFound;
}

// The search of `tree`'s subtree below its floor; a floor that is already complete (a finished
// session) has nothing left to search and is only verified.
VoxelDesignResult searchPuzzle(VoxelConstructionTree& tree, const VoxelDesignOptions& options) {
  VoxelDesignResult result;
  result.seed = options.seed;
  DesignProgress& progress = result.progress;
  progress.targetParts = options.parts;
  progress.bestDepth = progress.depth = tree.depth() + 1;  // the floor's parts are placed already
  if (options.limits.deepestSnapshots) progress.deepestGrid = std::make_shared<const VoxelGrid>(tree.grid());
  VoxelSearchTree searchTree(tree, options, result);
  search::ConstructionSearch search(searchTree, options.limits, search::SearchRules{});
  search::SearchEnd end = search::SearchEnd::Exhausted;
  if (tree.depth() == options.parts - 1) {
    if (searchTree.acceptComplete()) end = search::SearchEnd::Found;
  } else {
    end = search.run(progress);
  }
  progress.depth = tree.depth() + 1;
  progress.seconds = search.seconds();
  result.status = statusOf(end);
  if (result.status == DesignStatus::Success) result.partSizes = partSizeSpread(result.puzzle);
  result.message = outcomeMessage(result.status, end == search::SearchEnd::NodeLimit, options, progress, search.counts());
  return result;
}

std::string sizeText(const char* what, int size) { return std::string(what) + " part size " + std::to_string(size); }

// Refuses part size bounds that no N parts covering the shape can meet, naming the values.
void checkPartSizeBounds(const VoxelDesignOptions& options, int64_t voxelCount) {
  const int64_t n = options.parts, minSize = options.minPartSize, maxSize = options.maxPartSize;
  const std::string shape = "the shape's " + std::to_string(voxelCount) + " voxels";
  if (minSize < 0 || maxSize < 0) throwBadInput("", "part sizes must be positive (0: automatic)");
  if (maxSize > 0 && minSize > maxSize) {
    throwBadInput("", sizeText("max", options.maxPartSize) + " is less than " + sizeText("min", options.minPartSize));
  }
  if (maxSize > 0 && maxSize * n < voxelCount) {
    throwBadInput("", sizeText("max", options.maxPartSize) + " is too small: " + std::to_string(n) + " parts of at most " +
                          std::to_string(maxSize) + " voxels hold " + std::to_string(maxSize * n) + ", fewer than " + shape);
  }
  if (minSize * n > voxelCount) {
    throwBadInput("", sizeText("min", options.minPartSize) + " is too large: " + std::to_string(n) + " parts of at least " +
                          std::to_string(minSize) + " voxels need " + std::to_string(minSize * n) + ", more than " + shape);
  }
}

// Options with the automatic values filled in: the automatic minimum, no maximum as the whole
// shape, and the even-size bounds intersected with the user's. (Bounds that pass
// checkPartSizeBounds hold the mean voxels / N between them, as the even bounds and the automatic
// minimum do, so the intersection is never empty.)
VoxelDesignOptions effectiveOptions(const VoxelDesignOptions& options, int64_t voxelCount) {
  checkPartSizeBounds(options, voxelCount);
  VoxelDesignOptions effective = options;
  if (effective.minPartSize <= 0) effective.minPartSize = std::max<int>(2, static_cast<int>(voxelCount / options.parts / 4));
  if (effective.maxPartSize <= 0) effective.maxPartSize = static_cast<int>(voxelCount);
  if (options.evenParts) {
    const PartSizeBounds even = evenPartBounds(voxelCount, options.parts);
    effective.minPartSize = std::max(effective.minPartSize, even.min);
    effective.maxPartSize = std::min(effective.maxPartSize, even.max);
  }
  return effective;
}

}  // namespace

VoxelDesignResult designVoxelPuzzle(const VoxelGrid& shape, const VoxelDesignOptions& options) {
  int64_t voxelCount = 0;
  VoxelGrid grid = normalizedShape(shape, options, &voxelCount);
  const VoxelDesignOptions effective = effectiveOptions(options, voxelCount);
  DesignContext context = makeContext(grid, effective, voxelCount);
  VoxelConstructionTree tree(std::move(grid), effective, context);
  return searchPuzzle(tree, effective);
}

struct VoxelDesignSession::State {
  VoxelDesignOptions options;
  DesignContext context;
  VoxelConstructionTree tree;
  State(VoxelGrid grid, VoxelDesignOptions effective, int64_t voxelCount)
      : options(std::move(effective)), context(makeContext(grid, options, voxelCount)), tree(std::move(grid), options, context) {}
};

VoxelDesignSession::VoxelDesignSession(const VoxelGrid& shape, const VoxelDesignOptions& options) {
  int64_t voxelCount = 0;
  VoxelGrid grid = normalizedShape(shape, options, &voxelCount);
  state_ = std::make_unique<State>(std::move(grid), effectiveOptions(options, voxelCount), voxelCount);
}

VoxelDesignSession::~VoxelDesignSession() = default;

const VoxelGrid& VoxelDesignSession::current() const { return state_->tree.grid(); }
int VoxelDesignSession::partsPlaced() const { return state_->tree.depth(); }
int VoxelDesignSession::targetParts() const { return state_->options.parts; }
bool VoxelDesignSession::complete() const { return state_->tree.depth() == state_->options.parts - 1; }
int VoxelDesignSession::childCount() { return static_cast<int>(state_->tree.children().size()); }

VoxelGrid VoxelDesignSession::childPreview(int n) {
  if (n < 0 || n >= childCount()) throwBadInput("", "child " + std::to_string(n) + " does not exist (the node has " + std::to_string(childCount()) + " children)");
  return state_->tree.preview(static_cast<size_t>(n));
}

void VoxelDesignSession::chooseChild(int n) {
  if (n < 0 || n >= childCount()) throwBadInput("", "child " + std::to_string(n) + " does not exist (the node has " + std::to_string(childCount()) + " children)");
  state_->tree.descend(static_cast<size_t>(n));
}

bool VoxelDesignSession::generateNextPart() {
  if (childCount() == 0) return false;
  state_->tree.descend(0);
  return true;
}

bool VoxelDesignSession::goBack() { return state_->tree.ascend(); }

VoxelDesignResult VoxelDesignSession::finish(const DesignLimits& limits) {
  VoxelDesignOptions options = state_->options;
  options.limits = limits;
  // A copy of the path: the session stays where it is, and its explored children stay explored.
  VoxelConstructionTree subtree = state_->tree;
  subtree.makeCurrentTheFloor();
  return searchPuzzle(subtree, options);
}

CheckReport VoxelDesignSession::check() const { return checkVoxelAssembly(state_->tree.grid()); }

}  // namespace desia
