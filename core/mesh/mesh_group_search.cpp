// SPDX-License-Identifier: GPL-3.0-or-later
// The complete search for moves of several parts (paper Section 3.3; BurrTools' disassembler, as
// core/voxel/group_disassembly.cpp runs it on cells) for mesh assemblies off any lattice. At one
// position of a sub-assembly and one direction d (a base direction of the assembly's contacts,
// either sign), the gap of parts p and q is how far p travels along d before q stops it, swept on
// the triangles (pairTravelDistance; infinity when it passes). A set of parts can move a distance
// a when no part outside it is within a gap below a of a part inside: the least such set holding a
// part is its closure, and every such set a union of closures. A set whose gaps to the rest are
// all infinite leaves: a separation, after which both sides are searched on their own (an explicit
// work list). The distances tried are those where the moving parts' faces square to d meet the
// faces square to d of the parts they pass (where a channel across d may open, as cells meet on a
// lattice), and the gaps themselves (where a slanted face stops a move). Positions are the parts'
// offsets from the sub-assembly's first part, hashed rounded to the tolerance; breadth-first, so
// the first separation found has the fewest moves (BurrTools' level). Bounded by counts of positions and of
// work (triangles swept, set operations: the same plan everywhere).
//
// What it proves: where every face of every part is square or parallel to every direction tried
// (boxes drawn off any lattice), the distances tried are all the distances at which what can move
// changes, as the cells' sizes are on a lattice, so the level is the least and a search that runs
// out of positions proves the parts left stuck (for moves along those directions, as BurrTools'
// and the voxel kind's proofs are). Where a face is slanted, a way out may need a distance no
// square face or gap marks (a peg that lines up with a countersunk hole), so the plan
// found is not proven the fewest and parts left are not proven stuck: the plan says why.
#include "mesh/mesh_group_search.h"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <unordered_map>
#include <set>

#include "desia/analysis.h"
#include "desia/tolerances.h"
#include "mesh/mesh_lattice.h"
#include "search/level_notation.h"

