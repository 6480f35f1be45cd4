// SPDX-License-Identifier: GPL-3.0-or-later
// Slanted sliding dovetails (milled; issue 26): the tongue plate S stands with its side (bevelled
// to lie on the face) on a face of the housing plate F, their planes from
// slantedDovetail.leastDegrees (60) to less than square apart (IBOIS's hexboxes: 80..88), as a
// slanted tenon's (slanted_tenon.h). A tongue of dovetail section grows out of that side through F to its
// far face, centred on S's mid-plane and leaning with it; the housing is a slot through F with
// walls that lean with S's slant and flare out towards F's far face (dovetail.slope), open at the
// end S leaves through and stopped before the other. S then leaves only along the shared edge,
// out through the open end: what the hexboxes' plan asks of plates on bevelled sides, which a
// slanted tenon (out along S's plane) does not give (the paper's sliding dovetail, Section 5.2,
// Fig. 2 right, at an angle and through; a laser cuts square to the sheet, so only a router
// makes it). Through, not blind: the slot is a slanted cut through F (PlateCuts::slanted, as the
// slanted tenons' mortises), which holds on plates with bevelled sides too.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/vec3.h"
#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"
#include "plate/joints/slanted_tenon.h"

namespace desia {

// Where a slanted sliding dovetail can be milled for one contact. Its points are measured in the
// frame (s, c, n): s along the side from side.origin[0], c across it on F's face along `width`,
// n into F along side.intoMortise (an orthonormal frame: the side's edges lie on F's face).
struct SlantedDovetailSite {
  SlantedSide side;
  Vec3 width{0, 0, 0};   // unit, on F's face square to the side, from its edge on S's first face to the second's
  double sideWidth = 0;  // the side's width on F's face, along `width`
  double lean = 0;       // how far S's mid-plane runs along `width` per mm into F (cot of the planes' angle)
  double depth = 0;      // F's thickness: the tongue runs through F
  // The tongue's section: its walls at F's face [0] and far face [1], as c (low, high).
  std::array<std::array<double, 2>, 2> walls{};
  std::array<bool, 2> opens{false, false};  // the slot may open at the side's start [0] (towards -along) / end [1]
  std::array<double, 2> reach{0, 0};        // how far past the contact it runs on to F's edge there
  double stop = 0;                          // how far before the closed end the slot stops
  // The directions the tongue plate may leave in: along the side towards an open end.
  std::vector<Vec3> exits() const;
};

// One slanted dovetail to cut: the site and the end its slot opens at (0: from, 1: to).
struct SlantedDovetailCut {
  SlantedDovetailSite site;
  int openEnd = 1;
};

// The site on `contact` when the geometry allows one: a slanted side (slantedSideOf, from
// options.slantedDovetail.leastDegrees), long
// enough for a stopped slot (housingStop + shortestJoint), the tongue's neck at F's face
// dovetail.width of S's thickness and at least dovetail.narrowestNeck, flaring by dovetail.slope
// per mm through F; the slot inside F (on both its faces) from the stop to an end where F's
// material ends (at the contact's end or, run on past it, at F's edge); nothing otherwise.
std::optional<SlantedDovetailSite> slantedDovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                         const JointCutOptions& options = {});

// The tongue, as a solid attached to S: the section from F's face to its far face, along the
// contact from the stop to the open end.
Plate slantedDovetailTongue(const SlantedDovetailCut& cut);

// The slot through F: its outline on F's first face's plane [0] and on its second's [1], vertex
// for vertex, its walls moved out by `grow` mm (and its stop back by as much), run on past F's
// edge at the open end.
std::array<Loop, 2> slantedDovetailSlot(const std::vector<Plate>& plates, const SlantedDovetailCut& cut,
                                        const JointCutOptions& options, double grow);

// The normals of the joint's faces, from S into F: the shoulder, the two walls (leaning back
// towards S, so it cannot be pulled out) and the stop (against the exit).
std::vector<Vec3> slantedDovetailFaceNormals(const SlantedDovetailCut& cut);

// Where the slot lies in F, seen along its axis.
CutFootprint slantedDovetailFootprint(const std::vector<Plate>& plates, const SlantedDovetailCut& cut,
                                      const JointCutOptions& options);

// The joint to cut: the tongue attached to S, the slot (its walls and stop moved out by half the
// clearance) cut through F.
std::shared_ptr<const JointCut> jointCut(const SlantedDovetailCut& cut);

// The family for the joint planner (milled joints): a joint where the slot can open towards the
// mover's way out.
std::unique_ptr<JointFamily> makeSlantedDovetailFamily(const JointSetting& setting);

}  // namespace desia
