// SPDX-License-Identifier: GPL-3.0-or-later
// Pieces shared by the steps of the voxel designer (key generation, P_i/R_i generation, search).
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "desia/voxel.h"

namespace desia::design {

constexpr std::array<Int3, 6> kAxisSteps{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};

inline Int3 plus(const Int3& a, const Int3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Int3 minus(const Int3& a, const Int3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline int manhattan(const Int3& a, const Int3& b) { return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z); }
inline Int3 axisStep(int axis) { return kAxisSteps[2 * axis]; }  // +x, +y, +z

// The voxel at `index + step`, or -1 outside the grid. Inline arithmetic (not
// VoxelGrid::coordinates, out of line): this is the designer's innermost call, in every
// path search, column walk and frontier of part generation.
inline int64_t neighbourIndex(const VoxelGrid& grid, int64_t index, const Int3& step) {
  const int64_t nx = grid.nx(), ny = grid.ny();
  const int64_t x = index % nx + step.x, y = (index / nx) % ny + step.y, z = index / (nx * ny) + step.z;
  if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= grid.nz()) return -1;
  return x + nx * (y + ny * z);
}

// The six face neighbours of every voxel of one grid, without division: neighbourIndex divides
// three times per call, and the path searches and flood fills of part generation (Section 4.3)
// visit millions of neighbours per part on a 35^3 grid. neighbour(i, s) == neighbourIndex(grid,
// i, kAxisSteps[s]) for every voxel and step.
class GridSteps {
 public:
  explicit GridSteps(const VoxelGrid& grid);
  int64_t neighbour(int64_t index, int step) const {
    return (inside_[static_cast<size_t>(index)] >> step) & 1 ? index + offset_[step] : -1;
  }

 private:
  std::array<int64_t, 6> offset_{};
  std::vector<uint8_t> inside_;  // bit s: the neighbour along kAxisSteps[s] is in the grid
};

// A candidate child of a construction-tree node: the voxels that leave R_i to form the new part.
struct Candidate {
  std::vector<int64_t> partVoxels;  // sorted
  double rankKey = 0;               // smaller ranks first
};

// The shared context of one design run.
struct DesignContext {
  const VoxelDesignOptions& options;
  std::vector<int> groupOf;  // voxel -> group index or -1
  std::vector<std::vector<int64_t>> groups;
  int64_t shapeVoxels = 0;
  std::mt19937_64 random;
};

// Accessibility of Song et al. 2012 (original-code-notes B4): a0 = number of 6-neighbours in the
// set, then three Jacobi passes a_k = a_(k-1) + 0.1^k * sum of the neighbours' a_(k-1). Low values
// are exposed voxels; a high sum means a compact set. Returns a value per grid voxel (0 outside).
std::vector<double> accessibility(const VoxelGrid& grid, int label);

// Is the set of voxels with `label` one face-connected piece (and non-empty)?
bool isFaceConnected(const VoxelGrid& grid, int label);

// How many of `voxels` lie on the shape's surface: a face neighbour is empty (label 0) or beyond
// the grid (`steps` are the grid's).
int shapeSurfaceVoxelCount(const VoxelGrid& grid, const GridSteps& steps, const std::vector<int64_t>& voxels);

// The weight of a part's shape-surface voxel in the compactness ranking, against the remainder's
// accessibility sum (rankingKey; see design_geometry.cpp for why and what it changed).
constexpr double kShapeSurfaceWeight = 3.0;

// Ranking key of a candidate (smaller first) for the chosen ranking; `grid` is the state after
// the split, `partLabel` the new part and `remainderLabel` the new remainder. Compactness: minus
// the remainder's accessibility sum, minus kShapeSurfaceWeight per shape-surface voxel of the part.
double rankingKey(const VoxelGrid& grid, int partLabel, int remainderLabel, CandidateRanking ranking);

// Splits the remainder: the candidate's voxels keep `remainderLabel` (they become the new part
// P_i), every other remainder voxel gets remainderLabel + 1 (the new R_i). Undo restores.
void applyCandidate(VoxelGrid& grid, int remainderLabel, const Candidate& candidate);
void undoCandidate(VoxelGrid& grid, int remainderLabel);

// Builds a new part inside the remainder (label r): forced voxels, shortest-path connection,
// removal along one axis direction, growth to a size. Shared by key and part generation.
class PartBuilder {
 public:
  PartBuilder(const VoxelGrid& grid, int remainderLabel, const DesignContext& context, const std::vector<double>& access);

