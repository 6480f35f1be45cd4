// SPDX-License-Identifier: GPL-3.0-or-later
// Exact checks of a candidate split, with the project's own tests (Section 4.1 requirements).
#pragma once

#include "desia/model.h"
#include "desia/voxel.h"
#include "voxel/design_internals.h"

namespace desia::design {

// After a split with the new part at `partLabel` and the new remainder at partLabel + 1: is the
// remainder one piece, is A_i interlocking with part 1 as key free along `keyDirection` only (for
// the key itself, with only [P1, R1]: P1 free along keyDirection only), and can the new part
// leave [P_i, R_i]?
// The whole-grid reference; SplitEvaluator (split_evaluation.h) gives the same answers per node.
bool acceptsSplit(const VoxelGrid& grid, int partLabel, const Int3& keyDirection);

// Requirement (ii) alone, on the assembly of the split grid (assemblyFromVoxels).
bool splitInterlocks(const Assembly& assembly, int partLabel, const Int3& keyDirection);

}  // namespace desia::design
