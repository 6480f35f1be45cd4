// SPDX-License-Identifier: GPL-3.0-or-later
// The complete disassembler (group_disassembly.h). For one position of a sub-assembly and one
// axis, a gap matrix tells how far each part can slide before it meets each other part (Bill
// Cutler's movement matrix, as BurrTools computes it). A set of parts can move `a` units along a
// direction when no part outside the set is within a gap smaller than `a` of a part inside it:
// the least such set containing a part is its closure, and every such set is a union of
// closures. A set whose gaps to the rest are all infinite leaves: a separation.
#include "voxel/group_disassembly.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>
#include <set>
#include <unordered_map>
#include <utility>

#include "desia/error.h"
#include "search/level_notation.h"
#include "voxel/gap_matrix.h"

namespace desia {
namespace {

using group_moves::GapMatrix;
using group_moves::kDirections;
using group_moves::kFar;
using group_moves::PartGeometry;

// Sets moved together per direction and distance, at one position: closures and their unions.
// Hundreds of independent parts could make unions explode; beyond this bound the search is not
// complete and says so.
constexpr size_t kMaxSetsPerMove = 4096;
constexpr int kMaxOffset = 30000;  // positions are stored as int16

Vec3 directionVector(int direction) {
  Vec3 v{0, 0, 0};
  v[kDirections[direction][0]] = kDirections[direction][1];
  return v;
}

// Sets of parts of a sub-assembly (local indices): one word for up to 64 parts, words beyond.
class SmallPartSet {
 public:
  explicit SmallPartSet(int = 0) {}
  void add(int p) { bits_ |= uint64_t{1} << p; }
  bool has(int p) const { return (bits_ >> p) & 1; }
  void unite(const SmallPartSet& other) { bits_ |= other.bits_; }
  int count() const {
    int n = 0;
    for (uint64_t b = bits_; b; b &= b - 1) ++n;
    return n;
  }
  bool operator==(const SmallPartSet& other) const { return bits_ == other.bits_; }
  bool operator<(const SmallPartSet& other) const { return bits_ < other.bits_; }

 private:
  uint64_t bits_ = 0;
};

class WidePartSet {
 public:
  explicit WidePartSet(int parts = 0) : words_(static_cast<size_t>((parts + 63) / 64), 0) {}
  void add(int p) { words_[static_cast<size_t>(p / 64)] |= uint64_t{1} << (p % 64); }
  bool has(int p) const { return (words_[static_cast<size_t>(p / 64)] >> (p % 64)) & 1; }
  void unite(const WidePartSet& other) {
    for (size_t w = 0; w < words_.size(); ++w) words_[w] |= other.words_[w];
  }
  int count() const {
    int n = 0;
    for (uint64_t word : words_) {
      for (uint64_t b = word; b; b &= b - 1) ++n;
    }
    return n;
  }
  bool operator==(const WidePartSet& other) const { return words_ == other.words_; }
  bool operator<(const WidePartSet& other) const { return words_ < other.words_; }

 private:
  std::vector<uint64_t> words_;
};

// The positions of one sub-assembly visited breadth-first: the offsets of its k parts (int16,
// relative to its first part), the position each was reached from, and a hash set over them.
// The move between two positions is read back from their difference (the parts that moved).
class PositionStore {
 public:
  explicit PositionStore(int parts) : width_(3 * parts) {}

  size_t size() const { return parent_.size(); }
  int width() const { return width_; }
  const int16_t* offsets(size_t state) const { return &offsets_[state * static_cast<size_t>(width_)]; }
  int32_t parent(size_t state) const { return parent_[state]; }
  // The memory the store would hold after one more insert (vectors grow by doubling).
  int64_t bytesAfterInsert() const {
    auto grown = [](size_t size, size_t capacity, size_t added) {
      return size + added <= capacity ? capacity : std::max(size + added, 2 * capacity);
    };
    const size_t slots = (parent_.size() + 1) * 2 > slots_.size() ? std::max<size_t>(64, slots_.size() * 2) : slots_.size();
    return static_cast<int64_t>(grown(offsets_.size(), offsets_.capacity(), static_cast<size_t>(width_)) * sizeof(int16_t) +
                                grown(parent_.size(), parent_.capacity(), 1) * sizeof(int32_t) + slots * sizeof(int32_t));
  }

