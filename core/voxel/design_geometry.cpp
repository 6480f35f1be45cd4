// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry shared by the voxel designer's steps (paper Section 4.3, "geometry realization").
#include <algorithm>
#include <cmath>
#include <limits>

#include "voxel/design_internals.h"

namespace desia::design {

GridSteps::GridSteps(const VoxelGrid& grid) : inside_(static_cast<size_t>(grid.voxelCount()), 0) {
  const int64_t nx = grid.nx(), nxy = nx * grid.ny();
  offset_ = {1, -1, nx, -nx, nxy, -nxy};
  size_t i = 0;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x, ++i) {
        inside_[i] = static_cast<uint8_t>((x + 1 < grid.nx()) | (x > 0) << 1 | (y + 1 < grid.ny()) << 2 | (y > 0) << 3 |
                                          (z + 1 < grid.nz()) << 4 | (z > 0) << 5);
      }
    }
  }
}

std::vector<double> accessibility(const VoxelGrid& grid, int label) {
  const GridSteps steps(grid);
  // The set's voxels and, once, their in-set neighbours: the three passes then touch only the set
  // (this runs for every ranked candidate, on grids of tens of thousands of voxels).
  std::vector<int64_t> voxels;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == label) voxels.push_back(i);
  }
  std::vector<std::array<int64_t, 6>> neighbours(voxels.size());
  std::vector<uint8_t> neighbourCount(voxels.size(), 0);
  for (size_t k = 0; k < voxels.size(); ++k) {
    for (int step = 0; step < 6; ++step) {
      const int64_t j = steps.neighbour(voxels[k], step);
      if (j >= 0 && grid.labelAt(j) == label) neighbours[k][neighbourCount[k]++] = j;
    }
  }
  const int64_t n = grid.voxelCount();
  std::vector<double> current(static_cast<size_t>(n), 0.0), next(static_cast<size_t>(n), 0.0);
  for (size_t k = 0; k < voxels.size(); ++k) current[voxels[k]] = neighbourCount[k];
  double weight = 1.0;
  for (int pass = 1; pass <= 3; ++pass) {
    weight *= 0.1;  // beta^pass with beta = 0.1
    for (size_t k = 0; k < voxels.size(); ++k) {
      double sum = 0;
      for (uint8_t m = 0; m < neighbourCount[k]; ++m) sum += current[neighbours[k][m]];
      next[voxels[k]] = current[voxels[k]] + weight * sum;
    }
    std::swap(current, next);
  }
  return current;
}

bool isFaceConnected(const VoxelGrid& grid, int label) {
  const GridSteps steps(grid);
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
    for (int step = 0; step < 6; ++step) {
      const int64_t j = steps.neighbour(i, step);
      if (j < 0 || seen[j] || grid.labelAt(j) != label) continue;
      seen[j] = true;
      stack.push_back(j);
    }
  }
  return reached == total;
}

int shapeSurfaceVoxelCount(const VoxelGrid& grid, const GridSteps& steps, const std::vector<int64_t>& voxels) {
  int count = 0;
  for (int64_t v : voxels) {
    bool onSurface = false;
    for (int step = 0; step < 6 && !onSurface; ++step) {
      const int64_t w = steps.neighbour(v, step);
      onSurface = w < 0 || grid.labelAt(w) == 0;
    }
    count += onSurface ? 1 : 0;
  }
  return count;
}

