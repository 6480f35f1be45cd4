// SPDX-License-Identifier: GPL-3.0-or-later
// Contact normals snapped to the design's directions, once, the same way for the designer and
// `desia check`: designs turned by any rotation or written to 6 decimals (as CAD tools write
// them) give faces meant to be parallel normals 1e-9 to 1e-7 rad apart, and faces meant to be
// square 1e-9 to 1e-7 rad off square. The blocking tests count a contact as blocking a direction
// when d·n > 1e-9 (README "Verdicts on computed normals"), so that noise makes the paper's base
// directions (section 4.1: one per pair of contact normals) multiply (the MITRED BOX turned and
// rounded: 72 instead of 7) and makes faces block what slides along them.
#pragma once

#include <vector>

#include "desia/plate.h"

namespace desia {

// The angle (rad) within which normals, up to sign, are one direction of the design and pairs
// are square: tolerance::kComputedDirectionRad for geometry desia computed (the designer's jointed
// plates, results it wrote at full precision, contacts), tolerance::kDrawnDirectionRad for designs
// drawn elsewhere. Real design angles are degrees apart (the dovetail's 1-in-6 slope is 0.17 rad,
// the closest plates of the LIZARD example 0.09 rad); a larger angle for computed geometry would
// merge the faces of jointed plates that differ for real, and they would no longer verify.

// The unit vectors with every group of parallel ones (single linkage within `angle`, up to sign)
// replaced by one vector (their mean, signs kept), then every pair of those within `angle` of
// square made square to rounding (tolerance::kSquaredCosine). The result does not depend on the
// order of `normals`: groups are found on all pairs, means summed in sorted order and the squaring
// is symmetric (all pairs turned at once, repeated until square).
std::vector<Vec3> snappedDirections(const std::vector<Vec3>& normals, double angle);

// The contacts' normals snapped with snappedDirections within tolerance::kComputedDirectionRad (crossings
// have no normal and keep theirs).
void snapContactNormals(std::vector<PlateContact>* contacts);

}  // namespace desia
