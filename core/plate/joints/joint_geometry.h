// SPDX-License-Identifier: GPL-3.0-or-later
// What every plate joint family measures the plates with (paper Section 5.2, geometry
// realization): the small questions every joint asks of a contact or a plate's face. Its
// tolerances are in desia/tolerances.h.
#pragma once

#include <polyclipping/clipper.hpp>

#include <optional>
#include <utility>
#include <vector>

#include "desia/plate.h"
#include "plate/plane_frame.h"

namespace desia {

// The area (mm^2) of Clipper paths in a PlaneFrame's integer coordinates.
double areaOf(const ClipperLib::Paths& paths);

// Area of the loops' region (non-zero) inside or outside `face` (its outline minus its holes).
double areaAgainst(const std::vector<Loop>& loops, const std::vector<Loop>& face, const PlaneFrame& frame,
                   bool outside);

// The region's extent along a direction, as distances from a point.
std::pair<double, double> extentAlong(const Loop& region, const Vec3& origin, const Vec3& direction);

// The plate across a contact from `plate`, for contacts where two plates touch (not crossings);
// the check every joint on a touching pair opens with.
std::optional<int> touchingPartnerOf(const PlateContact& contact, int plate);

// How many of the two plates have a face on the contact: 0 where they meet edge to edge (a
// mitre), 2 where they lie face to face (a lap), 1 for an edge on a face (T and L joints).
int facesOnContact(const std::vector<Plate>& plates, const PlateContact& contact);

// A solid from its first loop and its second (vertex for vertex), its first loop turned so that
// its normal points to the second (the milled pieces every family attaches to a plate).
Plate solidOf(Loop first, Loop second);

}  // namespace desia