double rankingKey(const VoxelGrid& grid, int partLabel, int remainderLabel, CandidateRanking ranking) {
  if (ranking == CandidateRanking::Compactness) {
    // Most compact remainder first: the largest accessibility sum ranks first (Section 4.1, after
    // Song et al. 2012). Parts that take the shape's surface rank higher: a part on the surface
    // is blocked along its outward side only by neighbours that wrap around it, which a large
    // remainder offers and a late one does not. Ranked by compactness alone, a large shape keeps a
    // one-voxel skin of its surface for last, which no split can divide into interlocking parts.
    // The surface weight (3) is the one that designed the most shapes of the weights tried.
    double sum = 0;
    for (double a : accessibility(grid, remainderLabel)) sum += a;
    std::vector<int64_t> part;
    for (int64_t i = 0; i < grid.voxelCount(); ++i) {
      if (grid.labelAt(i) == partLabel) part.push_back(i);
    }
    return -sum - kShapeSurfaceWeight * shapeSurfaceVoxelCount(grid, GridSteps(grid), part);
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

PartSizeBounds partSizeBounds(const VoxelDesignOptions& options) {
  PartSizeBounds bounds;
  bounds.min = std::max(1, options.minPartSize);
  bounds.max = options.maxPartSize > 0 ? options.maxPartSize : std::numeric_limits<int>::max();
  return bounds;
}

SizeWindow partSizeWindow(int64_t remainderVoxels, int partsLeftIncludingRemainder, const PartSizeBounds& bounds) {
  const int64_t later = std::max(0, partsLeftIncludingRemainder - 1);  // parts after this one
  const int64_t low = std::max<int64_t>(bounds.min, remainderVoxels - later * bounds.max);
  const int64_t high = std::min<int64_t>(bounds.max, remainderVoxels - later * bounds.min);
  return {static_cast<int>(std::clamp<int64_t>(low, 0, std::numeric_limits<int>::max())),
          static_cast<int>(std::clamp<int64_t>(high, -1, std::numeric_limits<int>::max()))};
}

SizeWindow clampInto(const SizeWindow& heuristic, const SizeWindow& allowed) {
  if (allowed.empty()) return allowed;
  return {std::clamp(heuristic.min, allowed.min, allowed.max), std::clamp(heuristic.max, allowed.min, allowed.max)};
}

PartBuilder::PartBuilder(const VoxelGrid& grid, int remainderLabel, const DesignContext& context,
                         const std::vector<double>& access)
    : grid_(grid),
      context_(context),
      access_(access),
      steps_(grid),
      state_(static_cast<size_t>(grid.voxelCount()), kOther),
      cameFrom_(static_cast<size_t>(grid.voxelCount()), -2),
      connected_(static_cast<size_t>(grid.voxelCount()), false),
      bestG_(static_cast<size_t>(grid.voxelCount()), -1) {
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == remainderLabel) state_[i] = kFree;
  }
}

void PartBuilder::restore(const Snapshot& snapshot) {
  while (journal_.size() > snapshot.journal) {
    state_[journal_.back().first] = journal_.back().second;
    journal_.pop_back();
  }
  part_.resize(snapshot.part);
  forcedPart_.resize(snapshot.forcedPart);
}