namespace desia::mesh {
namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();
// Sets of parts are bit masks: a sub-assembly of more parts held together is not searched.
constexpr size_t kMostParts = 64;
// Sets moved alike at one position (closures and their unions), as the voxel search bounds them:
// past it (or GroupSearchLimits) the plan says "not proven".
constexpr size_t kMostSetsPerMove = 4096;

using PartMask = uint64_t;

// Hashes a key of integers (FNV-1a over their bits): the maps below are only looked up, never
// walked, so their order cannot reach the plan.
struct IntegersHash {
  template <typename Integers>
  size_t operator()(const Integers& key) const {
    uint64_t hash = 1469598103934665603ull;
    for (const int64_t value : key) hash = (hash ^ static_cast<uint64_t>(value)) * 1099511628211ull;
    return static_cast<size_t>(hash);
  }
};

// A cache key: two parts and their relative offset in tolerances, or -1, two parts and a direction.
using CacheKey = std::array<int64_t, 5>;

std::string workLimitText(const GroupSearchLimits& limits) {
  return std::to_string(limits.work) + " steps of work (triangles swept, sets of parts joined)";
}

int countOf(PartMask mask) { return static_cast<int>(std::bitset<64>(mask).count()); }

// A position of a sub-assembly: each part's offset from where the search began, relative to the
// first part (which never moves: when it went with others, the rest moved the other way), and the
// move that led here (the set that moved, along which direction, how far).
struct Position {
  std::vector<Vec3> offsets;
  int parent = -1;
  int direction = -1;
  double amount = 0;
  PartMask moved = 0;
};

// The values ascending, one of each run within `tolerance` (its least).
std::vector<double> distinctSorted(std::vector<double> values, double tolerance) {
  std::sort(values.begin(), values.end());
  std::vector<double> distinct;
  for (double value : values) {
    if (distinct.empty() || value - distinct.back() > tolerance) distinct.push_back(value);
  }
  return distinct;
}

// The base directions of the contacts (paper Section 3.1). Three square ones (a puzzle drawn on
// axes, turned any way) are taken as the voxel kind takes its axes, the second first (core/voxel/
// gap_matrix.h), each signed and matched to the world axis it lies nearest as the lattice reading
// matches them (mesh_lattice.cpp): when several separations are equally small the first is taken,
// and the levels after the first number depend on it, so a puzzle reads the same level on and off
// its lattice.
std::vector<Vec3> searchDirections(const Assembly& assembly) {
  std::vector<Vec3> bases;
  for (const BaseDirection& base : computeBaseDirections(assembly)) bases.push_back(base.vector);
  const auto square = [](const Vec3& a, const Vec3& b) { return std::abs(dot(a, b)) < tolerance::kSquareCosine; };
  if (bases.size() != 3 || !square(bases[0], bases[1]) || !square(bases[0], bases[2]) || !square(bases[1], bases[2])) {
    return bases;
  }
  std::array<Vec3, 3> axes{};
  std::array<bool, 3> used{false, false, false};
  for (size_t world = 0; world < 3; ++world) {
    size_t best = 3;
    for (size_t k = 0; k < 3; ++k) {
      if (!used[k] && (best == 3 || std::abs(bases[k][world]) > std::abs(bases[best][world]))) best = k;
    }
    used[best] = true;
    axes[world] = bases[best][world] < 0 ? negated(bases[best]) : bases[best];
  }
  return {axes[1], axes[0], cross(axes[0], axes[1])};  // right-handed, as the lattice's grid
}

// Is the triangle's plane square to d, or parallel to it (as drawn: the sweep's own reading)?
bool squareToDirection(const Triangle& t, const Vec3& d) { return std::abs(dot(t.normal, d)) >= 1 - tolerance::kFacingCosine; }
bool parallelToDirection(const Triangle& t, const Vec3& d) { return std::abs(dot(t.normal, d)) <= tolerance::kDrawnDirectionRad; }

// Why the search cannot prove (see the file's comment), or "" when it can: the directions must be
// three lines square to each other (fewer leave ways out untried: a part may need to step back
// along a contact's normal before a move along their cross product), and every face must lie
// square to one of them, flat along it within the tolerance, and parallel to the other two.
std::string whyNotProven(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                         const std::vector<Vec3>& directions) {
  const auto squareLines = [](const Vec3& a, const Vec3& b) { return std::abs(dot(a, b)) < tolerance::kSquareCosine; };
  if (directions.size() != 6 || !squareLines(directions[0], directions[2]) || !squareLines(directions[0], directions[4]) ||
      !squareLines(directions[2], directions[4])) {
    return "the contacts give " + std::to_string(directions.size() / 2) +
           " lines to move along, not three square to each other, and the search does not try every way out";
  }
  for (size_t part = 0; part < geometry.size(); ++part) {
    for (const Triangle& t : geometry[part].triangles) {
      if (t.twiceArea <= 0) continue;
      int squareTo = 0;
      for (size_t line = 0; line < 6; line += 2) {
        const Vec3& d = directions[line];
        if (squareToDirection(t, d)) {
          const double lo = std::min({dot(t.p[0], d), dot(t.p[1], d), dot(t.p[2], d)});
          const double hi = std::max({dot(t.p[0], d), dot(t.p[1], d), dot(t.p[2], d)});
          if (hi - lo <= meshes.tolerance) ++squareTo;
        } else if (!parallelToDirection(t, d)) {
          squareTo = -1;
          break;
        }
      }
      if (squareTo != 1) {
        return "part " + std::to_string(meshes.parts[part].id) +
               " has faces slanted to the moves tried, and off a lattice the search does not try every distance there";
      }
    }
  }
  return "";
}

// What every sub-assembly's search shares: the directions, each part's levels of faces square to
// each direction, the gaps of part pairs by their relative offset (most recur: a move changes the
// offsets of the parts it moves only), and the work done.
class SearchContext {
 public:
  SearchContext(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry, const GroupSearchLimits& limits)
      : meshes_(meshes), geometry_(geometry), limits_(limits) {
    for (const Vec3& d : searchDirections(meshes.assembly)) {
      directions_.push_back(d);
      directions_.push_back(negated(d));
    }
    notProven_ = whyNotProven(meshes, geometry, directions_);
    levels_.resize(geometry.size());
    for (size_t part = 0; part < geometry.size(); ++part) {
      for (const Vec3& d : directions_) levels_[part].push_back(squareLevels(geometry[part], d));
    }
  }

