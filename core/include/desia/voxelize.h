// SPDX-License-Identifier: GPL-3.0-or-later
// Solid voxelization of a closed triangle mesh: the input shape of the voxel puzzle designer.
#pragma once

#include <string>

#include "desia/triangle_mesh.h"
#include "desia/voxel_grid.h"

namespace desia {

struct VoxelizeOptions {
  // Voxels along the longest side of the bounding box (1..1024); the other sides get
  // ceil(extent / voxel size) voxels, at least 1.
  int resolution = 32;
};

// One part (label 1) made of every voxel whose centre lies inside the mesh. Voxel (0,0,0) sits at
// the bounding-box minimum; mesh axes map to grid axes unchanged (+y is up in both). Checks the
// mesh first (checkClosedMesh), refuses grids outside VoxelLimits before allocating (TooLarge),
// and fails with BadInput when the result is empty or not face-connected. Deterministic: the same
// mesh gives the same grid, bit for bit, natively and in WebAssembly.
VoxelGrid voxelizeSolid(const TriangleMesh& mesh, const VoxelizeOptions& options,
                        const std::string& source = "<input>");

}  // namespace desia