bool PartBuilder::addToPart(int64_t voxel) {
  auto addOne = [&](int64_t v) {
    if (state_[v] == kPart) return true;
    if (state_[v] != kFree) return false;
    setState(v, kPart);
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
  const size_t first = part_.size();
  if (!addToPart(voxel)) return false;
  forcedPart_.push_back(voxel);
  // Propagation (see the header): the runs in front of the new part voxels join the part now.
  return !propagate_ || clearPathFrom(first, removal_);
}

bool PartBuilder::forceRemainder(int64_t voxel) {
  const Int3 back{-removal_.x, -removal_.y, -removal_.z};
  auto forceOne = [&](int64_t v) {
    if (state_[v] == kForcedRemainder) return true;
    if (state_[v] != kFree) return false;
    setState(v, kForcedRemainder);
    if (!propagate_) return true;
    // Propagation (see the header): a part voxel behind v in its remainder run would have v in
    // its way out, so the run behind v stays in the remainder. A forced voxel already had its
    // own run settled, so the walk stops there.
    for (int64_t w = neighbourIndex(grid_, v, back); w >= 0 && state_[w] != kOther; w = neighbourIndex(grid_, w, back)) {
      if (state_[w] == kPart) return false;
      if (state_[w] == kForcedRemainder) break;
      setState(w, kForcedRemainder);
    }
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
  std::vector<int64_t> component;  // also the list of connected_ entries to clear at the end
  // Adds `from` and every part voxel face-connected to it to the connected component.
  auto flood = [&](int64_t from) {
    if (connected_[from]) return;
    std::vector<int64_t> stack{from};
    connected_[from] = true;
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      component.push_back(v);
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(v, step);
        if (w < 0 || connected_[w] || state_[w] != kPart) continue;
        connected_[w] = true;
        stack.push_back(w);
      }
    }
  };
  // Breadth-first from the whole component: the first time the target is reached, the path back
  // is a shortest connection through voxels the part may take. The search is pruned to voxels
  // that can lie on a shortest path (distance + Manhattan distance to the target <= the target's
  // distance, found first by A*), which finds the same path as the whole breadth-first search:
  // a voxel w on a shortest path takes its predecessor from its neighbours one step closer to the
  // component, which are all on shortest paths too, so by induction over the distance the pruned
  // queue holds those voxels in the same relative order and each w the same predecessor. The
  // cost follows the region between the component and the target, not a ball around it.
  auto reach = [&](int64_t target) {
    const Int3 goal = grid_.coordinates(target);
    std::vector<int64_t> visited;
    const int32_t distance = bestFirst(component, goal, [&](int64_t v) { return v == target; }, &visited);
    clearBestG(visited);
    if (distance < 0) return false;
    // The queue is a vector read from `head` on; it also lists every voxel whose cameFrom_ entry
    // was set, for the clean-up. `at` and `layer` hold each entry's coordinates and distance.
    std::vector<int64_t> queue(component.begin(), component.end());
    std::vector<Int3> at;
    for (int64_t v : component) at.push_back(grid_.coordinates(v));
    std::vector<int32_t> layer(component.size(), 0);
    size_t head = 0;
    for (int64_t v : component) cameFrom_[v] = -1;
    bool reached = false;
    while (head < queue.size() && !reached) {
      const int64_t v = queue[head];
      const Int3 c = at[head];
      const int32_t next = layer[head] + 1;
      ++head;
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(v, step);
        if (w < 0 || cameFrom_[w] != -2 || (state_[w] != kFree && state_[w] != kPart)) continue;
        const Int3 cw = plus(c, kAxisSteps[step]);
        if (next + manhattan(cw, goal) > distance) continue;  // on no shortest path
        cameFrom_[w] = v;
        queue.push_back(w);
        at.push_back(cw);
        layer.push_back(next);
        if (w == target) {
          reached = true;
          break;
        }
      }
    }
    bool added = reached;
    for (int64_t v = target; reached && cameFrom_[v] >= 0; v = cameFrom_[v]) added = added && addToPart(v);
    for (int64_t v : queue) cameFrom_[v] = -2;
    return added;
  };
  bool ok = true;
  flood(forcedPart_[0]);
  for (size_t k = 1; k < forcedPart_.size() && ok; ++k) {
    const int64_t target = forcedPart_[k];
    if (connected_[target]) continue;
    ok = reach(target);
    if (ok) flood(target);
  }
  // Group members added along the way must be attached too.
  for (int64_t v : part_) ok = ok && connected_[v];
  for (int64_t v : component) connected_[v] = false;
  return ok;
}