  const MeshAssembly& meshes() const { return meshes_; }
  const std::vector<Vec3>& directions() const { return directions_; }
  int64_t sweeps() const { return sweeps_; }
  const GroupSearchLimits& limits() const { return limits_; }
  // Why the search cannot prove the fewest moves or stuck parts; "" when it can.
  const std::string& notProven() const { return notProven_; }
  void addWork(int64_t steps) { work_ += steps; }
  int64_t work() const { return work_; }
  bool outOfWork() const { return work_ > limits_.work; }

  // Where part p's faces square to direction dir meet part q's when p moves along it (both at
  // offset 0): each level of q less each level of p, ascending, distinct within the tolerance.
  const std::vector<double>& levelDifferences(int p, int q, int dir) {
    const CacheKey key{-1, p, q, dir, 0};
    if (const std::vector<double>* known = cached(key)) return *known;
    std::vector<double> values;
    for (double mine : levels_[static_cast<size_t>(p)][static_cast<size_t>(dir)]) {
      for (double theirs : levels_[static_cast<size_t>(q)][static_cast<size_t>(dir)]) values.push_back(theirs - mine);
    }
    work_ += static_cast<int64_t>(values.size());
    return cache(key, distinctSorted(std::move(values), meshes_.tolerance));
  }

  // Gaps of part p placed at `offset` from part q, along every direction (index as directions()).
  // Swept in place: p's triangles are moved one at a time inside the sweep, after its box passed.
  const std::vector<double>& gaps(int p, int q, const Vec3& offset) {
    const double tolerance = meshes_.tolerance;
    const auto key = [&](int a, int b, const Vec3& r) {
      return CacheKey{a, b, std::llround(r[0] / tolerance), std::llround(r[1] / tolerance), std::llround(r[2] / tolerance)};
    };
    if (const std::vector<double>* known = cached(key(p, q, offset))) return *known;
    const PartGeometry& mover = geometry_[static_cast<size_t>(p)];
    const PartGeometry& obstacle = geometry_[static_cast<size_t>(q)];
    std::vector<double> forward(directions_.size()), backward(directions_.size());
    for (size_t dir = 0; dir < directions_.size(); ++dir) {
      // q moving against d meets p exactly where p moving along d meets q.
      forward[dir] = backward[dir ^ 1] = pairTravelDistance(meshes_, mover, offset, obstacle, directions_[dir], &work_);
      ++sweeps_;
    }
    cache(key(q, p, negated(offset)), std::move(backward));
    return cache(key(p, q, offset), std::move(forward));
  }

 private:
  const std::vector<double>* cached(const CacheKey& key) const {
    const auto found = cacheIndex_.find(key);
    return found == cacheIndex_.end() ? nullptr : &cacheValues_[found->second];
  }
  const std::vector<double>& cache(const CacheKey& key, std::vector<double> values) {
    const auto placed = cacheIndex_.emplace(key, cacheValues_.size());
    if (placed.second) cacheValues_.push_back(std::move(values));
    return cacheValues_[placed.first->second];
  }

  // Where the part's faces square to d lie along d (where cells meet, on a lattice). Not the
  // vertices of faces slanted to d: tried, they multiply the positions (DraculasDentalDesaster,
  // dented at a slant, went from 634 positions past 100,000), and they would not make the distances
  // complete either (two slanted faces' edges crossing mark a distance no vertex does).
  std::vector<double> squareLevels(const PartGeometry& part, const Vec3& d) const {
    std::vector<double> values;
    for (const Triangle& t : part.triangles) {
      if (t.twiceArea <= 0 || !squareToDirection(t, d)) continue;
      for (const Vec3& p : t.p) values.push_back(dot(p, d));
    }
    return distinctSorted(std::move(values), meshes_.tolerance);
  }