  // Adds the position unless already known; true when it is new.
  bool insert(const std::vector<int16_t>& offsets, int32_t parent) {
    if ((parent_.size() + 1) * 2 > slots_.size()) grow();
    size_t slot = hashOf(offsets.data()) & (slots_.size() - 1);
    while (slots_[slot] >= 0) {
      if (std::equal(offsets.begin(), offsets.end(), this->offsets(static_cast<size_t>(slots_[slot])))) return false;
      slot = (slot + 1) & (slots_.size() - 1);
    }
    slots_[slot] = static_cast<int32_t>(parent_.size());
    offsets_.insert(offsets_.end(), offsets.begin(), offsets.end());
    parent_.push_back(parent);
    return true;
  }

 private:
  uint64_t hashOf(const int16_t* offsets) const {
    uint64_t h = 1469598103934665603ULL;
    for (int k = 0; k < width_; ++k) {
      h ^= static_cast<uint16_t>(offsets[k]);
      h *= 1099511628211ULL;
    }
    return h ^ (h >> 29);
  }

  void grow() {
    std::vector<int32_t> slots(std::max<size_t>(64, slots_.size() * 2), -1);
    for (size_t state = 0; state < parent_.size(); ++state) {
      size_t slot = hashOf(offsets(state)) & (slots.size() - 1);
      while (slots[slot] >= 0) slot = (slot + 1) & (slots.size() - 1);
      slots[slot] = static_cast<int32_t>(state);
    }
    slots_.swap(slots);
  }

  int width_;
  std::vector<int16_t> offsets_;
  std::vector<int32_t> parent_;
  std::vector<int32_t> slots_;
};

// One sub-assembly's search: from its parts' offsets to the first separation, breadth-first.
template <typename PartSet>
class SubAssemblySearch {
 public:
  enum class Outcome { Separated, Stuck, LimitReached };

  // `work`: the plan's count of the search's operations (part-pair tests and set unions), shared
  // by its sub-assemblies and bounded by options.maxGroupWork.
  SubAssemblySearch(PartGeometry& geometry, const std::vector<int>& parts, const VoxelDisassemblyOptions& options,
                    int64_t* work)
      : parts_(parts), k_(static_cast<int>(parts.size())), options_(options), store_(k_), gaps_(geometry, parts_),
        work_(work) {}

  // `offsets`: 3 per part, in the order of `parts`.
  Outcome run(const std::vector<int>& offsets) {
    std::vector<int16_t> start(offsets.size());
    for (size_t n = 0; n < offsets.size(); ++n) start[n] = static_cast<int16_t>(offsets[n] - offsets[n % 3]);
    store_.insert(start, -1);
    std::vector<Moved> moves;
    std::vector<int16_t> next(start.size());
    for (size_t state = 0; state < store_.size(); ++state) {
      gaps_.fill(store_.offsets(state));
      *work_ += static_cast<int64_t>(k_) * k_;
      if (findSeparation()) {
        separationState_ = state;
        return Outcome::Separated;
      }
      const MovesFound found = movesFrom(&moves);
      if (found == MovesFound::TooManySets) {
        limit_ = "more than " + std::to_string(kMaxSetsPerMove) + " sets of parts move alike at one position";
        return Outcome::LimitReached;
      }
      if (found == MovesFound::OutOfWork || *work_ > options_.maxGroupWork) {
        limit_ = std::to_string(options_.maxGroupWork) + " operations of the search for moves (maxGroupWork)";
        return Outcome::LimitReached;
      }
      for (const Moved& move : moves) {
        if (!moved(store_.offsets(state), move, &next)) {
          limit_ = "parts moved more than " + std::to_string(kMaxOffset) + " units apart";
          return Outcome::LimitReached;
        }
        // Bounds checked before the position is kept: its memory would be taken first.
        if (static_cast<int64_t>(store_.size()) >= options_.maxGroupStates) {
          limit_ = std::to_string(options_.maxGroupStates) + " positions of a sub-assembly (maxGroupStates)";
          return Outcome::LimitReached;
        }
        if (store_.bytesAfterInsert() > options_.maxGroupBytes) {
          limit_ = std::to_string(options_.maxGroupBytes >> 20) + " MiB of positions (maxGroupBytes)";
          return Outcome::LimitReached;
        }
        store_.insert(next, static_cast<int32_t>(state));
      }
    }
    return Outcome::Stuck;
  }