template <typename IsGoal>
int32_t PartBuilder::bestFirst(const std::vector<int64_t>& sources, const Int3& toward, IsGoal isGoal,
                               std::vector<int64_t>* visited) {
  struct Entry {
    int64_t voxel;
    Int3 at;
    int32_t distance;
  };
  std::vector<std::vector<Entry>> buckets;  // by distance + Manhattan distance to `toward`
  auto push = [&](int64_t v, const Int3& at, int32_t distance) {
    if (bestG_[v] >= 0 && bestG_[v] <= distance) return;
    if (bestG_[v] < 0) visited->push_back(v);
    bestG_[v] = distance;
    const size_t f = static_cast<size_t>(distance + manhattan(at, toward));
    if (f >= buckets.size()) buckets.resize(f + 1);
    buckets[f].push_back({v, at, distance});
  };
  for (int64_t v : sources) push(v, grid_.coordinates(v), 0);
  for (size_t f = 0; f < buckets.size(); ++f) {
    while (!buckets[f].empty()) {  // last in, first out: the deepest entry of the bucket first
      const Entry entry = buckets[f].back();
      buckets[f].pop_back();
      if (entry.distance != bestG_[entry.voxel]) continue;  // a shorter way was found meanwhile
      if (isGoal(entry.voxel)) return entry.distance;
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(entry.voxel, step);
        if (w >= 0 && canBePart(w)) push(w, plus(entry.at, kAxisSteps[step]), entry.distance + 1);
      }
    }
  }
  return -1;
}

bool PartBuilder::forcedPartConnectable() {
  if (forcedPart_.empty()) return false;
  // Each forced voxel searches its way towards the first (best-first, aimed at it) until it meets
  // a voxel already known to be connected to it: the voxels a search reached are connected too.
  // Same answer as a breadth-first search from the first forced voxel, at the cost of paths
  // rather than of balls around the first voxel (forced voxels lie far apart early in a large
  // shape). connected_ marks the known voxels, `joined` lists them for the clean-up.
  const int64_t first = forcedPart_[0];
  const Int3 firstAt = grid_.coordinates(first);
  std::vector<int64_t> joined{first}, visited;
  connected_[first] = true;
  bool ok = true;
  for (size_t k = 1; k < forcedPart_.size() && ok; ++k) {
    const int64_t target = forcedPart_[k];
    if (connected_[target]) continue;
    visited.clear();
    ok = bestFirst({target}, firstAt, [&](int64_t v) { return static_cast<bool>(connected_[v]); }, &visited) >= 0;
    clearBestG(visited);
    for (int64_t v : visited) {
      if (ok && !connected_[v]) {
        connected_[v] = true;
        joined.push_back(v);
      }
    }
  }
  for (int64_t v : joined) connected_[v] = false;
  return ok;
}

std::vector<int64_t> PartBuilder::columnFrom(int64_t voxel, const Int3& direction) const {
  std::vector<int64_t> column;
  for (int64_t v = neighbourIndex(grid_, voxel, direction); v >= 0 && (state_[v] == kFree || state_[v] == kForcedRemainder);
       v = neighbourIndex(grid_, v, direction)) {
    column.push_back(v);
  }
  return column;
}

bool PartBuilder::clearPathAlong(const Int3& direction) { return clearPathFrom(0, direction); }

bool PartBuilder::clearPathFrom(size_t first, const Int3& direction) {
  // Groups can add voxels whose own columns need clearing: repeat until nothing changes.
  for (size_t done = first; done < part_.size();) {
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
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(v, step);
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
      const Snapshot before = snapshot();
      bool ok = addToPart(candidate);
      for (int64_t v : column) ok = ok && addToPart(v);
      ok = ok && clearPathAlong(direction);
      if (!ok || size() > maxSize) {
        restore(before);
        continue;
      }
      grown = true;
      break;
    }
    if (!grown) return false;
  }
  return size() <= maxSize;
}

bool PartBuilder::absorb(const std::vector<int64_t>& voxels, const Int3& direction) {
  const size_t first = part_.size();
  for (int64_t v : voxels) {
    if (!addToPart(v)) return false;
  }
  return clearPathFrom(first, direction);
}

std::vector<int64_t> PartBuilder::sortedPartVoxels() const {
  std::vector<int64_t> sorted = part_;
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

}  // namespace desia::design
