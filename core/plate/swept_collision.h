// SPDX-License-Identifier: GPL-3.0-or-later
// The swept collision test of plate plans (paper Section 5.2: each plate must leave along its
// direction past the plates still in place): whether a solid moved along a direction by any
// distance passes through another.
#pragma once

#include "desia/triangle_mesh.h"
#include "desia/plate.h"

namespace desia {

// True when `mover`, moved along the unit direction d by any distance, would pass through
// `obstacle` (their interiors meet). Exact for the plates' polyhedra: two surface triangles whose
// shadows along d overlap with positive area, with the obstacle's triangle ahead, mean a collision.
bool plateCollidesAlong(const Plate& mover, const Plate& obstacle, const Vec3& d, double tolerance);
// The same for closed meshes (plateMesh of each plate, made once when many pairs are tested).
bool meshCollidesAlong(const TriangleMesh& mover, const TriangleMesh& obstacle, const Vec3& d, double tolerance);

}  // namespace desia
