// SPDX-License-Identifier: GPL-3.0-or-later
// Lower level entry of the voxel removal search (voxel_disassembly.cpp) for callers that already
// know the part's voxels and the box of the other parts (the designer checks every candidate's
// part against the same [P_i, R_i] grid, Section 4.1 requirement iii).
#pragma once

#include <vector>

#include "desia/voxel.h"

namespace desia {

// findVoxelRemovalPath(occupancy, label, path) without its scan of the grid: `partVoxels` are the
// voxels with `label` in index order, [obstaclesMin, obstaclesMax] the bounding box of the other
// non-zero voxels (obstaclesMin.x > obstaclesMax.x when there are none). Same answer and path.
bool findVoxelRemovalPathOf(const VoxelGrid& occupancy, int label, const std::vector<int64_t>& partVoxels,
                            const Int3& obstaclesMin, const Int3& obstaclesMax, std::vector<Move>* path);

}  // namespace desia
