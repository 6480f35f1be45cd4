// SPDX-License-Identifier: GPL-3.0-or-later
// Halved joints (paper Fig. 2, middle): two plates that cross, each slotted halfway where the
// other passes through it, the slots opening on opposite sides so that one plate slides off the
// other along the crossing line.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"

namespace desia {

// A slot to cut out of a plate (a halved joint's half): a rectangle in its plane, through it.
// Where the plates cross at an angle other than square, its walls follow the other plate's
// faces (paper Fig. 16c at any angle): `secondFace` is then its outline on the plate's second
// face, vertex for vertex (a parallelogram's trace shifted across the line), else empty.
struct SlotCut {
  int plate = 0;
  Loop rectangle;
  Loop secondFace;
};

// The two slots of a halved joint at a crossing: `mover` leaves along d (along the crossing
// line), so its slot runs from the middle of the crossing back out of its outline behind it, and
// the other plate's from the middle out of its outline ahead; each as wide as the other plate is
// thick plus options.clearance (at an angle: the other plate's slab, widened by half the
// clearance on each side, where it meets this one), and run on past the crossing's end by the
// crossing's length or twice the wider slot, whichever is more, and options.woodMargin.
std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, const JointCutOptions& options);

// Where the slot lies, seen along the plate's axis (a slanted slot: both its faces' outlines).
CutFootprint slotFootprint(const SlotCut& slot);

// The slot to cut (its clearance is in its rectangle).
std::shared_ptr<const JointCut> jointCut(const SlotCut& slot);

// Do the plates of `crossing` cross at an angle other than square, so that a halved joint's
// notch walls are slanted to the sheet (leaning more than the contact tolerance across the
// thicker plate)? A laser (or a router's through cut) cuts square to the sheet, so only a router
// milling the slanted walls makes such a notch (issue 26, lead's decision).
bool needsSlantedNotchWalls(const std::vector<Plate>& plates, const PlateContact& crossing);

// Can the slots of a halved joint on `crossing` open so that `mover` leaves the other plate along
// d (parallel to the crossing line)? The mover's slot opens behind it, the other plate's ahead,
// so the mover's outline must end at the crossing behind it and the other's ahead of it: with
// the crossing, or tapering past it (PlateContact::aOverhang: crossing the slot at a slant, as a
// rib's end bevelled to sit level does) by no more than the slot is wide on that plate, which
// the slot, run on past the crossing's end (halvedSlots), cuts away. A plate running on past the
// end square across the slot does not open there: a slot would cut an empty notch into it.
bool halvedSlotsOpen(const std::vector<Plate>& plates, const PlateContact& crossing, int mover, const Vec3& d);

// How wide the slot of `crossing` is on `plate` (square to the crossing line, in its plane): the
// other plate's slab where it passes through this one, both faces' traces.
double slotWidthOn(const std::vector<Plate>& plates, const PlateContact& crossing, int plate);

// Why no joint of a cut design (JointRealization::Cut) joins the graph's first crossing at an
// angle: "the crossing of plates 1 and 5 at 60.0 degrees needs slanted notch walls, ...: mill them
// (joints 'milled')", or "" when every crossing is square.
std::string slantedCrossingsNeedMilling(const PlateGraph& graph);

// The family for the joint planner: plates that cross part only along their crossing line, and
// only towards the sides their slots can open to; when cut (not milled), only where they cross square.
std::unique_ptr<JointFamily> makeHalvedFamily(const JointSetting& setting);

}  // namespace desia
