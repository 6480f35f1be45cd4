// SPDX-License-Identifier: GPL-3.0-or-later
// The registry of plate joint families (paper Section 5.2): every family a design may make, in
// the order the planner prefers them, and what the planner asks of them. Adding a family is a
// file of its own (its sites, its cut and its JointFamily) and its line in the two tables of
// joint_families.cpp (kFamilies, with its user-visible name, and kCutOrder), plus its JointType
// in desia/plate.h (and the name in the package's types, wasm/index.d.ts).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"

namespace desia {

class JointFamilies {
 public:
  // The families the realization makes (cut joints always, milled ones for Milled), for the
  // design of `graph`; keeps references to both arguments.
  JointFamilies(const PlateGraph& graph, const JointCutOptions& options, JointRealization realization);

  // Which joint `mover` gets with `other` when it leaves along d. Plates that cross: a joint of a
  // family that joins crossings (halved), or nothing when none lets them part that way. Planned
  // joints: the paper's rule by the angle between their shared edge and d (plannedJointType).
  // Otherwise the first family, in the order of preference, that lets the mover out on one of
  // the pair's contacts (on the largest such contact), or an empty joint.
  std::optional<PlateJoint> jointFor(int mover, int other, const Vec3& d) const;

  // The ways out the families' joints on `contact` give `plate`, added to `ways`.
  void addWaysOut(int contact, int plate, std::vector<Vec3>& ways) const;

  // A joint's faces in the joint model (normals from the mover into the other plate), and whether
  // the pair's other contacts keep theirs (JointFamily::faceNormals). Empty joints have none and
  // keep them; planned joints have the paper's model (plannedJointNormals) and do not.
  std::vector<Vec3> faceNormals(const PlateJoint& joint) const;
  bool keepsOtherContacts(const PlateJoint& joint) const;

  // Where the joints cut into the plates, in the joints' order.
  std::vector<CutFootprint> footprints(const std::vector<PlateJoint>& joints) const;

  // The joints to cut, with `clearance` mm of play, family by family in the cutting order.
  JointCutList cuts(const std::vector<PlateJoint>& joints, double clearance) const;

 private:
  struct Member {
    JointType type;
    std::unique_ptr<JointFamily> family;
  };
  const JointFamily& family(JointType type) const;
  std::optional<PlateJoint> crossingJoint(int crossing, int mover, int other, const Vec3& d) const;
  PlateJoint plannedJoint(int mover, int other, const Vec3& d) const;
  PlateJoint preferredJoint(int mover, int other, const Vec3& d) const;

  const PlateGraph& graph_;
  JointSetting setting_;
  std::vector<Member> families_;  // in the order of preference
};

// The paper's rule for planned joints: halved where the shared edge runs along d,
// mortise-and-tenon where it is within 45..135 degrees of d, empty otherwise.
JointType plannedJointType(const Vec3& edge, const Vec3& d);

}  // namespace desia