  const MeshAssembly& meshes_;
  const std::vector<PartGeometry>& geometry_;
  GroupSearchLimits limits_;
  std::vector<Vec3> directions_;
  std::string notProven_;
  std::vector<std::vector<std::vector<double>>> levels_;
  // Gaps (keyed by two parts and their relative offset in tolerances) and level differences
  // (keyed by -1, two parts and a direction), in one store: one kind of map keeps the code small.
  // A deque: a reference handed out stays valid while later entries are added.
  std::unordered_map<CacheKey, size_t, IntegersHash> cacheIndex_;
  std::deque<std::vector<double>> cacheValues_;
  int64_t sweeps_ = 0;
  int64_t work_ = 0;
};

// A set of parts moved along directions()[direction] by `amount` (kFar: out).
struct SetMove {
  int direction = 0;
  double amount = 0;
  PartMask parts = 0;
};

// One sub-assembly's search, from its parts' offsets to the first separation, breadth-first.
class SubAssemblySearch {
 public:
  enum class Outcome { Separated, Stuck, LimitReached };

  SubAssemblySearch(SearchContext& context, const std::vector<int>& parts)
      : context_(context), parts_(parts), k_(static_cast<int>(parts.size())) {}

  Outcome run(const std::vector<Vec3>& offsets) {
    Position start;
    for (const Vec3& offset : offsets) start.offsets.push_back(minus(offset, offsets.front()));
    known_.emplace(keyOf(start), 0);
    positions_.push_back(std::move(start));
    std::vector<SetMove> moves;
    for (size_t at = 0; at < positions_.size(); ++at) {
      if (!fillGaps(positions_[at])) return stop(workLimitText(context_.limits()));
      if (findSeparation()) {  // the gaps are all known: a separation found is sound past the bound too
        separationPosition_ = at;
        return Outcome::Separated;
      }
      const MovesFound found = movesFrom(positions_[at], &moves);
      if (found == MovesFound::TooManySets) {
        return stop("more than " + std::to_string(kMostSetsPerMove) + " sets of parts move alike at one position");
      }
      if (found == MovesFound::OutOfWork || context_.outOfWork()) return stop(workLimitText(context_.limits()));
      for (const SetMove& move : moves) {
        Position next = moved(positions_[at], move, static_cast<int>(at));
        std::vector<int64_t> key = keyOf(next);
        if (known_.count(key)) continue;
        if (positions_.size() >= context_.limits().positions) {
          return stop(std::to_string(context_.limits().positions) + " positions of a sub-assembly");
        }
        known_.emplace(std::move(key), positions_.size());
        positions_.push_back(std::move(next));
      }
    }
    return Outcome::Stuck;
  }

  size_t positions() const { return positions_.size(); }
  const std::string& limit() const { return limit_; }
  const std::vector<Vec3>& offsetsAtSeparation() const { return positions_[separationPosition_].offsets; }
  bool leaves(int local) const { return (separation_.parts >> local) & 1; }

  // After Separated: the moves from the start to the separation, the last one out.
  std::vector<GroupMove> plan() const {
    std::vector<GroupMove> moves{groupMove(separation_.parts, separation_.direction, kFar)};
    for (size_t at = separationPosition_; positions_[at].parent >= 0; at = static_cast<size_t>(positions_[at].parent)) {
      const Position& position = positions_[at];
      moves.push_back(groupMove(position.moved, position.direction, position.amount));
    }
    std::reverse(moves.begin(), moves.end());
    return moves;
  }

 private:
  Outcome stop(const std::string& limit) {
    limit_ = limit;
    return Outcome::LimitReached;
  }

  GroupMove groupMove(PartMask set, int direction, double amount) const {
    GroupMove move;
    for (int p = 0; p < k_; ++p) {
      if ((set >> p) & 1) move.parts.push_back(parts_[static_cast<size_t>(p)]);
    }
    std::sort(move.parts.begin(), move.parts.end());
    move.direction = context_.directions()[static_cast<size_t>(direction)];
    move.out = std::isinf(amount);
    move.length = move.out ? 0 : amount;
    return move;
  }

  // The position's offsets rounded to the tolerance: positions within it of each other are one.
  std::vector<int64_t> keyOf(const Position& position) const {
    const double tolerance = context_.meshes().tolerance;
    std::vector<int64_t> key;
    for (const Vec3& offset : position.offsets) {
      for (int i = 0; i < 3; ++i) key.push_back(std::llround(offset[i] / tolerance));
    }
    return key;
  }

