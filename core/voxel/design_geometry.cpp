// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry shared by the voxel designer's steps (paper Section 4.3, "geometry realization").
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "voxel/design_internals.h"

namespace desia::design {

std::vector<double> accessibility(const VoxelGrid& grid, int label) {
  const int64_t n = grid.voxelCount();
  std::vector<double> current(static_cast<size_t>(n), 0.0), next(static_cast<size_t>(n), 0.0);
  for (int64_t i = 0; i < n; ++i) {
    if (grid.labelAt(i) != label) continue;
    int count = 0;
    for (const Int3& step : kAxisSteps) {
      const int64_t j = neighbourIndex(grid, i, step);
      count += (j >= 0 && grid.labelAt(j) == label) ? 1 : 0;
    }
    current[i] = count;
  }
  double weight = 1.0;
  for (int pass = 1; pass <= 3; ++pass) {
    weight *= 0.1;  // beta^pass with beta = 0.1
    for (int64_t i = 0; i < n; ++i) {
      if (grid.labelAt(i) != label) continue;
      double sum = 0;
      for (const Int3& step : kAxisSteps) {
        const int64_t j = neighbourIndex(grid, i, step);
        if (j >= 0 && grid.labelAt(j) == label) sum += current[j];
      }
      next[i] = current[i] + weight * sum;
    }
    std::swap(current, next);
  }
  return current;
}

bool isFaceConnected(const VoxelGrid& grid, int label) {
  int64_t total = 0, start = -1;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != label) continue;
    ++total;
    if (start < 0) start = i;
  }
  if (start < 0) return false;
  std::vector<bool> seen(static_cast<size_t>(grid.voxelCount()), false);
  std::vector<int64_t> stack{start};
  seen[start] = true;
  int64_t reached = 0;
  while (!stack.empty()) {
    const int64_t i = stack.back();
    stack.pop_back();
    ++reached;
    for (const Int3& step : kAxisSteps) {
      const int64_t j = neighbourIndex(grid, i, step);
      if (j < 0 || seen[j] || grid.labelAt(j) != label) continue;
      seen[j] = true;
      stack.push_back(j);
    }
  }
  return reached == total;
}

double rankingKey(const VoxelGrid& grid, int partLabel, int remainderLabel, CandidateRanking ranking) {
  if (ranking == CandidateRanking::Compactness) {
    // Most compact remainder first: the largest accessibility sum ranks first.
    double sum = 0;
    for (double a : accessibility(grid, remainderLabel)) sum += a;
    return -sum;
  }
  double sum = 0;
  int64_t count = 0;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != partLabel) continue;
    const Int3 c = grid.coordinates(i);
    switch (ranking) {
      case CandidateRanking::LowestX: case CandidateRanking::HighestX: sum += c.x; break;
      case CandidateRanking::LowestY: case CandidateRanking::HighestY: sum += c.y; break;
      default: sum += c.z; break;
    }
    ++count;
  }
  const double mean = count ? sum / static_cast<double>(count) : 0;
  const bool highestFirst = ranking == CandidateRanking::HighestX || ranking == CandidateRanking::HighestY ||
                            ranking == CandidateRanking::HighestZ;
  return highestFirst ? -mean : mean;
}

void applyCandidate(VoxelGrid& grid, int remainderLabel, const Candidate& candidate) {
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == remainderLabel) grid.setLabelAt(i, remainderLabel + 1);
  }
  for (int64_t v : candidate.partVoxels) grid.setLabelAt(v, remainderLabel);
}

void undoCandidate(VoxelGrid& grid, int remainderLabel) {
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == remainderLabel + 1) grid.setLabelAt(i, remainderLabel);
  }
}

int targetPartSize(int64_t remainderVoxels, int partsLeftIncludingRemainder) {
  return static_cast<int>(remainderVoxels / std::max(1, partsLeftIncludingRemainder));
}

PartBuilder::PartBuilder(const VoxelGrid& grid, int remainderLabel, const DesignContext& context,
                         const std::vector<double>& access)
    : grid_(grid), context_(context), access_(access), state_(static_cast<size_t>(grid.voxelCount()), kOther) {
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == remainderLabel) state_[i] = kFree;
  }
}

bool PartBuilder::addToPart(int64_t voxel) {
  auto addOne = [&](int64_t v) {
    if (state_[v] == kPart) return true;
    if (state_[v] != kFree) return false;
    state_[v] = kPart;
    part_.push_back(v);
    return true;
  };
  const int group = context_.groupOf.empty() ? -1 : context_.groupOf[voxel];
  if (group < 0) return addOne(voxel);
  for (int64_t v : context_.groups[group]) {
    if (!addOne(v)) return false;
  }
  return true;
}

bool PartBuilder::forcePart(int64_t voxel) {
  if (!addToPart(voxel)) return false;
  forcedPart_.push_back(voxel);
  return true;
}