  // Forces a voxel (and its appearance group) into the part / into the remainder. False on a
  // conflict (the voxel is outside the remainder, or already forced the other way).
  // With a removal direction set (propagateAlong), each force also settles what it implies: the
  // part must leave along it with nothing of the remainder right in front (Section 4.3 iv), so
  // forcing a part voxel takes the remainder run in front of it into the part, and forcing a
  // remainder voxel keeps the remainder run behind it in the remainder. A conflict then shows at
  // the force that causes it (false), not later when the path is cleared.
  bool forcePart(int64_t voxel);
  bool forceRemainder(int64_t voxel);
  // Sets the removal direction whose consequences forcePart / forceRemainder propagate (see
  // above); in effect until reset() or the next call. Not journaled: set it right after reset().
  void propagateAlong(const Int3& direction) {
    propagate_ = true;
    removal_ = direction;
  }
  // Connects all forced part voxels by shortest paths through unforced remainder voxels.
  bool connect();
  // Look-ahead for connect(): can the forced part voxels still be joined, i.e. do they lie in one
  // face-connected piece of the voxels that may still go to the part? connect() succeeds exactly
  // then (its paths only turn such voxels into part voxels), so a design that fails here is dead
  // and the next one can be tried at once. Stops as soon as all are reached.
  bool forcedPartConnectable();
  // Absorbs, from every part voxel, the remainder voxels along `direction` up to the first voxel
  // that is not in the remainder, so no remainder voxel sits right in front of the part. False
  // when that would take a voxel forced into the remainder.
  bool clearPathAlong(const Int3& direction);
  // Grows the part by columns along `direction` (a voxel plus what clearPathAlong would then
  // absorb), least accessible first, until it has at least `minSize` voxels; false if it cannot or
  // ends above `maxSize`.
  bool growTo(int minSize, int maxSize, const Int3& direction, std::mt19937_64& random);
  // Takes `voxels` (remainder voxels) into the part, with what clearPathAlong(direction) then
  // absorbs; false when one of them is forced into the remainder.
  bool absorb(const std::vector<int64_t>& voxels, const Int3& direction);

  // May the voxel still go to the part / stay in the remainder?
  bool canBePart(int64_t voxel) const { return state_[voxel] == kFree || state_[voxel] == kPart; }
  bool canBeRemainder(int64_t voxel) const { return state_[voxel] == kFree || state_[voxel] == kForcedRemainder; }

  // Saves and restores the builder's choices, to try another design after a failed one. Changes
  // are journaled, so both cost what the attempt touched, not the size of the grid.
  struct Snapshot {
    size_t journal = 0, part = 0, forcedPart = 0;
  };
  Snapshot snapshot() const { return {journal_.size(), part_.size(), forcedPart_.size()}; }
  void restore(const Snapshot& snapshot);
  // Back to the state right after construction (for the next attempt at the same node).
  void reset() {
    restore(Snapshot{});
    propagate_ = false;
  }

  const std::vector<int64_t>& partVoxels() const { return part_; }
  std::vector<int64_t> sortedPartVoxels() const;
  int size() const { return static_cast<int>(part_.size()); }