  // gaps_[dir][p * k + q]: how far p travels along direction dir before q stops it.
  // False when the work bound stopped it part-way (the gaps are then not all known).
  bool fillGaps(const Position& position) {
    const size_t directions = context_.directions().size();
    gaps_.assign(directions, std::vector<double>(static_cast<size_t>(k_ * k_), kFar));
    for (int p = 0; p < k_; ++p) {
      for (int q = p + 1; q < k_; ++q) {
        if (context_.outOfWork()) return false;
        const Vec3 offset = minus(position.offsets[static_cast<size_t>(p)], position.offsets[static_cast<size_t>(q)]);
        const std::vector<double>& gaps = context_.gaps(parts_[static_cast<size_t>(p)], parts_[static_cast<size_t>(q)], offset);
        for (size_t dir = 0; dir < directions; ++dir) {
          gaps_[dir][static_cast<size_t>(p * k_ + q)] = gaps[dir];
          gaps_[dir ^ 1][static_cast<size_t>(q * k_ + p)] = gaps[dir];
        }
      }
    }
    return true;
  }

  // The least set holding part x that can move `amount` along direction dir (kFar: out).
  PartMask closure(int x, int dir, double amount) const {
    context_.addWork(static_cast<int64_t>(k_) * k_);  // at most every pair looked at once
    const double reach = std::isinf(amount) ? kFar : amount - context_.meshes().tolerance;
    const std::vector<double>& gaps = gaps_[static_cast<size_t>(dir)];
    PartMask set = PartMask{1} << x;
    std::vector<int> frontier{x};
    while (!frontier.empty()) {
      const int p = frontier.back();
      frontier.pop_back();
      for (int q = 0; q < k_; ++q) {
        if (((set >> q) & 1) || gaps[static_cast<size_t>(p * k_ + q)] >= reach) continue;
        set |= PartMask{1} << q;
        frontier.push_back(q);
      }
    }
    return set;
  }

  // The smallest set that can leave (ties: the first direction, then the lowest part).
  bool findSeparation() {
    bool found = false;
    for (int dir = 0; dir < static_cast<int>(context_.directions().size()); ++dir) {
      for (int x = 0; x < k_; ++x) {
        const PartMask set = closure(x, dir, kFar);
        if (countOf(set) == k_ || (found && countOf(set) >= countOf(separation_.parts))) continue;
        separation_ = SetMove{dir, kFar, set};
        found = true;
      }
    }
    return found;
  }

  // The distances worth a move along dir: where a level of a part's faces square to dir meets a
  // level of another part's, and every finite gap; none beyond the largest finite gap (a set that
  // can move farther leaves).
  std::vector<double> amounts(const Position& position, int dir) const {
    const double tolerance = context_.meshes().tolerance;
    const Vec3& d = context_.directions()[static_cast<size_t>(dir)];
    const std::vector<double>& gaps = gaps_[static_cast<size_t>(dir)];
    double largest = 0;
    std::vector<double> values;
    for (double gap : gaps) {
      if (std::isinf(gap) || gap <= tolerance) continue;
      largest = std::max(largest, gap);
      values.push_back(gap);
    }
    for (int p = 0; p < k_; ++p) {
      const double shiftP = dot(position.offsets[static_cast<size_t>(p)], d);
      for (int q = 0; q < k_; ++q) {
        if (q == p) continue;
        const double shift = dot(position.offsets[static_cast<size_t>(q)], d) - shiftP;
        const std::vector<double>& differences =
            context_.levelDifferences(parts_[static_cast<size_t>(p)], parts_[static_cast<size_t>(q)], dir);
        for (auto it = std::upper_bound(differences.begin(), differences.end(), tolerance - shift);
             it != differences.end() && *it + shift < largest; ++it) {
          values.push_back(*it + shift);
        }
      }
    }
    context_.addWork(static_cast<int64_t>(values.size()));  // gathered and sorted
    return distinctSorted(std::move(values), tolerance);
  }

  enum class MovesFound { All, TooManySets, OutOfWork };