  int64_t states() const { return static_cast<int64_t>(store_.size()); }
  const std::string& limit() const { return limit_; }

  // After Separated: the moves from the start to the separation, the last one `out`.
  std::vector<GroupMove> plan() const {
    std::vector<GroupMove> moves{outMove()};
    for (size_t state = separationState_; store_.parent(state) >= 0; state = static_cast<size_t>(store_.parent(state))) {
      moves.push_back(moveBetween(store_.offsets(static_cast<size_t>(store_.parent(state))), store_.offsets(state)));
    }
    std::reverse(moves.begin(), moves.end());
    return moves;
  }
  // After Separated: which parts left, and every part's offset at that moment.
  std::vector<char> leaving() const {
    std::vector<char> flags(static_cast<size_t>(k_));
    for (int p = 0; p < k_; ++p) flags[static_cast<size_t>(p)] = separation_.parts.has(p);
    return flags;
  }
  std::vector<int> offsetsAtSeparation() const {
    const int16_t* offsets = store_.offsets(separationState_);
    return std::vector<int>(offsets, offsets + store_.width());
  }

 private:
  struct Moved {
    int direction = 0;
    int amount = 0;  // 0: out to infinity
    PartSet parts;
  };

  // The least set containing part x that can move `amount` units (kFar: out) along `direction`.
  PartSet closure(int x, int direction, int amount) const {
    PartSet set(k_);
    set.add(x);
    std::vector<int>& frontier = frontier_;
    frontier.assign(1, x);
    while (!frontier.empty()) {
      const int p = frontier.back();
      frontier.pop_back();
      *work_ += k_;
      for (int q = 0; q < k_; ++q) {
        if (set.has(q) || gaps_.gap(direction, p, q) >= amount) continue;
        set.add(q);
        frontier.push_back(q);
      }
    }
    return set;
  }

  // The smallest set that can leave (ties: the first direction, then the lowest part).
  bool findSeparation() {
    bool found = false;
    int bestCount = 0;
    for (int direction = 0; direction < 6; ++direction) {
      for (int x = 0; x < k_; ++x) {
        PartSet set = closure(x, direction, kFar);
        const int count = set.count();
        if (count == k_ || (found && count >= bestCount)) continue;
        separation_ = Moved{direction, 0, std::move(set)};
        bestCount = count;
        found = true;
      }
    }
    return found;
  }

  enum class MovesFound { All, TooManySets, OutOfWork };

  // Every finite move from the current gaps: closures for each part, direction and distance,
  // and their unions (moving independent sets at once is one move).
  MovesFound movesFrom(std::vector<Moved>* moves) const {
    moves->clear();
    std::vector<PartSet> sets;
    for (int direction = 0; direction < 6; ++direction) {
      for (int amount = 1;; ++amount) {
        sets.clear();
        for (int x = 0; x < k_; ++x) {
          PartSet set = closure(x, direction, amount);
          if (set.count() != k_) sets.push_back(std::move(set));
        }
        if (sets.empty()) break;
        std::sort(sets.begin(), sets.end());
        sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
        const MovesFound unions = addUnions(&sets);
        if (unions != MovesFound::All) return unions;
        for (PartSet& set : sets) moves->push_back(Moved{direction, amount, std::move(set)});
        if (*work_ > options_.maxGroupWork) return MovesFound::OutOfWork;
      }
    }
    return MovesFound::All;
  }

