// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning (paper Section 3.3): a sequence of single-part removals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/voxel_grid.h"

namespace desia {

// One straight translation of `steps` units along `direction` (a unit axis for voxels).
struct Move {
  Vec3 direction{0, 0, 0};
  int steps = 0;
};

struct Removal {
  int part = -1;           // internal index
  std::vector<Move> path;  // the last move takes the part clear of the remaining parts
};

struct DisassemblyPlan {
  bool complete = false;  // all parts removed (the last part stays in place, empty path)
  std::vector<Removal> removals;
  std::vector<int> stuck;           // parts left when no further removal exists (complete == false)
  bool searchLimitReached = false;  // some search gave up at its work limit: "stuck" is not proven
  // Work done (voxel plans only): part searches run (cached failures are not run again) and voxel
  // collision tests made, for tests and benchmarks that pin down how the planner scales.
  int64_t searches = 0;
  int64_t voxelTests = 0;
};

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
};

// Voxel assemblies: removals are collision-free translations to infinity checked by sweeping; when
// no straight path exists, a breadth-first search over unit axis steps finds a bent path (as the
// original code does). Each round removes the lowest-id part that can leave, which is complete:
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

// Assemblies known only by their contacts: a part is removable when it is locally free along a
// base direction in the DBG of the remaining parts (no sweep is possible without geometry).
DisassemblyPlan planContactDisassembly(const Assembly& assembly);

}  // namespace desia