bool PartBuilder::forceRemainder(int64_t voxel) {
  auto forceOne = [&](int64_t v) {
    if (state_[v] == kForcedRemainder) return true;
    if (state_[v] != kFree) return false;
    state_[v] = kForcedRemainder;
    return true;
  };
  const int group = context_.groupOf.empty() ? -1 : context_.groupOf[voxel];
  if (group < 0) return forceOne(voxel);
  for (int64_t v : context_.groups[group]) {
    if (!forceOne(v)) return false;
  }
  return true;
}

bool PartBuilder::connect() {
  if (forcedPart_.empty()) return false;
  std::vector<bool> connected(state_.size(), false);
  std::vector<int64_t> component;
  // Adds `from` and every part voxel face-connected to it to the connected component.
  auto flood = [&](int64_t from) {
    if (connected[from]) return;
    std::vector<int64_t> stack{from};
    connected[from] = true;
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      component.push_back(v);
      for (const Int3& step : kAxisSteps) {
        const int64_t w = neighbourIndex(grid_, v, step);
        if (w < 0 || connected[w] || state_[w] != kPart) continue;
        connected[w] = true;
        stack.push_back(w);
      }
    }
  };
  flood(forcedPart_[0]);
  for (size_t k = 1; k < forcedPart_.size(); ++k) {
    const int64_t target = forcedPart_[k];
    if (connected[target]) continue;
    // Breadth-first from the whole component: the first time the target is reached, the path
    // back is a shortest connection through voxels the part may take.
    std::vector<int64_t> cameFrom(state_.size(), -2);
    std::deque<int64_t> queue(component.begin(), component.end());
    for (int64_t v : component) cameFrom[v] = -1;
    bool reached = false;
    while (!queue.empty() && !reached) {
      const int64_t v = queue.front();
      queue.pop_front();
      for (const Int3& step : kAxisSteps) {
        const int64_t w = neighbourIndex(grid_, v, step);
        if (w < 0 || cameFrom[w] != -2 || (state_[w] != kFree && state_[w] != kPart)) continue;
        cameFrom[w] = v;
        if (w == target) {
          reached = true;
          break;
        }
        queue.push_back(w);
      }
    }
    if (!reached) return false;
    for (int64_t v = target; cameFrom[v] >= 0; v = cameFrom[v]) {
      if (!addToPart(v)) return false;
    }
    flood(target);
  }
  // Group members added along the way must be attached too.
  for (int64_t v : part_) {
    if (!connected[v]) return false;
  }
  return true;
}

std::vector<int64_t> PartBuilder::columnFrom(int64_t voxel, const Int3& direction) const {
  std::vector<int64_t> column;
  for (int64_t v = neighbourIndex(grid_, voxel, direction); v >= 0 && (state_[v] == kFree || state_[v] == kForcedRemainder);
       v = neighbourIndex(grid_, v, direction)) {
    column.push_back(v);
  }
  return column;
}

bool PartBuilder::clearPathAlong(const Int3& direction) {
  // Groups can add voxels whose own columns need clearing: repeat until nothing changes.
  for (size_t done = 0; done < part_.size();) {
    const size_t end = part_.size();
    for (size_t k = done; k < end; ++k) {
      for (int64_t v : columnFrom(part_[k], direction)) {
        if (state_[v] == kForcedRemainder || !addToPart(v)) return false;
      }
    }
    done = end;
  }
  return true;
}

bool PartBuilder::growTo(int minSize, int maxSize, const Int3& direction, std::mt19937_64& random) {
  while (size() < minSize) {
    // Frontier: free voxels next to the part, least accessible first (exposed voxels make parts
    // that leave the remainder compact), ties broken by index for determinism.
    std::vector<int64_t> frontier;
    for (int64_t v : part_) {
      for (const Int3& step : kAxisSteps) {
        const int64_t w = neighbourIndex(grid_, v, step);
        if (w >= 0 && state_[w] == kFree) frontier.push_back(w);
      }
    }
    std::sort(frontier.begin(), frontier.end());
    frontier.erase(std::unique(frontier.begin(), frontier.end()), frontier.end());
    std::stable_sort(frontier.begin(), frontier.end(), [&](int64_t a, int64_t b) { return access_[a] < access_[b]; });
    bool grown = false;
    for (int64_t candidate : frontier) {
      // Skip a choice now and then (as the original's 0.9 choice rate) so seeds give variety.
      if (random() % 10 == 0) continue;
      std::vector<int64_t> column = columnFrom(candidate, direction);
      bool blocked = false;
      for (int64_t v : column) blocked = blocked || state_[v] == kForcedRemainder;
      if (blocked) continue;
      const std::vector<uint8_t> before = state_;
      const size_t sizeBefore = part_.size();
      bool ok = addToPart(candidate);
      for (int64_t v : column) ok = ok && addToPart(v);
      ok = ok && clearPathAlong(direction);
      if (!ok || size() > maxSize) {
        state_ = before;
        part_.resize(sizeBefore);
        continue;
      }
      grown = true;
      break;
    }
    if (!grown) return false;
  }
  return size() <= maxSize;
}

std::vector<int64_t> PartBuilder::sortedPartVoxels() const {
  std::vector<int64_t> sorted = part_;
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

}  // namespace desia::design
