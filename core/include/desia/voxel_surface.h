// SPDX-License-Identifier: GPL-3.0-or-later
// The surfaces of voxel parts as closed triangle meshes: what exports print, what viewers draw,
// and what frames build their joint pieces from.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/triangle_mesh.h"
#include "desia/voxel_grid.h"

namespace desia {

// The closed surface of part `partId`: one square per voxel face that does not touch the same
// part (faces against empty space, another part or the grid's border), as outward triangles, in
// grid coordinates times `voxelSize` (voxel (x, y, z) spans [x, x+1] x [y, y+1] x [z, z+1]).
// Every edge is used by exactly two triangles, in opposite directions, even where two voxels of
// the part touch only along an edge (see the definition for how), and where two voxels touch only
// at a corner each has its own copy of it (splitPinchedVertices): a 2-manifold. Throws BadInput
// for a part without voxels.
TriangleMesh partSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize = 1.0);

// partSurfaceMesh with every face against another part moved in by `clearance` (0 <= clearance <
// voxelSize / 2, else BadInput): the part as it is printed. Still closed, every edge in exactly two
// triangles in opposite directions; faces against empty space stay in place (see the definition).
TriangleMesh insetPartSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize, double clearance);

// Voxel indices of each part, in index order; entry k lists part k (entry 0 stays empty).
std::vector<std::vector<int64_t>> voxelsByPart(const VoxelGrid& grid);

// partSurfaceMesh for voxels already collected (all labelled partId, in index order).
TriangleMesh surfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels, double voxelSize);
// insetPartSurfaceMesh for voxels already collected, the clearance already checked (0 = as is).
TriangleMesh insetSurfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels,
                                  double voxelSize, double clearance);

// An axis-aligned box, [lo[k], hi[k]] along each axis k.
struct AxisAlignedBox {
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
};

// The closed surface of the union of `boxes`, one solid: the boxes' face planes cut space into
// cells (coordinates closer than `sameCoordinate` are one plane), a cell is solid when some box
// holds it, and the surface is built from the solid cells as partSurfaceMesh builds it from voxels
// (so boxes that overlap or touch leave no inner walls, and every edge is in exactly two
// triangles). Exact: no face is cut at a slant. Throws BadInput for no boxes or a box of no volume,
// TooLarge above 2^24 cells.
TriangleMesh surfaceOfBoxUnion(const std::vector<AxisAlignedBox>& boxes, double sameCoordinate);

// Throws BadInput (naming `source` and the value) unless 0 <= clearance < voxelSize / 2: at half a
// voxel, a part one voxel thick between two others would vanish.
void requireValidClearance(double voxelSize, double clearance, const std::string& source);

}  // namespace desia
