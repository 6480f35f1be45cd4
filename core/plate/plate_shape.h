// SPDX-License-Identifier: GPL-3.0-or-later
// What a plate's shape is, shared by the contacts (plate_geometry) and the joint cuts
// (plate_joints): its thickness, whether it is a prism (its second face its first one lifted
// along its axis) or has mitred sides, and where it has its whole thickness.
#pragma once

#include <polyclipping/clipper.hpp>

#include <vector>

#include "desia/plate.h"

namespace desia {

// The distance between the plate's two faces.
double plateThickness(const Plate& plate);

// The second face is the first lifted along the thickness axis (no mitred side).
bool isPrism(const Plate& plate);

// Where the plate has its whole thickness (ctIntersection: both faces seen along its axis) or any
// of it (ctUnion), as loops in its first face's plane. A prism: its first face.
std::vector<Loop> faceRegion(const Plate& plate, ClipperLib::ClipType operation);

// The prism where the plate has its whole thickness: inside the plate, so an overlap of two such
// cores is an overlap of the plates (empty loops when the mitres leave no such region).
Plate corePrism(const Plate& plate);

}  // namespace desia
