// SPDX-License-Identifier: GPL-3.0-or-later
// The checks and the ranking of the candidates of one construction-tree node (Section 4.1
// requirements, Section 4.3 "ranking"), with the work that does not depend on the candidate done
// once per node: a candidate then costs the neighbourhood of its part, not the grid. Every answer
// is the one of the whole-grid functions (acceptsSplit, rankingKey) on the split grid, to the bit.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "desia/model.h"
#include "desia/voxel.h"
#include "voxel/design_internals.h"

namespace desia::design {

// Accessibility (design_internals.h) of a set R and, for a part P taken out of it, the sum of the
// accessibility of R \ P, computed only where P changes it: a_k changes within k + 1 steps of P
// (through R \ P), the rest is read from R's own passes. The sum adds the same values in the same
// (index) order as the whole recomputation, so it is the same double.
class IncrementalAccessibility {
 public:
  IncrementalAccessibility(const VoxelGrid& grid, int label);
  // accessibility(grid, label): a value per grid voxel (0 outside the set).
  const std::vector<double>& values() const { return passes_[3]; }
  // The sum over R \ P of accessibility(grid with P taken out of R, label), in index order;
  // `part` lists voxels of R, sorted.
  double sumWithout(const std::vector<int64_t>& part);

 private:
  bool inRest(int64_t v) const { return grid_.labelAt(v) == label_ && !taken_[static_cast<size_t>(v)]; }
  void collectZone(const std::vector<int64_t>& part);
  void recomputeZone();

  const VoxelGrid& grid_;
  int label_;
  GridSteps steps_;
  std::vector<int64_t> voxels_;                // the set, in index order
  std::array<std::vector<double>, 4> passes_;  // a_0 .. a_3 of the set
  // Scratch of one call, cleared after it: P's voxels, the zone (distance 1..4 from P within
  // R \ P; zoneDistance_ 0 elsewhere) and its new values per pass.
  std::vector<uint8_t> taken_, zoneDistance_;
  std::vector<int64_t> zone_;  // by growing distance
  std::array<std::vector<double>, 4> changed_;
};

// The contacts of A_i = A_(i-1) with R_(i-1) split into P_i (label r) and R_i (label r + 1), as
// assemblyFromVoxels would list them for the split grid: the contacts between earlier parts are
// kept, the faces of R_(i-1) with each earlier part are counted once per node, and a candidate
// only counts the faces of its own part.
class SplitAssembly {
 public:
  SplitAssembly(const VoxelGrid& grid, int remainderLabel);
  // assemblyFromVoxels of the grid with `part` (sorted voxels of R_(i-1), R_i non-empty) split off.
  Assembly assemblyAfter(const std::vector<int64_t>& part);

 private:
  using Faces = std::array<int, 3>;  // per axis
  void countPartFaces(const std::vector<int64_t>& part);

  const VoxelGrid& grid_;
  int remainder_;
  GridSteps steps_;
  std::vector<Contact> kept_;          // contacts between earlier parts, in order
  std::vector<size_t> keptEnd_;        // per earlier part a: end of its contacts in kept_
  std::vector<Faces> belowRemainder_;  // per earlier part q: faces with q on the -axis side of R
  std::vector<Faces> aboveRemainder_;  // per earlier part q: faces with q on the +axis side of R
  // Scratch of one call: the same counts for P (belowPart_[q]: P on the -axis side of q,
  // abovePart_[q]: on its +axis side), and P's faces with R_i. `partMark_` flags P's voxels.
  std::vector<Faces> belowPart_, abovePart_;
  Faces partBelowRest_{}, restBelowPart_{};
  std::vector<uint8_t> partMark_;
};

// Is R \ P one face-connected piece, for a face-connected set R (label `label`) and P a sorted
// list of its voxels? Every piece of R \ P touches P (R is connected), so it is enough that the
// voxels of R \ P next to P lie in one piece: regions grown from each of them in lockstep merge
// (union-find) or one of them runs out first. The cost follows the neighbourhood of P where the
// rest stays connected around it, not the size of R.
class RemainderConnectivity {
 public:
  RemainderConnectivity(const VoxelGrid& grid, int label);
  bool connectedWithout(const std::vector<int64_t>& part);
  // The pieces P cuts off R: the voxels of R \ P outside one piece that stays R_i (none when R \ P
  // is one piece), if they number at most `maxVoxels`; nullopt when they are more, or when P takes
  // all of R. The same lockstep growth: the pieces that run out first are found whole and cut
  // off, the last one still growing stays, so the cost follows the small pieces, not R.
  std::optional<std::vector<int64_t>> piecesCutOff(const std::vector<int64_t>& part, size_t maxVoxels);

