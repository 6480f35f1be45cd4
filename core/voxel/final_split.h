// SPDX-License-Identifier: GPL-3.0-or-later
// The last split of the construction tree searched exhaustively (paper Section 4.1 requirements,
// with two parts left; see final_split.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "voxel/design_internals.h"

namespace desia::design {

// Work limits of one enumeration, in sets and exact checks (never time).
struct FinalSplitLimits {
  int64_t maxSets = 400000;     // connected candidate sets P_(N-1) visited
  int64_t maxExactChecks = 400; // sets passing the necessary conditions, checked exactly
  int maxSplits = 30;           // valid splits collected before stopping
};

struct FinalSplitStats {
  int64_t setsVisited = 0;
  int64_t exactChecks = 0;
  int splitsFound = 0;
  bool exhausted = true;  // every connected set of an allowed size was considered
};

// Splits of R_(i-1) (label `remainder`, at most 64 voxels) into a face-connected P_i of a size in
// `size` and a face-connected R_i such that A_i is interlocking with part 1 as key and P_i leaves
// [P_i, R_i] (acceptsSplit), up to the limits, in a fixed order, unranked (rankKey set, not
// sorted). With `lookAheadFinal` (three parts left), R_i must moreover admit such a split itself
// into the last two parts. Empty when R_(i-1) has more than 64 voxels (stats: not exhausted).
std::vector<Candidate> enumerateSplits(const VoxelGrid& grid, int remainder, const DesignContext& context,
                                       const SizeWindow& size, const FinalSplitLimits& limits, bool lookAheadFinal,
                                       FinalSplitStats* stats = nullptr);

}  // namespace desia::design
