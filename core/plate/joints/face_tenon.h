// SPDX-License-Identifier: GPL-3.0-or-later
// Stub tenons on a lap (milled; two plates lying face to face, as the CHAIR's repair bars on its
// legs): a block on the tenon plate's face in the middle of the lap (by default its middle third
// each way), standing into a blind mortise (by default a third of the other plate's thickness
// deep: a housing cut from that plate's face). The tenon plate can then leave only straight off
// the lap.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

struct FaceTenon {
  int tenonPlate = 0, mortisePlate = 0;
  Vec3 out{0, 0, 0};     // unit: the lap's normal from the mortise plate to the tenon plate (the way out)
  Vec3 origin{0, 0, 0};  // on the lap; the block spans origin + [s0, s1] u + [t0, t1] v
  Vec3 u{0, 0, 0}, v{0, 0, 0};
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
  double depth = 0;      // into the mortise plate
  Loop footprint(double grow) const;  // the block's rectangle on the lap, grown on every side
};

// The stub tenon on the lap `contact` for `tenonPlate` leaving along `d` (straight off the lap,
// both plates prisms, the block inside the lap with a margin), sized by options.faceTenon;
// nothing otherwise.
std::optional<FaceTenon> faceTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const Vec3& d, const JointCutOptions& options = {});

// The normals of a stub tenon's faces, from the tenon plate into the mortise plate: its end and
// its four sides.
std::vector<Vec3> faceTenonFaceNormals(const FaceTenon& tenon);

// The blind mortise, cut into the mortise plate from the lap's face.
CutFootprint faceTenonFootprint(const std::vector<Plate>& plates, const FaceTenon& tenon);

// The joint to cut: the blind mortise (grown by half the clearance on every side) and the block.
std::shared_ptr<const JointCut> jointCut(const FaceTenon& tenon);

// The family for the joint planner (milled joints): the block on the mover, which leaves straight
// off the lap.
std::unique_ptr<JointFamily> makeFaceTenonFamily(const JointSetting& setting);

}  // namespace desia
