// SPDX-License-Identifier: GPL-3.0-or-later
// Sliding joints along a mitre (milled; the paper's Fig. 16b, a halved joint for plates that meet
// at an angle with surface contact): the plate leaving along the shared edge (`slidePlate`) gets a
// groove of dovetail section in its mitre face, open towards its end behind it and stopped ahead;
// the other plate carries the tongue that runs in it. The slide plate can then leave only along
// the edge, forwards. The groove is a notch through the slide plate at its mitre with its wood
// given back around the groove (an attached prism) where the plate's other sides are clear;
// between there and its corner behind, the notch leaves the edge cut back (the tongue runs out
// through that gap).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

struct MitreSlide {
  int slidePlate = 0, tonguePlate = 0;
  Vec3 line{0, 0, 0};         // unit: the slide plate's way out, along the edge
  Vec3 mitreNormal{0, 0, 0};  // unit: the mitre's normal from the tongue plate into the slide plate
  Vec3 into{0, 0, 0};         // unit: the groove's depth, in the slide plate's plane across the edge
                              // (its faces leave the most wood round the groove that way)
  Vec3 middle{0, 0, 0};   // on the mitre face: where s = 0 along the edge, the tongue's root's middle across
  Vec3 across{0, 0, 0};   // unit, in the mitre face, perpendicular to the edge
  double halfHeight = 0;  // the tongue's root's half extent across the edge
  double depth = 0;       // how far it reaches into the slide plate, along `into`
  double lean = 0;        // how much wider its tip is on each side, per mm of depth (a dovetail)
  double tongueFrom = 0, tongueTo = 0;  // the tongue's extent along the edge; tongueTo is the groove's stop
  double woodFrom = 0;    // where the slide plate's wood around the groove begins again
  double notchFrom = 0;   // the notch's open end, past the slide plate's corner behind
  double notchReach = 0;  // how far the notch runs into the slide plate from the mitre
  Loop notch;             // the cut through the slide plate: the band at the mitre from its stop
                          // back past the whole plate
};

// The slide along the mitre `contact` for `slidePlate` leaving along d (parallel to the shared
// edge), sized by options.mitreSlide, when the plates leave room for the groove and the tongue
// (options.woodMargin of wood round the groove, a groove at least mitreSlide.shortestGroove long
// with wood all round it); nothing otherwise.
std::optional<MitreSlide> mitreSlideOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                       int slidePlate, const Vec3& d, const JointCutOptions& options = {});

// The normals of a slide's faces, from the slide plate into the tongue plate: the groove's floor
// (and the mitre), its two flanks, and its stop.
std::vector<Vec3> mitreSlideFaceNormals(const MitreSlide& slide);

// The notch through the slide plate.
CutFootprint mitreSlideFootprint(const std::vector<Plate>& plates, const MitreSlide& slide);

// The joint to cut: the notch, the slide plate's wood around the groove, and the tongue (less
// half the clearance all round and at its end).
std::shared_ptr<const JointCut> jointCut(const MitreSlide& slide);

// The family for the joint planner (milled joints): the groove in the mover, which leaves along
// the shared edge.
std::unique_ptr<JointFamily> makeMitreSlideFamily(const JointSetting& setting);

}  // namespace desia
