// SPDX-License-Identifier: GPL-3.0-or-later
// Graph design for P_i and R_i (paper Section 4.3, Fig. 7), exposed for the tests: per base DBG
// (one per axis) the kind of cycle that keeps it strongly connected, and its realization as voxels
// forced into P_i or R_i.
#pragma once

#include <random>
#include <vector>

#include "desia/model.h"
#include "voxel/design_internals.h"

namespace desia::design {

enum class AxisDesign { TwoInternal, OneInternalPartToRemainder, OneInternalRemainderToPart, NoInternal };

// An inherited contact along +e between R_(i-1) and an earlier part.
struct ExternalContact {
  int64_t voxel;  // the R_(i-1) voxel of the contact
  int part;       // the earlier part's label
};

// Which earlier parts reach which in G(+e) without passing R_(i-1) (a part reaches itself; labels
// 1 .. R - 1). Each row is searched on first use: a node asks about the few parts near its seeds,
// while all rows cost one search of the graph per part (quadratic in the parts: most of a node's
// time late in a 1500-part cube). The graph must outlive it.
class PartReachability {
 public:
  PartReachability() = default;
  PartReachability(const DirectedGraph& graph, int remainder);
  bool operator()(int from, int to) const;

 private:
  const DirectedGraph* graph_ = nullptr;
  int remainder_ = 0;
  mutable std::vector<std::vector<bool>> rows_;  // by `from`; empty until first asked
};

// Everything about one axis e of A_(i-1) that graph design needs.
struct AxisInfo {
  std::vector<ExternalContact> remainderBlockedBy;  // R voxel v, part at v+e: edge R -> part in G(+e)
  std::vector<ExternalContact> blockingPart;        // R voxel w, part at w-e: edge part -> R in G(+e)
  std::vector<int64_t> pairForward;                 // R voxel a with a+e in R
  std::vector<int64_t> pairBackward;                // R voxel a with a-e in R
  std::vector<int64_t> pairBoth;                    // both
  PartReachability reaches;                         // (from, to) over earlier parts, avoiding R
  // Position of each voxel in the lists above (-1: absent), so picks near a seed can search the
  // neighbourhood instead of whole lists.
  std::vector<int32_t> remainderBlockedByIndex, blockingPartIndex, pairForwardIndex, pairBackwardIndex, pairBothIndex;
};

// Contacts, blocking pairs and reachability of one axis of A_(i-1) whose remainder has label
// `remainder`; in recursive mode only P_(i-1) may close cycles (Fig. 11).
AxisInfo describeAxis(const VoxelGrid& grid, int remainder, int axis, const DirectedGraph& graph, bool recursive);

// Designs allowed on `axis` when P_i leaves along `removal`: no internal edge may block it.
std::vector<AxisDesign> allowedDesigns(int axis, const Int3& removal);

// Forces the voxels that realize `design` on `axis` near `seed`; false when the geometry cannot.
bool realizeAxis(AxisDesign design, int axis, const AxisInfo& info, const VoxelGrid& grid, const Int3& seed,
                 std::mt19937_64& random, PartBuilder& builder);

}  // namespace desia::design