  // Unions of the closures, each set once (the closures are sorted and distinct on entry). With
  // m independent closures there are 2^m - 1: kMaxSetsPerMove and the work bound stop that.
  MovesFound addUnions(std::vector<PartSet>* sets) const {
    std::set<PartSet> known(sets->begin(), sets->end());
    for (size_t a = 0; a < sets->size(); ++a) {
      for (size_t b = 0; b < a; ++b) {
        *work_ += 4 * k_;  // a union, its count and a lookup in an ordered set: a few closure steps
        PartSet joined = (*sets)[a];
        joined.unite((*sets)[b]);
        if (joined.count() == k_ || !known.insert(joined).second) continue;
        if (sets->size() >= kMaxSetsPerMove) return MovesFound::TooManySets;
        sets->push_back(std::move(joined));
      }
      if (*work_ > options_.maxGroupWork) return MovesFound::OutOfWork;
    }
    return MovesFound::All;
  }

  bool moved(const int16_t* offsets, const Moved& move, std::vector<int16_t>* next) const {
    const int axis = kDirections[move.direction][0], step = kDirections[move.direction][1] * move.amount;
    const bool firstMoves = move.parts.has(0);
    for (int p = 0; p < k_; ++p) {
      for (int a = 0; a < 3; ++a) {
        int value = offsets[3 * p + a];
        if (a == axis && move.parts.has(p)) value += step;
        if (a == axis && firstMoves) value -= step;  // keep the first part at the origin
        if (value > kMaxOffset || value < -kMaxOffset) return false;
        (*next)[static_cast<size_t>(3 * p + a)] = static_cast<int16_t>(value);
      }
    }
    return true;
  }

  // The move from one position to the next: the parts whose offset changed moved by that change
  // (the first part never moves: when it went with others, the rest moved the other way).
  GroupMove moveBetween(const int16_t* before, const int16_t* after) const {
    GroupMove move;
    int shift[3] = {0, 0, 0};
    for (int p = 0; p < k_; ++p) {
      const int d[3] = {after[3 * p] - before[3 * p], after[3 * p + 1] - before[3 * p + 1],
                        after[3 * p + 2] - before[3 * p + 2]};
      if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
      move.parts.push_back(parts_[p]);
      std::copy(d, d + 3, shift);
    }
    std::sort(move.parts.begin(), move.parts.end());
    for (int a = 0; a < 3; ++a) {
      if (shift[a] == 0) continue;
      move.direction[a] = shift[a] > 0 ? 1 : -1;
      move.steps = std::abs(shift[a]);
    }
    return move;
  }

  GroupMove outMove() const {
    GroupMove move;
    for (int p = 0; p < k_; ++p) {
      if (separation_.parts.has(p)) move.parts.push_back(parts_[p]);
    }
    std::sort(move.parts.begin(), move.parts.end());
    move.direction = directionVector(separation_.direction);
    move.out = true;
    return move;
  }