  // Every finite move from the current gaps: closures for each part, direction and distance, and
  // their unions (moving independent sets at once is one move).
  MovesFound movesFrom(const Position& position, std::vector<SetMove>* moves) const {
    moves->clear();
    const PartMask all = k_ == 64 ? ~PartMask{0} : (PartMask{1} << k_) - 1;
    std::vector<PartMask> sets;
    for (int dir = 0; dir < static_cast<int>(context_.directions().size()); ++dir) {
      for (double amount : amounts(position, dir)) {
        sets.clear();
        for (int x = 0; x < k_; ++x) {
          const PartMask set = closure(x, dir, amount);
          if (set != all) sets.push_back(set);
        }
        if (sets.empty()) break;
        std::sort(sets.begin(), sets.end());
        sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
        const MovesFound unions = addUnions(all, &sets);
        if (unions != MovesFound::All) return unions;
        for (PartMask set : sets) moves->push_back(SetMove{dir, amount, set});
        if (context_.outOfWork()) return MovesFound::OutOfWork;
      }
    }
    return MovesFound::All;
  }

  // Unions of the closures, each set once (sorted and distinct on entry), as the voxel search
  // makes them: m independent closures have 2^m - 1 unions, so kMostSetsPerMove and the work
  // bound stop that, each union and its lookup counted. Few sets (the common case) are looked up
  // along the vector, many in an ordered set built once they are many.
  MovesFound addUnions(PartMask all, std::vector<PartMask>* sets) const {
    constexpr size_t kLookAlong = 32;
    std::set<PartMask> known;
    const auto isNew = [&](PartMask set) {
      if (known.empty() && sets->size() > kLookAlong) known.insert(sets->begin(), sets->end());
      if (known.empty()) {
        context_.addWork(1 + static_cast<int64_t>(sets->size()) / 8);
        return std::find(sets->begin(), sets->end(), set) == sets->end();
      }
      context_.addWork(1 + static_cast<int64_t>(std::log2(static_cast<double>(known.size()))));
      return known.insert(set).second;
    };
    for (size_t a = 0; a < sets->size(); ++a) {
      for (size_t b = 0; b < a; ++b) {
        const PartMask joined = (*sets)[a] | (*sets)[b];
        if (joined == all || !isNew(joined)) continue;
        if (sets->size() >= kMostSetsPerMove) return MovesFound::TooManySets;
        sets->push_back(joined);
      }
      if (context_.outOfWork()) return MovesFound::OutOfWork;
    }
    return MovesFound::All;
  }

  Position moved(const Position& from, const SetMove& move, int parent) const {
    const Vec3 step = scaled(context_.directions()[static_cast<size_t>(move.direction)], move.amount);
    Position next{from.offsets, parent, move.direction, move.amount, move.parts};
    for (int p = 0; p < k_; ++p) {
      Vec3& offset = next.offsets[static_cast<size_t>(p)];
      if ((move.parts >> p) & 1) offset = plus(offset, step);
      if (move.parts & 1) offset = minus(offset, step);  // keep the first part at the origin
    }
    return next;
  }

  SearchContext& context_;
  std::vector<int> parts_;
  int k_;
  std::vector<Position> positions_;
  std::unordered_map<std::vector<int64_t>, size_t, IntegersHash> known_;
  std::vector<std::vector<double>> gaps_;
  size_t separationPosition_ = 0;
  SetMove separation_;
  std::string limit_;
};

using search::levelOf;
using search::Separation;
using Pending = search::PendingSubAssembly<Vec3>;

// Records the separation of `current` and queues both sides (the side left in place first).
void separate(const Pending& current, const SubAssemblySearch& search, DisassemblyPlan* plan,
              std::vector<Separation>* tree, std::vector<Pending>* pending) {
  const std::vector<GroupMove> moves = search.plan();
  plan->moves.insert(plan->moves.end(), moves.begin(), moves.end());
  const int node = search::addSeparation(tree, static_cast<int>(moves.size()), current.parent, current.left);
  Pending sides[2];  // [0] left in place, [1] removed
  for (size_t p = 0; p < current.parts.size(); ++p) {
    Pending& side = sides[search.leaves(static_cast<int>(p)) ? 1 : 0];
    side.parts.push_back(current.parts[p]);
    side.offsets.push_back(search.offsetsAtSeparation()[p]);
  }
  for (int s : {1, 0}) {
    if (sides[s].parts.size() == 1) plan->removals.push_back({sides[s].parts[0], {}});
  }
  for (int s : {1, 0}) {
    if (sides[s].parts.size() < 2) continue;
    sides[s].parent = node;
    sides[s].left = s == 0;
    pending->push_back(std::move(sides[s]));
  }
}

}  // namespace

