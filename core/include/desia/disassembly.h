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

// Assemblies known only by their contacts: a part is removable when it is locally free along a
// base direction in the DBG of the remaining parts (no sweep is possible without geometry).
DisassemblyPlan planContactDisassembly(const Assembly& assembly);

}  // namespace desia