 private:
  enum : uint8_t { kOther = 0, kFree = 1, kPart = 2, kForcedRemainder = 3 };
  bool addToPart(int64_t voxel);  // with its group; false if it meets a forced-remainder voxel
  void setState(int64_t voxel, uint8_t state) {
    journal_.push_back({voxel, state_[voxel]});
    state_[voxel] = state;
  }
  std::vector<int64_t> columnFrom(int64_t voxel, const Int3& direction) const;
  // Absorbs the remainder runs in front of part_[first..] along `direction` (and of what that
  // adds); false when one holds a forced-remainder voxel.
  bool clearPathFrom(size_t first, const Int3& direction);

  const VoxelGrid& grid_;
  const DesignContext& context_;
  const std::vector<double>& access_;
  GridSteps steps_;
  std::vector<uint8_t> state_;
  std::vector<int64_t> part_;
  std::vector<int64_t> forcedPart_;
  std::vector<std::pair<int64_t, uint8_t>> journal_;  // (voxel, previous state), in order
  bool propagate_ = false;
  Int3 removal_{0, 0, 0};
  // Best-first search over the voxels the part may take (free or part), from `sources` towards
  // `toward` (bucket queue on distance + Manhattan distance to it), until a voxel `isGoal` accepts
  // leaves the queue: returns its distance from the sources, or -1 when none is reachable. With
  // the single goal `toward` it is A* with a consistent heuristic, so the distance is exact.
  // `visited` receives every voxel reached (their bestG_ entries, to be cleared by the caller).
  template <typename IsGoal>
  int32_t bestFirst(const std::vector<int64_t>& sources, const Int3& toward, IsGoal isGoal, std::vector<int64_t>* visited);
  void clearBestG(const std::vector<int64_t>& visited) {
    for (int64_t v : visited) bestG_[v] = -1;
  }

  // Scratch buffers of connect(), grid-sized once; entries used are cleared after each use.
  std::vector<int64_t> cameFrom_;
  std::vector<bool> connected_;
  std::vector<int32_t> bestG_;  // of bestFirst: the best distance pushed, -1 unreached
};

// Key generation (Section 4.2): candidates {A_1} for [P1, R1] with P1 free along the key direction
// only, ranked, at most options.candidates of them.
std::vector<Candidate> generateKeyCandidates(const VoxelGrid& grid, DesignContext& context, int targetSize);

// P_i / R_i generation (Section 4.3): candidates {A_i} from A_(i-1) whose remainder has label
// `remainderLabel` (= i); each keeps the assembly interlocking with part 1 as key and P_i
// removable from [P_i, R_i].
std::vector<Candidate> generatePartCandidates(const VoxelGrid& grid, int remainderLabel, DesignContext& context,
                                              int targetSize, int partsStillToPlace);

// The target size of the next part: what is left shared evenly over the parts still to make.
int targetPartSize(int64_t remainderVoxels, int partsLeftIncludingRemainder);

// A range of part sizes [min, max] in voxels; empty when min > max.
struct SizeWindow {
  int min = 0;
  int max = 0;
  bool empty() const { return min > max; }
};

// The part size bounds of a run: options.minPartSize and options.maxPartSize, filled in by the
// designer (effective options), so every part, the last remainder included, lies within them.
PartSizeBounds partSizeBounds(const VoxelDesignOptions& options);

// Look-ahead on sizes: the sizes the next part may take within `bounds` such that the remainder
// it leaves can still be split into the parts still to make (partsLeftIncludingRemainder - 1 of
// them), each within `bounds`: remainder - size between (partsLeft - 1) * min and
// (partsLeft - 1) * max. A part outside it is a dead branch however the rest is designed.
SizeWindow partSizeWindow(int64_t remainderVoxels, int partsLeftIncludingRemainder, const PartSizeBounds& bounds);

// A heuristic window (e.g. the target size +- a quarter) moved into the sizes `allowed` permits:
// each end clamped into `allowed`, so the heuristic decides wherever the bounds leave it room.
SizeWindow clampInto(const SizeWindow& heuristic, const SizeWindow& allowed);

}  // namespace desia::design
