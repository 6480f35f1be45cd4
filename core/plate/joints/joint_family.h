// SPDX-License-Identifier: GPL-3.0-or-later
// What a plate joint family is to the joint planner (paper Section 5.2): for one design, which
// pairs its joints can join and which ways they let a plate leave in, the faces a joint gives the
// joint model, where it cuts the plates and how. The registry (joint_families.h) holds every
// family and is what the planner asks.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/plate.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"

namespace desia {

// What a family sees of the design: the structure, the realization and the joints' sizes.
struct JointSetting {
  const PlateGraph& graph;
  const JointCutOptions& options;
  JointRealization realization;
};

class JointFamily {
 public:
  explicit JointFamily(const JointSetting& setting) : setting_(setting) {}
  virtual ~JointFamily() = default;
  JointFamily(const JointFamily&) = delete;
  JointFamily& operator=(const JointFamily&) = delete;

  // Its joints join plates that cross (through each other), not plates that touch.
  virtual bool joinsCrossings() const { return false; }
  // Can one of its joints on `contact` (an index into graph.contacts) let `mover` leave the plate
  // across it along d?
  virtual bool lets(int contact, int mover, const Vec3& d) const = 0;
  // The ways its joints on `contact` let `plate` leave in, added to the candidate directions
  // (beyond the shared edges and the plate's own axis).
  virtual void addWaysOut(int /*contact*/, int /*plate*/, std::vector<Vec3>& /*ways*/) const {}
  // The normals of the faces a joint of the family gives its pair in the joint model, from
  // joint.mover into joint.other. The pair's other contacts keep their faces unless
  // keepsOtherContacts() says no (the contact the joint is made in is always replaced).
  virtual std::vector<Vec3> faceNormals(const PlateJoint& joint) const = 0;
  virtual bool keepsOtherContacts() const { return true; }
  // Where the joint cuts into the plates, without play (what the designer keeps apart).
  virtual void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const = 0;
  // The joint to cut, with `clearance` mm of play, added to `cuts`.
  virtual void addCuts(const PlateJoint& joint, double clearance, JointCutList& cuts) const = 0;

 protected:
  const PlateGraph& graph() const { return setting_.graph; }
  const std::vector<Plate>& plates() const { return setting_.graph.plates; }
  const PlateContact& contact(int index) const { return setting_.graph.contacts[static_cast<size_t>(index)]; }
  const JointCutOptions& options() const { return setting_.options; }
  JointRealization realization() const { return setting_.realization; }

 private:
  JointSetting setting_;
};

// Joints made in the plates (cut or milled), not the planned model alone.
bool makesJoints(JointRealization realization);

// Does a joint whose tenon plate may leave along `exits` let `mover` leave along d (the tenon
// plate along an exit, the other plate against one)?
bool exitsLet(const std::vector<Vec3>& exits, int tenonPlate, int mover, const Vec3& d);
// Exactly (within tolerance::kDirection): a joint cut along its own way and verified at clearance
// 0 binds on a way even 0.03 degrees off it (a drawn design's shared edge beside its bevelled
// side: IBOIS's hexboxes), so letting such ways in (tried: up to kPlannedParallelSine) only gave
// the search joints that failed on the jointed plates.

// The site (or joint) a family worked out for a joint it let: a family is asked for the faces and
// cuts of its own joints only, so finding none is a bug in the family (Internal), never a
// missing site read as if it were there.
template <typename Site>
const Site& letJointSite(const std::optional<Site>& site, const char* family) {
  if (!site) throw Error(ErrorCode::Internal, std::string("a ") + family + " joint where no " + family + " fits");
  return *site;
}

// The least slope (mm per mm of depth) a dovetail's flanks are given: straight flanks would let
// the tongue or tab out across them, which the families' ways out do not say.
constexpr double kLeastFlankSlope = 1.0 / 100;

// Throw BadInput naming the setting (e.g. "dovetail.slope") unless it is a number of at least
// `least`, or a share above 0 and below 1 (at most 1 where `whole` may be taken).
void requireAtLeast(double value, double least, const char* setting);
void requireShare(const LengthShare& share, const char* setting, bool whole = false);

// The paper's model of a joint not cut (planned joints, and halved joints whose plates cross): a
// shoulder across d and the cheeks and ends every slot or tenon has, from the mover's thickness
// axis.
std::vector<Vec3> plannedJointNormals(const Vec3& thicknessAxis, const Vec3& d);

}  // namespace desia
