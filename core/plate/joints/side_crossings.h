// SPDX-License-Identifier: GPL-3.0-or-later
// Where plates crossing a side pass through it (issue 26): in IBOIS's VDA corner an upright bar
// straddles the side two hexagons of a layer share, through both; its slots (halved joints or a
// through slot) are cut there, so a joint on that side (an in-plane dovetail) must sit beside it.
#pragma once

#include <utility>
#include <vector>

#include "desia/plate.h"
#include "plate/plate_graph.h"

namespace desia {

// The plates that cross both plates of `contact` (two plates that touch).
std::vector<int> platesCrossingBoth(const PlateGraph& graph, const PlateContact& contact);

// The longest stretch of the side [from, to] (distances along the unit `along` from `origin`)
// that the slabs of the plates `crossers` leave free: a point s of the side is taken where a slab,
// grown by `grow` on both faces, holds origin + s along + t across for some t within `reach` of
// the side (`across`: unit, in the plates' plane, square to the side). The whole side without
// crossers; {from, from} when they cover it.
std::pair<double, double> clearStretchOfSide(const std::vector<Plate>& plates, const std::vector<int>& crossers,
                                             const Vec3& origin, const Vec3& along, const Vec3& across, double from,
                                             double to, double reach, double grow);

}  // namespace desia