  std::vector<int> parts_;
  int k_;
  const VoxelDisassemblyOptions& options_;
  PositionStore store_;
  GapMatrix gaps_;
  mutable std::vector<int> frontier_;
  int64_t* work_;
  size_t separationState_ = 0;
  Moved separation_;
  std::string limit_;
};

using search::levelOf;
using search::Separation;
using PendingSubAssembly = search::PendingSubAssembly<int>;  // offsets: 3 cell counts per part

}  // namespace

std::vector<int> singlePartLevel(const std::vector<int>& moveCounts) {
  std::vector<Separation> chain;
  for (size_t k = 0; k < moveCounts.size(); ++k) {
    chain.push_back({moveCounts[k], k + 1 < moveCounts.size() ? static_cast<int>(k + 1) : -1, -1});
  }
  return levelOf(chain);
}

namespace {

// Records a separation of `current` (the moves to it, the last one out) and queues both sides,
// each continuing from `offsets` (where its parts were when they separated).
void recordSeparation(const PendingSubAssembly& current, const std::vector<GroupMove>& moves,
                      const std::vector<char>& leaving, const std::vector<int>& offsets, GroupPlan* plan,
                      std::vector<Separation>* tree, std::vector<PendingSubAssembly>* pending) {
  plan->moves.insert(plan->moves.end(), moves.begin(), moves.end());
  const int node = search::addSeparation(tree, static_cast<int>(moves.size()), current.parent, current.left);
  PendingSubAssembly sides[2];  // [0] left in place, [1] removed
  for (size_t p = 0; p < current.parts.size(); ++p) {
    PendingSubAssembly& side = sides[leaving[p] ? 1 : 0];
    side.parts.push_back(current.parts[p]);
    side.offsets.insert(side.offsets.end(), offsets.begin() + static_cast<std::ptrdiff_t>(3 * p),
                        offsets.begin() + static_cast<std::ptrdiff_t>(3 * p + 3));
  }
  for (int s : {1, 0}) {
    if (sides[s].parts.size() == 1) plan->freeOrder.push_back(sides[s].parts[0]);
  }
  for (int s : {1, 0}) {  // pushed removed first, so the side left in place is taken apart first
    if (sides[s].parts.size() < 2) continue;
    sides[s].parent = node;
    sides[s].left = s == 0;
    pending->push_back(std::move(sides[s]));
  }
}

// Searches one sub-assembly; on a separation records it and queues both sides.
template <typename PartSet>
bool searchSubAssembly(PartGeometry& geometry, const PendingSubAssembly& current, const VoxelDisassemblyOptions& options,
                       GroupPlan* plan, std::vector<Separation>* tree, std::vector<PendingSubAssembly>* pending) {
  SubAssemblySearch<PartSet> search(geometry, current.parts, options, &plan->work);
  const auto outcome = search.run(current.offsets);
  plan->states += search.states();
  if (outcome == SubAssemblySearch<PartSet>::Outcome::Separated) {
    recordSeparation(current, search.plan(), search.leaving(), search.offsetsAtSeparation(), plan, tree, pending);
    return true;
  }
  if (outcome == SubAssemblySearch<PartSet>::Outcome::LimitReached) {
    plan->limitReached = true;
    plan->limit = search.limit();
  }
  return false;
}

}  // namespace

GroupPlan planGroupDisassembly(const VoxelGrid& grid, int partCount, const VoxelDisassemblyOptions& options) {
  GroupPlan plan;
  if (partCount < 2) {
    plan.complete = true;
    if (partCount == 1) plan.freeOrder.push_back(0);
    return plan;
  }
  PartGeometry geometry(grid, partCount);
  std::vector<Separation> tree;
  PendingSubAssembly whole;
  for (int part = 0; part < partCount; ++part) whole.parts.push_back(part);
  whole.offsets.assign(static_cast<size_t>(3 * partCount), 0);
  std::vector<PendingSubAssembly> pending{whole};
  while (!pending.empty()) {
    PendingSubAssembly current = std::move(pending.back());
    pending.pop_back();
    const int k = static_cast<int>(current.parts.size());
    if (k > options.maxGroupParts) {
      plan.unseparated.push_back(current.parts);
      plan.limitReached = true;
      plan.limit = std::to_string(k) + " parts held together: the search takes at most " +
                   std::to_string(options.maxGroupParts) + " (maxGroupParts)";
      continue;
    }
    const bool separated = k <= 64 ? searchSubAssembly<SmallPartSet>(geometry, current, options, &plan, &tree, &pending)
                                   : searchSubAssembly<WidePartSet>(geometry, current, options, &plan, &tree, &pending);
    if (!separated) plan.unseparated.push_back(current.parts);
  }
  plan.complete = plan.unseparated.empty();
  plan.level = levelOf(tree);  // of the separations made, when the plan stopped short
  return plan;
}

}  // namespace desia
