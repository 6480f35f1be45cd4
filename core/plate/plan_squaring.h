// SPDX-License-Identifier: GPL-3.0-or-later
// A plan's ways out and its jointed plates' contact normals, squared to each other where the
// rounding of a design's coordinates left them off square by tolerance::kSquareCosine or less.
//
// Designs given to a micrometre (plates-from-mesh writes 6 decimals) have faces meant to slide along
// a way out that are off square to it by 1e-9 to 1e-7 rad, and ways out (shared edges, mitre
// normals, tenon axes) off by as much. The blocking tests count a contact as blocking a direction
// when d·n > 1e-9 (README "Verdicts on computed normals"), so such a face holds a plate that slides
// along it in the design. A real block (more than that) is kept as it is, and the swept check
// of every plate judges the shapes themselves.
#pragma once

#include <vector>

#include "desia/model.h"
#include "desia/plate.h"

namespace desia {

// The plan's ways out (directions[k]: part k, the k-th to leave) and the assembly's contact
// normals squared to each other: each way out to the faces of its part against parts still in
// place that it is within tolerance::kSquareCosine of square to (a way out several parts share,
// once, to the faces of all of them), then each normal to every way out it is as close to square
// to. The result depends on the order of the parts, so the designer and `desia check` both give it
// the plates in removal order (verifyJointedPlates).
Assembly squaredPlanAssembly(Assembly assembly, std::vector<Vec3>* directions);

// The unit vector `v` made exactly square to every one of `others` it is within
// tolerance::kSquareCosine of square to (those furthest apart first; `v` itself when they span all
// of space). `first` (if given, one of `others`) leads: v is squared to it before any other.
Vec3 squaredToNearlySquare(const Vec3& v, const std::vector<Vec3>& others, const Vec3* first = nullptr);

// `normal` made exactly square to every way out it is within tolerance::kSquareCosine of square to.
Vec3 squaredToPlan(Vec3 normal, const std::vector<Vec3>& directions);

// The contacts of jointed plates (part k = the k-th to leave: position[plate]) as an assembly for
// the tests, its normals and the ways out squared to each other (squaredPlanAssembly).
Assembly jointedAssembly(const std::vector<PlateContact>& contacts, const std::vector<int>& position,
                         std::vector<Part> parts, std::vector<Vec3>* directions);

}  // namespace desia
