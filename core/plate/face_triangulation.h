// SPDX-License-Identifier: GPL-3.0-or-later
// Triangulating a planar face with holes (face_triangulation.cpp), for plate meshes.
#pragma once

#include <vector>

#include "desia/model.h"
#include "desia/plate.h"

namespace desia {

// Triangles of a planar face (loops[0] the outline, the rest holes) wound counter-clockwise about
// `outward`, appended to `mesh`; the loops' vertices are mesh vertices first, first + 1, ... in
// loop order. `flat`: twice a triangle's area below which a corner counts as flat (rounding).
void addFaceTriangles(const std::vector<Loop>& loops, const Vec3& outward, int first, TriangleMesh* mesh, double flat);

}  // namespace desia
