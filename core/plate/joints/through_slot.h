// SPDX-License-Identifier: GPL-3.0-or-later
// Through slots (issue 26): where a plate crosses another square (an upright bar through a layer
// of IBOIS's VDA corner, straddling the edge where two plates of the layer meet), the crossed
// plate gets a slot through it as large as the whole crossing (the bar's section plus the
// clearance), run out of its outline where it ends at the crossing, and the bar sits in it whole:
// the bar leaves along the crossed plate's axis (in its own plane, square to the crossing line),
// either way. Offered only where halved joints cannot let the bar out along the line either way
// (its slots in the two plates open towards each other); a cut joint (square to the sheet).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

struct ThroughSlotSite {
  int seated = 0;   // the plate sitting whole in the slot (the bar: its section is the slot's)
  int slotted = 0;  // the plate the slot goes through
  // Where the slotted plate ends at the crossing: [0] towards -line, [1] towards +line.
  std::array<bool, 2> opens{false, false};
  Vec3 out{0, 0, 0};  // unit: the slotted plate's axis, the seated plate's way out (and its negation)
};

// The site on contacts[crossingIndex] with `seated` seated, when the plates cross square, the
// slotted plate ends at the crossing on one side at most (the slot does not cut it in two),
// halved joints on the seated plate's crossings along that line hold it both ways along it, and
// the slotted plate leaves options.woodMargin of wood round the slot (at options.clearance) on
// its long sides and closed ends; nothing otherwise.
std::optional<ThroughSlotSite> throughSlotSiteOf(const std::vector<Plate>& plates,
                                                 const std::vector<PlateContact>& contacts, int crossingIndex,
                                                 int seated, const JointCutOptions& options = {});

// The slot through the slotted plate: the crossing's extent along the line (grown by half the
// clearance at closed ends, run out past the outline at open ones) across the seated plate's
// thickness plus the clearance.
Loop throughSlotRegion(const std::vector<Plate>& plates, const PlateContact& crossing, const ThroughSlotSite& site,
                       const JointCutOptions& options, double clearance);

// The normals of the joint's faces, from the seated plate into the slotted one: the slot's walls
// (+-the seated plate's axis) and its closed ends (along the line).
std::vector<Vec3> throughSlotFaceNormals(const std::vector<Plate>& plates, const PlateContact& crossing,
                                         const ThroughSlotSite& site);

std::unique_ptr<JointFamily> makeThroughSlotFamily(const JointSetting& setting);

}  // namespace desia
