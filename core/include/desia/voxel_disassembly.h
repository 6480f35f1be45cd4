// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly of voxel assemblies: each part's collision-free path out, found by sweeping along the
// axes and, where no straight path exists, by a breadth-first search over unit axis steps.
#pragma once

#include <cstdint>
#include <vector>

#include "desia/contact_check.h"
#include "desia/voxel_disassembly.h"
#include "desia/voxel_grid.h"

namespace desia {

struct VoxelDisassemblyOptions {
  // Bounds on the breadth-first search over unit axis steps, per attempted removal: visited
  // offsets, and voxel collision tests made (sweeps included; a test of a placement stops at its
  // first colliding voxel), so a pathological input (a part in a huge cavity) cannot keep the
  // search busy for minutes.
  int maxSearchStates = 2'000'000;
  int64_t maxVoxelTests = 200'000'000;
  // Voxel collision tests for a whole plan (all searches together), the backstop against many
  // parts each needing a long search. When it runs out the plan stops: searchLimitReached, and
  // every part still in place is listed in `stuck` without being proven stuck.
  int64_t maxTotalVoxelTests = 1'000'000'000;
  // The complete disassembler (moves of several parts at once, searched breadth-first, as
  // BurrTools does), run when the single-part plan fails or needs a bent path. Its bounds, per
  // sub-assembly searched: positions kept, and the memory they take (about 1 GiB by default).
  bool groupMoves = true;
  int64_t maxGroupStates = 2'000'000;
  int64_t maxGroupBytes = int64_t{1} << 30;
  int maxGroupParts = 1000;  // sub-assemblies of more parts are not searched (said in `limit`)
  // Operations of that search for the whole plan (part-pair tests and unions of sets): its time
  // bound, about a few seconds natively. Many parts that move independently make 2^m moves.
  int64_t maxGroupWork = 4'000'000'000;
};

// Voxel assemblies: first the single-part plan: removals are collision-free translations to
// infinity checked by sweeping; when no straight path exists, a breadth-first search over unit
// axis steps finds a bent path (as the original code does). When that plan fails or bends, the
// complete disassembler (group_disassembly.h) searches moves of several parts for the fewest
// moves (the level); a straight single-part plan is already level 1 and kept as it is. Each round removes the lowest-id part that can leave, which is complete:
// removing a part never blocks another, so greedy removal finds a sequence whenever one exists.
// A part whose search failed is searched again only when a removal could change that search
// (it removed a part the search collided with, or shrank the box of the other parts); the plan is
// the same as searching every part every round, at about one search per part and removal nearby.
DisassemblyPlan planVoxelDisassembly(const VoxelGrid& grid, const Assembly& assembly,
                                     const VoxelDisassemblyOptions& options = {});

// Can the part with `label` leave `occupancy` (every other non-zero voxel is an obstacle)? Fills
// `path` on success. `limitReached` (optional) tells whether the search stopped at its limits
// (maxSearchStates, and the smaller of maxVoxelTests and maxTotalVoxelTests).
bool findVoxelRemovalPath(const VoxelGrid& occupancy, int label, std::vector<Move>* path,
                          const VoxelDisassemblyOptions& options = {}, bool* limitReached = nullptr);

// The project's check of a voxel assembly (paper Sections 3 and 4.1 (iii)): the interlocking tests
// on the grid's contacts, and its disassembly planned on the voxels (planVoxelDisassembly).
CheckReport checkVoxelAssembly(const VoxelGrid& grid, const CheckOptions& options = {},
                               const VoxelDisassemblyOptions& disassembly = {});

}  // namespace desia
