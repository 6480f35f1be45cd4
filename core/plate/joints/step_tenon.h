// SPDX-License-Identifier: GPL-3.0-or-later
// Step tenons (milled; issue 26): plates meeting edge to edge at a shallow angle (their planes
// 30..80 degrees apart: slanted boxes, icosahedra, folded plates). Over a stretch of the mitre the
// tenon plate runs on past it, inside its own slab (where the two slabs overlap: the wood is in
// the tenon plate's stock), into a pocket milled in the other plate's edge. The pocket's wall
// contains the tenon plate's axis and the edge, its floor is the plane of the tenon plate's face
// towards the other plate; the stretch is two tenons side by side whose ends flare apart towards
// the pocket's wall (dovetails seen along the tenon plate's axis), so that the tenon plate leaves
// only straight out along its own axis, as the paper's mortise-and-tenon leaves along its one way
// (Section 5.2, Fig. 16; the pocket's walls all contain that way).
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

// A 2D point of the joint's section across the edge: x along `inward`, y along `up`.
using SectionPoint = std::array<double, 2>;
using Section = std::vector<SectionPoint>;

struct StepTenon {
  int tenonPlate = 0, pocketPlate = 0;
  Vec3 origin{0, 0, 0};   // on the mitre, in the middle of the stretch
  Vec3 line{0, 0, 0};     // unit, along the edge (s)
  Vec3 inward{0, 0, 0};   // unit, in the tenon plate's plane, square to the edge, into it (x)
  Vec3 up{0, 0, 0};       // unit, the tenon plate's axis, away from the pocket plate's side (y):
                          // the tenon plate's one way out
  Vec3 mitre{0, 0, 0};    // unit, the mitre's normal from the tenon plate into the pocket plate
  double floor = 0;       // y of the tenon plate's face towards the pocket plate (the pocket's floor)
  double top = 0;         // y of its other face
  double tenonTop = 0;    // y of the tenons' tops (the pocket is open above them)
  double wall = 0;        // x of the pocket's wall (the tenons' ends)
  double root = 0;        // x where the mitre meets the floor
  double gap = 0;         // between the two tenons at the wall, along the edge
  double halfWidth = 0;   // the pair's half extent along the edge at the wall
  double flare = 0;       // how far each tenon's ends run outwards along the edge per mm towards the root
  double notchHalf = 0;   // half the notch through the pocket plate along the edge
  Section overlap;        // the pocket plate's half of where the two slabs overlap (beyond the mitre)
  Section pocketWood;     // the pocket plate's section up to the notch's end, beyond the mitre
  Vec3 notchInward{0, 0, 0};  // unit, in the pocket plate's plane, square to the edge, into it
  double notchReach = 0;      // how far the notch through the pocket plate runs along notchInward
  // x of the mitre at height y (it meets the floor at `root`).
  double mitreAt(double y) const;
};

// The step tenon on the edge-to-edge `contact` with `tenonPlate` carrying the tenon, sized by
// options.stepTenon; nothing where the plates do not meet edge to edge, their planes are not
// within the family's angles, or the stretch is shorter than options.shortestJoint.
std::optional<StepTenon> stepTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const JointCutOptions& options = {});

// The normals of its faces, from the tenon plate into the pocket plate: the pocket's wall, its
// floor, the tenons' four flared ends, and the mitre beside them.
std::vector<Vec3> stepTenonFaceNormals(const StepTenon& tenon);

// The two tenons (attached to the tenon plate), less `play` on their ends, floor and wall.
std::vector<Plate> stepTenonSolids(const StepTenon& tenon, double play);

// The pocket plate's wood in the notch, less the pocket (attached back to it).
std::vector<Plate> stepTenonPocketWood(const StepTenon& tenon);

// Where it cuts: the notch through the pocket plate (its wood around the pocket is put back as
// attached solids).
CutFootprint stepTenonFootprint(const StepTenon& tenon);

// The joint to cut: the notch, the pocket plate's wood around the pocket and the tenon (less the
// clearance on its end, floor and sides).
std::shared_ptr<const JointCut> jointCut(const StepTenon& tenon);

// The family for the joint planner (milled joints).
std::unique_ptr<JointFamily> makeStepTenonFamily(const JointSetting& setting);

}  // namespace desia
