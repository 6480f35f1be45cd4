// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/joint_families.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/joints/dovetail.h"
#include "plate/joints/face_tenon.h"
#include "plate/joints/halved.h"
#include "plate/joints/inplane_dovetail.h"
#include "plate/joints/mitre_slide.h"
#include "plate/joints/mitre_tenon.h"
#include "plate/joints/slanted_dovetail.h"
#include "plate/joints/slanted_tenon.h"
#include "plate/joints/step_tenon.h"
#include "plate/joints/through_slot.h"
#include "plate/joints/tenon.h"

namespace desia {
namespace {

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Every family: its type, its name as users see it (results, reports, the package's types),
// whether only a CNC router makes it (JointRealization::Milled), and how to make it for a design.
// In the order the planner prefers them for a pair: joints that can be cut before milled ones,
// a tenon across a mitre before a slide along it, a sliding dovetail last (where no tenons let
// the plate out), a step tenon past a shallow mitre after them (it joins only what they cannot),
// on a bevelled side a slanted tenon before a slanted sliding dovetail (as square ones). In-plane
// dovetails join only plates lying in one plane edge to edge, which no other family joins.
// Halved joints join plates that cross, and after them through slots (only where a plate ends
// inside the crossing both ways and the other not).
struct FamilyEntry {
  JointType type;
  const char* name;
  bool milledOnly;
  std::unique_ptr<JointFamily> (*make)(const JointSetting&);
};

const FamilyEntry kFamilies[] = {
    {JointType::Halved, "halved", false, makeHalvedFamily},
    {JointType::ThroughSlot, "through-slot", false, makeThroughSlotFamily},
    {JointType::MortiseTenon, "mortise-tenon", false, makeTenonFamily},
    {JointType::InplaneDovetail, "inplane-dovetail", false, makeInplaneDovetailFamily},
    {JointType::MitreTenon, "mitre-tenon", true, makeMitreTenonFamily},
    {JointType::MitreSlide, "mitre-slide", true, makeMitreSlideFamily},
    {JointType::FaceTenon, "face-tenon", true, makeFaceTenonFamily},
    {JointType::Dovetail, "dovetail", true, makeDovetailFamily},
    {JointType::StepTenon, "step-tenon", true, makeStepTenonFamily},
    {JointType::SlantedTenon, "slanted-tenon", true, makeSlantedTenonFamily},
    {JointType::SlantedDovetail, "slanted-dovetail", true, makeSlantedDovetailFamily},
};

// The order the joints are cut in. Each plate's cut loops and attached solids come in this
// order, which the bytes of a result depend on: a new family goes at the end.
const JointType kCutOrder[] = {JointType::Dovetail,  JointType::MitreTenon, JointType::MitreSlide,
                               JointType::FaceTenon, JointType::Halved,     JointType::MortiseTenon,
                               JointType::StepTenon, JointType::SlantedTenon, JointType::SlantedDovetail,
                               JointType::InplaneDovetail, JointType::ThroughSlot};

}  // namespace

bool makesJoints(JointRealization realization) { return realization != JointRealization::Planned; }

bool exitsLet(const std::vector<Vec3>& exits, int tenonPlate, int mover, const Vec3& d) {
  for (const Vec3& exit : exits) {
    if (dot(tenonPlate == mover ? exit : negated(exit), d) > 1 - tolerance::kDirection) return true;
  }
  return false;
}


void requireAtLeast(double value, double least, const char* setting) {
  if (!(value >= least)) {
    throwBadInput("", std::string("the joint size ") + setting + " must be at least " + formatNumber(least) + ", got " +
                          formatNumber(value));
  }
}

void requireShare(const LengthShare& share, const char* setting, bool whole) {
  const double value = share.of(1);
  if (!(share.denominator > 0 && value > 0 && (whole ? value <= 1 : value < 1))) {
    throwBadInput("", std::string("the joint size ") + setting + " must be a share of a length above 0 and " +
                          (whole ? "at most 1" : "below 1") + ", got " + formatNumber(share.numerator) + "/" +
                          formatNumber(share.denominator));
  }
}

std::vector<Vec3> plannedJointNormals(const Vec3& thicknessAxis, const Vec3& d) {
  Vec3 u = minus(thicknessAxis, scaled(d, dot(thicknessAxis, d)));
  if (norm(u) < tolerance::kParallelSine) u = cross(d, std::abs(d[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0});
  u = normalized(u);
  const Vec3 v = cross(d, u);
  return {negated(d), u, negated(u), v, negated(v)};
}

JointType plannedJointType(const Vec3& edge, const Vec3& d) {
  if (parallel(edge, d)) return JointType::Halved;
  const double cosine = std::abs(dot(normalized(edge), normalized(d)));
  return cosine <= std::cos(M_PI / 4) + tolerance::kExactCosine ? JointType::MortiseTenon : JointType::Empty;
}

const char* jointTypeName(JointType type) {
  for (const FamilyEntry& entry : kFamilies) {
    if (entry.type == type) return entry.name;
  }
  return "empty";
}

JointFamilies::JointFamilies(const PlateGraph& graph, const JointCutOptions& options, JointRealization realization)
    : graph_(graph), setting_{graph, options, realization} {
  requireAtLeast(options.clearance, 0, "clearance");
  requireAtLeast(options.woodMargin, 0, "woodMargin");
  requireAtLeast(options.shortestJoint, 0, "shortestJoint");
  for (const FamilyEntry& entry : kFamilies) {
    if (entry.milledOnly && realization != JointRealization::Milled) continue;
    families_.push_back({entry.type, entry.make(setting_)});
  }
}

const JointFamily& JointFamilies::family(JointType type) const {
  for (const Member& member : families_) {
    if (member.type == type) return *member.family;
  }
  throw Error(ErrorCode::Internal, std::string("no joint family '") + jointTypeName(type) + "' in this design");
}

std::optional<PlateJoint> JointFamilies::jointFor(int mover, int other, const Vec3& d) const {
  const int crossing = crossingBetween(graph_, mover, other);
  if (crossing >= 0) return crossingJoint(crossing, mover, other, d);
  if (!makesJoints(setting_.realization)) return plannedJoint(mover, other, d);
  return preferredJoint(mover, other, d);
}

std::optional<PlateJoint> JointFamilies::crossingJoint(int crossing, int mover, int other, const Vec3& d) const {
  for (const Member& member : families_) {
    if (member.family->joinsCrossings() && member.family->lets(crossing, mover, d))
      return PlateJoint{mover, other, d, member.type, makesJoints(setting_.realization) ? crossing : -1};
  }
  return std::nullopt;
}

// Nothing is cut: the type by the edge of the pair's largest contact, no contact of its own.
PlateJoint JointFamilies::plannedJoint(int mover, int other, const Vec3& d) const {
  const std::vector<int>& neighbours = graph_.neighbours[static_cast<size_t>(mover)];
  const auto at = std::lower_bound(neighbours.begin(), neighbours.end(), other) - neighbours.begin();
  const Vec3& edge = graph_.edgeTo[static_cast<size_t>(mover)][static_cast<size_t>(at)];
  return PlateJoint{mover, other, d, plannedJointType(edge, d), -1};
}

PlateJoint JointFamilies::preferredJoint(int mover, int other, const Vec3& d) const {
  PlateJoint joint{mover, other, d, JointType::Empty, -1};
  for (const Member& member : families_) {
    if (member.family->joinsCrossings()) continue;
    for (int c : graph_.contactsOf[static_cast<size_t>(mover)]) {
      const PlateContact& contact = graph_.contacts[static_cast<size_t>(c)];
      if (contact.a != other && contact.b != other) continue;
      if (!member.family->lets(c, mover, d)) continue;
      if (joint.contact < 0 || contact.area > graph_.contacts[static_cast<size_t>(joint.contact)].area) {
        joint.type = member.type;
        joint.contact = c;
      }
    }
    if (joint.type != JointType::Empty) return joint;
  }
  return joint;
}

void JointFamilies::addWaysOut(int contact, int plate, std::vector<Vec3>& ways) const {
  for (const Member& member : families_) member.family->addWaysOut(contact, plate, ways);
}

std::vector<Vec3> JointFamilies::faceNormals(const PlateJoint& joint) const {
  if (joint.type == JointType::Empty) return {};
  if (joint.contact < 0) return plannedJointNormals(graph_.thicknessAxis[static_cast<size_t>(joint.mover)], joint.direction);
  return family(joint.type).faceNormals(joint);
}

bool JointFamilies::keepsOtherContacts(const PlateJoint& joint) const {
  if (joint.type == JointType::Empty) return true;
  return joint.contact >= 0 && family(joint.type).keepsOtherContacts();
}

std::vector<CutFootprint> JointFamilies::footprints(const std::vector<PlateJoint>& joints) const {
  std::vector<CutFootprint> footprints;
  for (const PlateJoint& joint : joints) {
    if (joint.type != JointType::Empty) family(joint.type).addFootprints(joint, footprints);
  }
  return footprints;
}

JointCutList JointFamilies::cuts(const std::vector<PlateJoint>& joints, double clearance) const {
  JointCutList cuts;
  for (const JointType type : kCutOrder) {
    for (const PlateJoint& joint : joints) {
      if (joint.type == type) family(type).addCuts(joint, clearance, cuts);
    }
  }
  return cuts;
}

}  // namespace desia