DisassemblyPlan searchGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                 const GroupSearchLimits& limits, GroupSearchStats* stats) {
  DisassemblyPlan plan;
  plan.singlePartPaths = false;
  plan.movesFollowRemovals = false;
  SearchContext context(meshes, geometry, limits);
  std::vector<Separation> tree;
  Pending whole;
  for (int part = 0; part < meshes.assembly.partCount(); ++part) {
    whole.parts.push_back(part);
    whole.offsets.push_back({0, 0, 0});
  }
  std::vector<Pending> pending;
  if (whole.parts.size() > 1) pending.push_back(whole);
  if (whole.parts.size() == 1) plan.removals.push_back({0, {}});
  while (!pending.empty()) {
    const Pending current = std::move(pending.back());
    pending.pop_back();
    if (current.parts.size() > kMostParts) {
      plan.unseparated.push_back(current.parts);
      plan.searchLimitReached = true;
      plan.limit = std::to_string(current.parts.size()) + " parts held together: the search takes at most " +
                   std::to_string(kMostParts);
      continue;
    }
    SubAssemblySearch search(context, current.parts);
    const SubAssemblySearch::Outcome outcome = search.run(current.offsets);
    plan.groupStates += static_cast<int64_t>(search.positions());
    if (outcome == SubAssemblySearch::Outcome::Separated) {
      separate(current, search, &plan, &tree, &pending);
      continue;
    }
    plan.unseparated.push_back(current.parts);
    if (outcome == SubAssemblySearch::Outcome::LimitReached) {
      plan.searchLimitReached = true;
      plan.limit = search.limit();
    }
  }
  for (const auto& together : plan.unseparated) plan.stuck.insert(plan.stuck.end(), together.begin(), together.end());
  std::sort(plan.stuck.begin(), plan.stuck.end());
  plan.complete = plan.unseparated.empty();
  plan.level = levelOf(tree);
  // Proven only where the distances tried are complete (the file's comment): else say why not.
  const bool proves = context.notProven().empty();
  const bool stoppedAtBound = plan.searchLimitReached;
  plan.levelMinimal = plan.complete && proves;
  if (!proves && !plan.searchLimitReached) {
    plan.limit = context.notProven();
    plan.searchLimitReached = !plan.complete;  // the parts left are not proven stuck
  }
  if (stats) *stats = GroupSearchStats{context.sweeps(), context.work(), proves, stoppedAtBound};
  return plan;
}

std::optional<DisassemblyPlan> planByGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                                std::string* note, std::string* limit) {
  GroupSearchStats stats;
  const DisassemblyPlan plan = searchGroupMoves(meshes, geometry, {}, &stats);
  const std::string what = "on no lattice: the search for moves of several parts (" + std::to_string(plan.groupStates) +
                           " positions, " + std::to_string(stats.pairSweeps) + " sweeps of part pairs) ";
  if (limit) *limit = plan.searchLimitReached ? plan.limit : "";
  if (!plan.complete) {
    *note = what + (stats.stoppedAtBound ? "stopped at its limit (" + plan.limit + ")"
                    : stats.proves ? "finds no plan either: every face is square to one of the three lines moved along and "
                                     "parallel to the others, so the parts left are stuck for moves along them"
                                   : "finds no plan, and the parts left are not proven stuck: " + plan.limit);
    return std::nullopt;
  }
  const std::string failure = sweepPlan(meshes, geometry, plan);
  if (!failure.empty()) {
    *note = what + "found a plan that fails the sweep: " + failure;
    if (limit) *limit = "the search's plan failed the sweep: " + failure;  // nothing is shown stuck
    return std::nullopt;
  }
  *note = what + "planned them, each move swept" + (plan.levelMinimal ? "" : " (the level not proven the fewest: " + plan.limit + ")");
  return plan;
}

}  // namespace desia::mesh
