// SPDX-License-Identifier: GPL-3.0-or-later
// Tenons across a mitre (milled; paper Fig. 16a, a mortise-and-tenon for plates that meet at an
// angle with surface contact): two plates meeting edge to edge along a shared mitre face, neither
// face on the other. A tenon of parallelogram section grows out of the tenon plate's mitre face
// along `into`, perpendicular to the shared edge, into a pocket in the other plate that fits it
// on all four sides; the tenon plate can then leave only along -into, straight out of the pocket.
// The tenon and the pocket's surround are prisms along the edge (Plate::attached), and the pocket
// plate gets a notch at its mitre, through it, beneath them.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/vec3.h"
#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

struct MitreTenon {
  int tenonPlate = 0, pocketPlate = 0;
  Vec3 line{0, 0, 0};     // unit, along the shared edge
  Vec3 into{0, 0, 0};     // unit, perpendicular to the edge, from the tenon plate into the pocket plate
  Vec3 middle{0, 0, 0};   // on the mitre face, the middle of the tenon's root
  Vec3 across{0, 0, 0};   // unit, in the mitre face, perpendicular to the edge
  double halfWidth = 0;   // the tenon's half extent along the edge
  double halfHeight = 0;  // its root's half extent across the edge, in the mitre face
  double depth = 0;       // how far it reaches along `into`
  double notchReach = 0;  // how far the notch runs into the pocket plate from `middle`, past the
                          // pocket and past the mitre (where the plate is whole again)
  double endWood = 0;     // mm of wood the notch leaves beyond an oblique tenon's tip along the
                          // edge (JointCutOptions::woodMargin)
};

// The tenon across the mitre `contact` for `tenonPlate` leaving the other plate along -into, sized
// by options.mitreTenon, when the other plate is thick enough there to hold its pocket (with
// options.woodMargin of wood on every side); nothing for other contacts or directions. Where plates
// `crossers` cross both (side_crossings.h), "the mitre" is the longest stretch of it they leave free.
std::optional<MitreTenon> mitreTenonOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                       int tenonPlate, const Vec3& into, const JointCutOptions& options = {},
                                       const std::vector<int>& crossers = {});

// The normals of a mitre tenon's faces, from the tenon plate into the pocket plate: its tip, its
// two ends and its two sides (the mitre contact itself stays).
std::vector<Vec3> mitreTenonFaceNormals(const MitreTenon& tenon);

// The notch through the pocket plate.
CutFootprint mitreTenonFootprint(const std::vector<Plate>& plates, const MitreTenon& tenon);

// The joint to cut: the notch, the pocket plate's wood around the pocket and the tenon (less the
// clearance on its sides and tip).
std::shared_ptr<const JointCut> jointCut(const MitreTenon& tenon);

// Shared with the mitre slide, whose groove is a pocket in the slide plate seen the same way.

// 2D points of a mitre tenon's section plane (through `middle`, across the edge): x along
// `across`, y along the mitre's normal into the pocket plate.
using Flat = std::array<double, 2>;

// The section plane's frame: `across`, the mitre's normal, and the edge.
struct MitreFrame {
  Vec3 origin, across, normal, line;
  Vec3 at(const Flat& q, double s) const {
    return plus(origin, plus(scaled(across, q[0]), plus(scaled(normal, q[1]), scaled(line, s))));
  }
};
MitreFrame mitreFrame(const MitreTenon& tenon);

// In the pocket plate's plane, across the edge, away from the mitre into the plate.
Vec3 pocketInward(const std::vector<Plate>& plates, const MitreTenon& tenon);

// The pocket plate's wood in a notch at its mitre, in the section across the edge: beyond the
// mitre, between its faces, up to the notch's end, with `pocketSection` (root corners [0] and [1]
// on the mitre, their tips [3] and [2]) bitten out of its edge on the mitre, exactly (no grid
// rounding: the pocket's walls must be parallel to the way its tenon or tongue moves, or the
// contacts computed from them would block it by a rounding error).
std::vector<Flat> woodAroundPocket(const std::vector<Plate>& plates, const MitreTenon& tenon,
                                   const std::vector<Flat>& pocketSection);

// The family for the joint planner (milled joints): a tenon on the mover, into the other plate,
// against the mover's way out.
std::unique_ptr<JointFamily> makeMitreTenonFamily(const JointSetting& setting);

}  // namespace desia