 private:
  int find(int region);
  // Grows regions of R \ P from P's neighbours in lockstep, merging those that meet, until at
  // most `stopAtGrowing` regions are still growing or every region has run out. Fills queue_
  // (every voxel reached) and marks owner_; the caller clears both with clear().
  void growRegions(const std::vector<int64_t>& part, int stopAtGrowing, size_t maxFinished, size_t* finishedVoxels);
  void clear(const std::vector<int64_t>& part);

  const VoxelGrid& grid_;
  int label_;
  int64_t size_ = 0;
  GridSteps steps_;
  std::vector<uint8_t> taken_;
  std::vector<int32_t> owner_;  // region of a reached voxel, -1 unreached; cleared after a call
  std::vector<int> parent_, pending_, regionSize_;
  std::vector<uint8_t> finished_;  // per region: ran out (a whole piece of R \ P)
  std::vector<int64_t> queue_;  // every reached voxel, in lockstep order
  int growing_ = 0;             // regions (roots) still growing
};

// Is a sorted voxel list face-connected (and non-empty)? Cost follows the list.
bool isListFaceConnected(const GridSteps& steps, const std::vector<int64_t>& voxels);

// The exact checks and the ranking key of every candidate of one node whose remainder has label
// `remainderLabel` (the largest label of `grid`), as acceptsSplit and rankingKey give them on the
// split grid. Falls back to those whole-grid functions when the node is not of that form (R not
// the last label or not one piece, as the tests may build).
class SplitEvaluator {
 public:
  SplitEvaluator(const VoxelGrid& grid, int remainderLabel, const Int3& keyDirection, CandidateRanking ranking);
  // acceptsSplit(grid with `candidate` applied, remainderLabel, keyDirection)
  bool accepts(const Candidate& candidate);
  // The pieces of R_(i-1) that `part` (sorted) would cut off R_i, when they are at most
  // `maxVoxels` (RemainderConnectivity::piecesCutOff); none otherwise, or when R_i stays whole.
  std::vector<int64_t> piecesCutOff(const std::vector<int64_t>& part, size_t maxVoxels);
  // rankingKey(grid with `candidate` applied, remainderLabel, remainderLabel + 1, ranking)
  double rankKey(const Candidate& candidate);
  // accessibility(grid, remainderLabel)
  const std::vector<double>& access() const { return accessibility_.values(); }

 private:
  bool partLeaves(const std::vector<int64_t>& part);

  const VoxelGrid& grid_;
  int remainder_;
  Int3 keyDirection_;
  CandidateRanking ranking_;
  bool local_ = false;  // the node has the form the local checks need
  GridSteps steps_;
  IncrementalAccessibility accessibility_;
  SplitAssembly assembly_;
  RemainderConnectivity connectivity_;
  // [P_i, R_i] alone, R_(i-1) labelled r + 1: P's voxels are set per candidate.
  VoxelGrid pair_;
  std::array<std::vector<int>, 3> slabs_;  // R_(i-1)'s voxels per x, y and z slab (R_i's box)
  std::optional<VoxelGrid> work_;          // the fallback's split grid (only where the node needs it)
};

}  // namespace desia::design
