// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning (paper Section 3.3): a sequence of single-part removals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/assembly.h"

namespace desia {

// One straight translation of `steps` units along `direction` (a unit axis for voxels).
struct Move {
  Vec3 direction{0, 0, 0};
  int steps = 0;
  double length = 0;  // mesh plans: a finite move's length in mm (steps = 0); 0 otherwise
};

struct Removal {
  int part = -1;           // internal index
  std::vector<Move> path;  // the last move takes the part clear of the remaining parts
};

// One move of a set of parts together (the unit BurrTools counts): a translation by `steps` whole
// units along the unit axis `direction`, or, when `out`, to infinity along it, after which the
// moved parts form a sub-assembly of their own and each side is taken apart on its own.
struct GroupMove {
  std::vector<int> parts;  // internal indices, ascending
  Vec3 direction{0, 0, 0};
  int steps = 0;           // 0 when `out`
  bool out = false;
};

struct DisassemblyPlan {
  bool complete = false;  // all parts removed (the last part stays in place, empty path)
  // `removals` lists single-part removals in order, each with its own path (the last part: none).
  // A plan that needed parts moved together (voxel plans only) lists in `removals` the order in
  // which parts come free, with empty paths, and sets singlePartPaths = false: `moves` is the plan.
  std::vector<Removal> removals;
  bool singlePartPaths = true;
  // Voxel plans: every move in order, separations included (`out`), and the disassembly level in
  // BurrTools' notation: moves of the first separation (the final move out included), then of
  // the separations below it, in pre-order, where a sub-assembly needs more than one move for
  // one of its separations. levelMinimal: found by breadth-first search, so no plan has fewer
  // moves before the first separation, and each later entry is the fewest for its sub-assembly
  // as the separations before it left it (as BurrTools counts); false when the level is that of
  // a plan found otherwise.
  std::vector<GroupMove> moves;
  std::vector<int> level;
  bool levelMinimal = false;
  bool movesFollowRemovals = true;  // `moves` are the removals' paths, else a plan of their own
  // Parts still together when the plan stopped, per sub-assembly (`stuck` lists them all).
  std::vector<std::vector<int>> unseparated;
  std::string limit;  // which search limit stopped the plan, in words ("" = none)
  std::vector<int> stuck;           // parts left when no further removal exists (complete == false)
  bool searchLimitReached = false;  // some search gave up at its work limit: "stuck" is not proven
  // Work done (voxel plans only): part searches run (cached failures are not run again) and voxel
  // collision tests made, for tests and benchmarks that pin down how the planner scales.
  int64_t searches = 0;
  int64_t voxelTests = 0;
  int64_t groupStates = 0;  // positions visited by the search for moves of several parts
};

// Assemblies known only by their contacts: a part is removable when it is locally free along a
// base direction in the DBG of the remaining parts (no sweep is possible without geometry).
DisassemblyPlan planContactDisassembly(const Assembly& assembly);

}  // namespace desia
