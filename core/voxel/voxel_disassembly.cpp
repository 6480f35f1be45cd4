// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning for voxel assemblies (paper Section 3.3): each removal is a translation to
// infinity, checked voxel by voxel along the way; when no straight path exists, a breadth-first
// search over unit axis steps looks for a bent one (voxels outside the grid are free).
#include <algorithm>
#include <array>
#include <deque>
#include <limits>

#include "desia/disassembly.h"
#include "desia/error.h"

namespace desia {
namespace {

// Axis directions in the order they are tried: up (+y, the .puz convention) first.
constexpr std::array<std::array<int, 3>, 6> kSteps{{{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}}};

struct Box {
  Int3 min{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  Int3 max{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  void add(const Int3& c) {
    min = {std::min(min.x, c.x), std::min(min.y, c.y), std::min(min.z, c.z)};
    max = {std::max(max.x, c.x), std::max(max.y, c.y), std::max(max.z, c.z)};
  }
  bool empty() const { return min.x > max.x; }
};

Int3 plus(const Int3& a, const Int3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Int3 stepOf(int s) { return {kSteps[s][0], kSteps[s][1], kSteps[s][2]}; }

// The voxels still in place, and the search for one part's way out of them.
class RemovalSearch {
 public:
  RemovalSearch(const VoxelGrid& occupancy, int label, const std::vector<Int3>& voxels, const Box& own,
                const VoxelDisassemblyOptions& limits)
      : occupancy_(occupancy), label_(label), voxels_(voxels), limits_(limits), own_(own) {}

  // True when the last findPath stopped at a work limit rather than exhausting the search.
  bool limitReached() const { return limitReached_; }

  // Bounding box of the other parts still in place (computed only for parts that can move).
  void setObstacles(const Box& obstacles) { obstacles_ = obstacles; }

  // A part that cannot take a single unit step in any direction is stuck; most parts of an
  // interlocking assembly are, so this cheap test comes before the search.
  bool canTakeAnyStep() const {
    for (int s = 0; s < 6; ++s) {
      if (!collides(stepOf(s))) return true;
    }
    return false;
  }

  // Finds a path out, or returns false. Breadth-first, so the first path found has the fewest
  // unit steps before the final straight move.
  bool findPath(std::vector<Move>* path) {
    if (obstacles_.empty()) return true;
    // Offsets at which the part's box still overlaps the obstacles' box; outside it, a straight
    // move is always free, so the search never needs to go there.
    // The range always contains the start (a part whose box is already apart from the others').
    const Int3 lo{std::min(0, obstacles_.min.x - own_.max.x), std::min(0, obstacles_.min.y - own_.max.y),
                  std::min(0, obstacles_.min.z - own_.max.z)};
    const Int3 hi{std::max(0, obstacles_.max.x - own_.min.x), std::max(0, obstacles_.max.y - own_.min.y),
                  std::max(0, obstacles_.max.z - own_.min.z)};
    const Int3 size{hi.x - lo.x + 1, hi.y - lo.y + 1, hi.z - lo.z + 1};
    auto slot = [&](const Int3& o) {
      return (o.x - lo.x) + static_cast<int64_t>(size.x) * ((o.y - lo.y) + static_cast<int64_t>(size.y) * (o.z - lo.z));
    };
    const int64_t slots = static_cast<int64_t>(size.x) * size.y * size.z;
    std::vector<int8_t> cameBy(static_cast<size_t>(slots), -1);  // step that reached the slot; 6 = start
    std::deque<Int3> queue{Int3{0, 0, 0}};
    cameBy[slot({0, 0, 0})] = 6;
    int visited = 0;
    while (!queue.empty()) {
      if (++visited > limits_.maxSearchStates || voxelTests_ > limits_.maxVoxelTests) {
        limitReached_ = true;
        return false;
      }
      const Int3 offset = queue.front();
      queue.pop_front();
      int escapeStep = -1, escapeDistance = 0;
      for (int s = 0; s < 6; ++s) {
        int distance = straightEscapeDistance(offset, s);
        if (distance > 0 && (escapeStep < 0 || distance < escapeDistance)) {
          escapeStep = s;
          escapeDistance = distance;
        }
      }
      if (escapeStep >= 0) {
        *path = tracePath(offset, cameBy, slot);
        appendMove(path, escapeStep, escapeDistance);
        return true;
      }
      for (int s = 0; s < 6; ++s) {
        const Int3 next = plus(offset, stepOf(s));
        if (next.x < lo.x || next.y < lo.y || next.z < lo.z || next.x > hi.x || next.y > hi.y || next.z > hi.z) continue;
        if (cameBy[slot(next)] >= 0 || collides(next)) continue;
        cameBy[slot(next)] = static_cast<int8_t>(s);
        queue.push_back(next);
      }
    }
    return false;
  }

 private:
  bool collides(const Int3& offset) const {
    voxelTests_ += static_cast<int64_t>(voxels_.size());
    for (const Int3& v : voxels_) {
      const Int3 p = plus(v, offset);
      if (!occupancy_.inside(p.x, p.y, p.z)) continue;
      const int l = occupancy_.label(p.x, p.y, p.z);
      if (l != 0 && l != label_) return true;
    }
    return false;
  }

  // Number of unit steps along step s after which the part's box is clear of the obstacles'
  // box, or 0 if it collides on the way.
  int straightEscapeDistance(const Int3& offset, int s) const {
    const Int3 d = stepOf(s);
    Int3 current = offset;
    for (int k = 1;; ++k) {
      current = plus(current, d);
      if (clearOfObstacles(current)) return k;
      if (collides(current)) return 0;
    }
  }

  bool clearOfObstacles(const Int3& offset) const {
    return own_.max.x + offset.x < obstacles_.min.x || own_.min.x + offset.x > obstacles_.max.x ||
           own_.max.y + offset.y < obstacles_.min.y || own_.min.y + offset.y > obstacles_.max.y ||
           own_.max.z + offset.z < obstacles_.min.z || own_.min.z + offset.z > obstacles_.max.z;
  }

  template <typename SlotFn>
  static std::vector<Move> tracePath(Int3 offset, const std::vector<int8_t>& cameBy, SlotFn slot) {
    std::vector<int> steps;
    while (cameBy[slot(offset)] != 6) {
      const int s = cameBy[slot(offset)];
      steps.push_back(s);
      const Int3 d = stepOf(s);
      offset = {offset.x - d.x, offset.y - d.y, offset.z - d.z};
    }
    std::reverse(steps.begin(), steps.end());
    std::vector<Move> path;
    for (int s : steps) appendMove(&path, s, 1);
    return path;
  }

  static void appendMove(std::vector<Move>* path, int s, int distance) {
    const Vec3 direction{double(kSteps[s][0]), double(kSteps[s][1]), double(kSteps[s][2])};
    if (!path->empty() && path->back().direction == direction) {
      path->back().steps += distance;
    } else {
      path->push_back({direction, distance});
    }
  }

  const VoxelGrid& occupancy_;
  int label_;
  const std::vector<Int3>& voxels_;
  const VoxelDisassemblyOptions& limits_;
  Box own_, obstacles_;
  mutable int64_t voxelTests_ = 0;
  bool limitReached_ = false;
};

}  // namespace

bool findVoxelRemovalPath(const VoxelGrid& occupancy, int label, std::vector<Move>* path,
                          const VoxelDisassemblyOptions& options, bool* limitReached) {
  std::vector<Int3> voxels;
  Box own, obstacles;
  for (int64_t i = 0; i < occupancy.voxelCount(); ++i) {
    const int l = occupancy.labelAt(i);
    if (l == 0) continue;
    const Int3 c = occupancy.coordinates(i);
    if (l == label) {
      voxels.push_back(c);
      own.add(c);
    } else {
      obstacles.add(c);
    }
  }
  if (limitReached) *limitReached = false;
  if (voxels.empty()) return false;
  RemovalSearch search(occupancy, label, voxels, own, options);
  if (!obstacles.empty() && !search.canTakeAnyStep()) return false;
  search.setObstacles(obstacles);
  const bool found = search.findPath(path);
  if (limitReached) *limitReached = search.limitReached();
  return found;
}

DisassemblyPlan planVoxelDisassembly(const VoxelGrid& grid, const Assembly& assembly,
                                     const VoxelDisassemblyOptions& options) {
  const int partCount = assembly.partCount();
  std::vector<std::vector<Int3>> voxels(partCount);
  std::vector<Box> boxes(partCount);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    const int label = grid.labelAt(i);
    if (label == 0) continue;
    voxels[label - 1].push_back(grid.coordinates(i));
    boxes[label - 1].add(voxels[label - 1].back());
  }
  auto obstaclesBox = [&](int part, const std::vector<bool>& removed) {
    Box box;
    for (int other = 0; other < partCount; ++other) {
      if (other == part || removed[other]) continue;
      box.add(boxes[other].min);
      box.add(boxes[other].max);
    }
    return box;
  };
  VoxelGrid occupancy = grid;
  std::vector<bool> removed(partCount, false);
  DisassemblyPlan plan;
  for (int remaining = partCount; remaining > 1; --remaining) {
    bool progressed = false;
    for (int part = 0; part < partCount && !progressed; ++part) {
      if (removed[part]) continue;
      std::vector<Move> path;
      RemovalSearch search(occupancy, part + 1, voxels[part], boxes[part], options);
      if (!search.canTakeAnyStep()) continue;
      search.setObstacles(obstaclesBox(part, removed));
      if (!search.findPath(&path)) {
        plan.searchLimitReached = plan.searchLimitReached || search.limitReached();
        continue;
      }
      plan.removals.push_back({part, path});
      removed[part] = true;
      for (const Int3& v : voxels[part]) occupancy.setLabel(v.x, v.y, v.z, 0);
      progressed = true;
    }
    if (!progressed) {
      for (int part = 0; part < partCount; ++part) {
        if (!removed[part]) plan.stuck.push_back(part);
      }
      return plan;
    }
  }
  for (int part = 0; part < partCount; ++part) {
    if (!removed[part]) plan.removals.push_back({part, {}});
  }
  plan.complete = true;
  return plan;
}

}  // namespace desia
