// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning for voxel assemblies (paper Section 3.3): each removal is a translation to
// infinity, checked voxel by voxel along the way; when no straight path exists, a breadth-first
// search over unit axis steps looks for a bent one (voxels outside the grid are free).
#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <set>
#include <utility>

#include "desia/error.h"
#include "desia/voxel.h"
#include "voxel/group_disassembly.h"
#include "voxel/voxel_removal.h"

namespace desia {
namespace {

// Axis directions in the order they are tried: up (+y, the .puz convention) first.
constexpr std::array<std::array<int, 3>, 6> kSteps{
    {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}}};

struct Box {
  Int3 min{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  Int3 max{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  void add(const Int3& c) {
    min = {std::min(min.x, c.x), std::min(min.y, c.y), std::min(min.z, c.z)};
    max = {std::max(max.x, c.x), std::max(max.y, c.y), std::max(max.z, c.z)};
  }
  bool empty() const { return min.x > max.x; }
  bool operator==(const Box& other) const { return min == other.min && max == other.max; }
};

Int3 plus(const Int3& a, const Int3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Int3 stepOf(int s) { return {kSteps[s][0], kSteps[s][1], kSteps[s][2]}; }

// The labels of the parts a search collided with, one witness per collision found, each label
// logged once. A failed search read the occupancy only to find those collisions (every other
// placement it tested was free, and removals only free more space), so it would fail again in
// exactly the same way until one of these parts leaves.
class BlockerLog {
 public:
  explicit BlockerLog(int labelCount)
      : lastSearch_(static_cast<size_t>(labelCount) + 1, -1), settled_(static_cast<size_t>(labelCount) + 1, false) {}
  void begin(int64_t search) {
    search_ = search;
    labels_.clear();
  }
  void add(int label) {
    if (lastSearch_[label] == search_) return;
    lastSearch_[label] = search_;
    labels_.push_back(label);
  }
  const std::vector<int>& labels() const { return labels_; }

  // Parts whose own last search failed: they leave only after something near them changes, so
  // they make the most lasting witnesses.
  void setSettled(int label, bool settled) { settled_[label] = settled; }
  bool settled(int label) const { return settled_[label]; }

 private:
  std::vector<int64_t> lastSearch_;  // per label: the search that last logged it
  std::vector<bool> settled_;
  std::vector<int> labels_;
  int64_t search_ = 0;
};

// The voxels still in place, and the search for one part's way out of them.
class RemovalSearch {
 public:
  // `maxVoxelTests`: this search's share of the work budget; `blockers` (optional) logs whom the
  // search collided with.
  RemovalSearch(const VoxelGrid& occupancy, int label, const std::vector<Int3>& voxels, const Box& own,
                const VoxelDisassemblyOptions& limits, int64_t maxVoxelTests, BlockerLog* blockers = nullptr)
      : occupancy_(occupancy),
        label_(label),
        voxels_(voxels),
        limits_(limits),
        maxVoxelTests_(maxVoxelTests),
        blockers_(blockers),
        own_(own) {}

  // True when the last findPath stopped at a work limit rather than exhausting the search.
  bool limitReached() const { return limitReached_; }
  int64_t voxelTests() const { return voxelTests_; }

  // Bounding box of the other parts still in place (computed only for parts that can move).
  void setObstacles(const Box& obstacles) { obstacles_ = obstacles; }

  // A part that cannot take a single unit step in any direction is stuck; most parts of an
  // interlocking assembly are, so this cheap test comes before the search.
  bool canTakeAnyStep() const {
    for (int s = 0; s < 6; ++s) {
      if (!collides(stepOf(s), s)) return true;
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
      if (++visited > limits_.maxSearchStates || voxelTests_ > maxVoxelTests_) {
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
        if (next.x < lo.x || next.y < lo.y || next.z < lo.z || next.x > hi.x || next.y > hi.y || next.z > hi.z)
          continue;
        if (cameBy[slot(next)] >= 0 || collides(next, s)) continue;
        cameBy[slot(next)] = static_cast<int8_t>(s);
        queue.push_back(next);
      }
    }
    return false;
  }

 private:
  // Does the part collide at `offset`, reached by one step s from a placement known to be free?
  // Every caller moves that way (from the assembled placement, a visited offset, or the previous
  // step of a sweep), so only the part's front face along s can newly collide: the other voxels
  // move onto cells the part itself has just left. Counts the voxels tested (the work).
  // With a blocker log, the witness of a collision is a settled part if one collides (the scan
  // stops there), else the colliding part with the highest id: parts leave in id order, so that
  // one tends to stay longest and the logged failure stays valid longest. The answer itself does
  // not depend on the choice.
  bool collides(const Int3& offset, int s) const {
    int witness = 0;
    for (int index : frontFace(s)) {
      ++voxelTests_;
      const Int3 p = plus(voxels_[index], offset);
      if (!occupancy_.inside(p.x, p.y, p.z)) continue;
      const int l = occupancy_.label(p.x, p.y, p.z);
      if (l == 0 || l == label_) continue;
      if (!blockers_) return true;
      if (blockers_->settled(l)) {
        witness = l;
        break;
      }
      witness = std::max(witness, l);
    }
    if (witness == 0) return false;
    blockers_->add(witness);
    return true;
  }

  // Indices of the voxels whose neighbour along step s is not part of this part, built on first
  // use (and counted as work: one voxel test per voxel of the part).
  const std::vector<int>& frontFace(int s) const {
    std::vector<int>& face = frontFaces_[s];
    if (face.empty()) {
      voxelTests_ += static_cast<int64_t>(voxels_.size());
      const Int3 d = stepOf(s);
      for (size_t i = 0; i < voxels_.size(); ++i) {
        const Int3 n = plus(voxels_[i], d);
        if (!occupancy_.inside(n.x, n.y, n.z) || occupancy_.label(n.x, n.y, n.z) != label_) {
          face.push_back(static_cast<int>(i));
        }
      }
    }
    return face;
  }

  // Number of unit steps along step s after which the part's box is clear of the obstacles'
  // box, or 0 if it collides on the way.
  int straightEscapeDistance(const Int3& offset, int s) const {
    const Int3 d = stepOf(s);
    Int3 current = offset;
    for (int k = 1;; ++k) {
      current = plus(current, d);
      if (clearOfObstacles(current)) return k;
      if (collides(current, s)) return 0;
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
  int64_t maxVoxelTests_;
  BlockerLog* blockers_;
  Box own_, obstacles_;
  mutable std::array<std::vector<int>, 6> frontFaces_;
  mutable int64_t voxelTests_ = 0;
  bool limitReached_ = false;
};

// Bounding boxes of the parts still in place, kept sorted per side, so that the box of all parts
// but one (the obstacles of that part's search) is read without a scan over the parts.
class RemainingBoxes {
 public:
  void add(int part, const Box& box) { update(part, box, true); }
  void remove(int part, const Box& box) { update(part, box, false); }

  Box excluding(int part) const {
    Box result;
    int* const bounds[6] = {&result.min.x, &result.min.y, &result.min.z, &result.max.x, &result.max.y, &result.max.z};
    for (int side = 0; side < 6; ++side) {
      for (const auto& [key, owner] : sides_[side]) {
        if (owner == part) continue;
        *bounds[side] = side < 3 ? key : -key;  // max sides are stored negated: the first entry is the extreme
        break;
      }
    }
    return result;
  }

 private:
  void update(int part, const Box& box, bool insert) {
    if (box.empty()) return;
    const int keys[6] = {box.min.x, box.min.y, box.min.z, -box.max.x, -box.max.y, -box.max.z};
    for (int side = 0; side < 6; ++side) {
      if (insert) {
        sides_[side].insert({keys[side], part});
      } else {
        sides_[side].erase({keys[side], part});
      }
    }
  }

  std::array<std::set<std::pair<int, int>>, 6> sides_;  // (bound, part), ordered by bound then part
};

// What the planner remembers of a part's last failed search.
struct FailedSearch {
  bool known = false;         // the part failed, and replaying its search would fail the same way
  bool limitReached = false;  // the search stopped at its work limit rather than running out of offsets
  Box obstacles;              // the box of the other parts it searched against (matters only with limitReached)
  int64_t search = -1;        // which search this was, to tell current entries of `dependents` from old ones
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
  RemovalSearch search(occupancy, label, voxels, own, options,
                       std::min(options.maxVoxelTests, options.maxTotalVoxelTests));
  if (!obstacles.empty() && !search.canTakeAnyStep()) return false;
  search.setObstacles(obstacles);
  const bool found = search.findPath(path);
  if (limitReached) *limitReached = search.limitReached();
  return found;
}

bool findVoxelRemovalPathOf(const VoxelGrid& occupancy, int label, const std::vector<int64_t>& partVoxels,
                            const Int3& obstaclesMin, const Int3& obstaclesMax, std::vector<Move>* path) {
  const VoxelDisassemblyOptions options;
  std::vector<Int3> voxels;
  Box own, obstacles;
  for (int64_t i : partVoxels) {
    voxels.push_back(occupancy.coordinates(i));
    own.add(voxels.back());
  }
  if (obstaclesMin.x <= obstaclesMax.x) {
    obstacles.add(obstaclesMin);
    obstacles.add(obstaclesMax);
  }
  if (voxels.empty()) return false;
  RemovalSearch search(occupancy, label, voxels, own, options, std::min(options.maxVoxelTests, options.maxTotalVoxelTests));
  if (!obstacles.empty() && !search.canTakeAnyStep()) return false;
  search.setObstacles(obstacles);
  return search.findPath(path);
}

// Greedy removal in id order (Section 3.3). Searching every remaining part after every removal
// costs up to K searches per round and K^2 in all: a container holding K sealed parts is searched
// in full after every removal, however far away. A failed search is instead kept until a removal
// could change it, and the part is skipped meanwhile:
// - The search met its collisions with its blockers (BlockerLog) and found every other placement
//   it tested free. Removals only free space, so while the blockers stay, the same tests give the
//   same answers and the search fails again.
// - It also read the box of the other parts, which shrinks as parts leave. A smaller box only
//   narrows the offsets tried, and cannot let a sweep count as clear before it collides: a sweep
//   from a placement that is not clear of the box can only become clear by passing beyond the box
//   along its direction, after which it cannot meet a part inside the box; and a placement clear of
//   the smaller box would have had a free sweep sideways, which the failed search would have found
//   (it hit no removed part). So a failure that ran out of offsets survives a smaller box. One
//   that stopped at its work limit does not (fewer offsets might fit the limit): it is searched
//   again when the box changes.
// The plan is therefore the one that searches every part every round (same removals, same
// paths), at one search per part plus one per removal of one of its blockers. The witness chosen
// for each collision (see RemovalSearch::collides) keeps the latter rare.
namespace {

DisassemblyPlan planSinglePartRemovals(const VoxelGrid& grid, const Assembly& assembly,
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
  RemainingBoxes remainingBoxes;
  for (int part = 0; part < partCount; ++part) remainingBoxes.add(part, boxes[part]);
  VoxelGrid occupancy = grid;
  std::vector<bool> removed(partCount, false);
  std::vector<FailedSearch> failed(partCount);
  // dependents[q]: (part, search) pairs whose failed search collided with part q.
  std::vector<std::vector<std::pair<int, int64_t>>> dependents(partCount);
  BlockerLog blockers(partCount);
  DisassemblyPlan plan;
  auto stop = [&](bool outOfBudget) {
    for (int part = 0; part < partCount; ++part) {
      if (!removed[part]) plan.stuck.push_back(part);
    }
    plan.searchLimitReached = plan.searchLimitReached || outOfBudget;
    return plan;
  };
  for (int remaining = partCount; remaining > 1; --remaining) {
    bool progressed = false;
    for (int part = 0; part < partCount && !progressed; ++part) {
      if (removed[part]) continue;
      FailedSearch& last = failed[part];
      if (last.known && (!last.limitReached || last.obstacles == remainingBoxes.excluding(part))) continue;
      // The whole plan's budget: a search may use what is left of it, up to its own limit.
      const int64_t budgetLeft = options.maxTotalVoxelTests - plan.voxelTests;
      if (budgetLeft <= 0) return stop(true);
      blockers.begin(plan.searches);
      blockers.setSettled(part + 1, false);
      last = FailedSearch{};
      last.search = plan.searches++;
      RemovalSearch search(occupancy, part + 1, voxels[part], boxes[part], options,
                           std::min(options.maxVoxelTests, budgetLeft), &blockers);
      std::vector<Move> path;
      bool found = false;
      if (search.canTakeAnyStep()) {
        last.obstacles = remainingBoxes.excluding(part);
        search.setObstacles(last.obstacles);
        found = search.findPath(&path);
      }
      plan.voxelTests += search.voxelTests();
      if (found) {
        plan.removals.push_back({part, path});
        removed[part] = true;
        remainingBoxes.remove(part, boxes[part]);
        for (const Int3& v : voxels[part]) occupancy.setLabel(v.x, v.y, v.z, 0);
        for (const auto& [dependent, which] : dependents[part]) {
          if (failed[dependent].search != which) continue;  // an older search of that part
          failed[dependent].known = false;
          blockers.setSettled(dependent + 1, false);
        }
        dependents[part].clear();
        progressed = true;
        continue;
      }
      if (search.limitReached()) {
        plan.searchLimitReached = true;
        // Out of the plan's budget, not only this search's: what is left is not proven stuck.
        if (plan.voxelTests >= options.maxTotalVoxelTests) return stop(true);
        last.limitReached = true;
      }
      last.known = true;
      blockers.setSettled(part + 1, true);
      for (int label : blockers.labels()) dependents[label - 1].push_back({part, last.search});
    }
    if (!progressed) return stop(false);
  }
  for (int part = 0; part < partCount; ++part) {
    if (!removed[part]) plan.removals.push_back({part, {}});
  }
  plan.complete = true;
  return plan;
}

bool everyRemovalStraight(const DisassemblyPlan& plan) {
  for (const Removal& removal : plan.removals) {
    if (removal.path.size() > 1) return false;
  }
  return true;
}

// A single-part plan as moves, and its level (each removal a separation of its own).
void describeAsMoves(DisassemblyPlan* plan) {
  std::vector<int> moveCounts;
  for (const Removal& removal : plan->removals) {
    if (removal.path.empty()) continue;  // the last part stays
    moveCounts.push_back(static_cast<int>(removal.path.size()));
    for (size_t m = 0; m < removal.path.size(); ++m) {
      const bool out = m + 1 == removal.path.size();
      plan->moves.push_back({{removal.part}, removal.path[m].direction, out ? 0 : removal.path[m].steps, out});
    }
  }
  plan->level = singlePartLevel(moveCounts);
}

}  // namespace

// The single-part plan first: when every removal is straight, each separation takes one move,
// the fewest possible, so the plan is already of the least level. Otherwise the complete
// disassembler decides; a bent single-part plan stands in only where it stops at its bounds.
DisassemblyPlan planVoxelDisassembly(const VoxelGrid& grid, const Assembly& assembly,
                                     const VoxelDisassemblyOptions& options) {
  DisassemblyPlan plan = planSinglePartRemovals(grid, assembly, options);
  if (plan.complete && everyRemovalStraight(plan)) {
    describeAsMoves(&plan);
    plan.levelMinimal = true;
    return plan;
  }
  if (!options.groupMoves) return plan;  // bent: the level is left to the complete disassembler
  GroupPlan group = planGroupDisassembly(grid, assembly.partCount(), options);
  plan.groupStates = group.states;
  if (!group.complete && plan.complete) {
    describeAsMoves(&plan);
    plan.limit = group.limit;
    return plan;
  }
  if (plan.complete) {
    // The single-part plan stands as `removals` (order and paths); the moves are the search's,
    // whose separations come in the order BurrTools' would mostly choose, so that the levels
    // below the first compare. When the single-part plan has that very level, it is those moves.
    DisassemblyPlan asMoves = plan;
    describeAsMoves(&asMoves);
    if (asMoves.level == group.level && asMoves.moves.size() == group.moves.size()) {
      asMoves.levelMinimal = true;
      return asMoves;
    }
    plan.moves = std::move(group.moves);
    plan.level = std::move(group.level);
    plan.levelMinimal = true;
    plan.movesFollowRemovals = false;
    return plan;
  }
  // The complete disassembler's plan, or what it took apart before it stopped.
  plan.complete = group.complete;
  plan.movesFollowRemovals = false;
  plan.singlePartPaths = false;
  plan.removals.clear();
  for (int part : group.freeOrder) plan.removals.push_back({part, {}});
  plan.moves = std::move(group.moves);
  plan.level = std::move(group.level);
  plan.levelMinimal = group.complete;
  plan.unseparated = std::move(group.unseparated);
  plan.stuck.clear();
  for (const auto& together : plan.unseparated) plan.stuck.insert(plan.stuck.end(), together.begin(), together.end());
  std::sort(plan.stuck.begin(), plan.stuck.end());
  plan.searchLimitReached = group.limitReached;
  plan.limit = group.limit;
  return plan;
}

CheckReport checkVoxelAssembly(const VoxelGrid& grid, const CheckOptions& options,
                               const VoxelDisassemblyOptions& disassembly) {
  return checkContacts(assemblyFromVoxels(grid), options,
                       [&](const Assembly& assembly) { return planVoxelDisassembly(grid, assembly, disassembly); });
}

}  // namespace desia
