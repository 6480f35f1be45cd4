// SPDX-License-Identifier: GPL-3.0-or-later
// Plates that pass through each other (paper Fig. 2, middle: crossings to be halved) or overlap
// where nothing explains it, as the contact computation finds and refuses them.
#pragma once

#include <optional>
#include <vector>

#include "desia/plate.h"

namespace desia {
namespace geometry {

// Plates p and q crossing through each other: their solids each fill the other's slab over a
// common stretch of the line where their planes meet (the crossing, as a contact); nothing when
// they do not cross. Perpendicular prisms that overlap in part are refused (BadInput); other
// pairs are slantedCrossing's.
std::optional<PlateContact> plateCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance);

// Plates p and q crossing at any angle (prisms, or with mitred sides judged by their cores), or
// nothing: never throws (the overlap checks below judge what is not a crossing). plateCrossing
// asks it for every pair but perpendicular prisms.
std::optional<PlateContact> slantedCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance);

// Perpendicular plates with mitred sides (which cannot cross) must not share volume; plates
// neither parallel nor perpendicular must not either. Both throw BadInput naming the plates.
void requireMitredPerpendicularApart(const Plate& a, const Plate& b, double tolerance);
void requireNoSlantedOverlap(const Plate& plateA, const Plate& plateB, double tolerance);

}  // namespace geometry
}  // namespace desia
