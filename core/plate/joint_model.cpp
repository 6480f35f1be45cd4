// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joint_model.h"

#include <cmath>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

// The assembly of A_i: parts 0..i-1 are the steps' plates, part i (when any plate is left) is R_i.
// Every contact of a joint's two plates keeps its faces, except the one the joint is made in,
// which gets the faces of the joint (JointFamily::faceNormals: for tenons the shoulder, their
// cheeks and their ends).
Assembly jointModel(const PlateGraph& graph, const JointFamilies& families, const std::vector<PlanStep>& steps) {
  const std::vector<Plate>& plates = graph.plates;
  std::vector<int> node(graph.plateCount, static_cast<int>(steps.size()));  // R_i by default
  Assembly assembly;
  for (size_t k = 0; k < steps.size(); ++k) {
    node[steps[k].plate] = static_cast<int>(k);
    assembly.parts.push_back({plates[steps[k].plate].id, plates[steps[k].plate].name});
  }
  if (static_cast<int>(steps.size()) < graph.plateCount) assembly.parts.push_back({0, "rest"});
  for (const PlanStep& step : steps) {
    for (const PlateJoint& joint : step.joints) {
      const int a = node[joint.mover], b = node[joint.other];
      if (families.keepsOtherContacts(joint)) {
        for (int c : graph.contactsOf[joint.mover]) {
          const PlateContact& contact = graph.contacts[c];
          if (c == joint.contact || contact.crossing) continue;
          if (contact.a == joint.mover && contact.b == joint.other)
            assembly.contacts.push_back({a, b, contact.normal, contact.area});
          if (contact.b == joint.mover && contact.a == joint.other)
            assembly.contacts.push_back({a, b, negated(contact.normal), contact.area});
        }
      }
      for (const Vec3& n : families.faceNormals(joint)) assembly.contacts.push_back({a, b, *cleanedNormal(n), 1.0});
    }
  }
  return assembly;
}

// Do the contact normals lie along at most three mutually square lines? Then the LP test adds
// nothing to the DBG test: the constraints n·(v_b - v_a) >= 0 split into one set per line, so any
// motion is motions along the lines, and the parts moving along one line (all at the speed of the
// fastest) are a motion the DBG along it finds, and the LP tests of such designs are skipped.
bool hasSquareNormalsOnly(const Assembly& model) {
  std::vector<Vec3> lines;
  for (const Contact& contact : model.contacts) {
    bool known = false;
    for (const Vec3& line : lines) {
      const double c = std::abs(dot(line, contact.normal));
      if (c > 1 - tolerance::kExactCosine) {
        known = true;
        break;
      }
      if (c > tolerance::kExactCosine) return false;  // neither along nor square to a line
    }
    if (known) continue;
    if (lines.size() == 3) return false;
    lines.push_back(contact.normal);
  }
  return true;
}

std::vector<Plate> jointedPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                                 const std::vector<PlateJoint>& joints, double clearance,
                                 const JointCutOptions& options) {
  JointCutOptions cut = options;
  cut.clearance = clearance;
  return cutJoints(plates, families.cuts(joints, clearance), cut);
}

std::vector<Plate> cutPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                             const std::vector<PlateJoint>& joints, const PlateOptions& geometry, double clearance,
                             const JointCutOptions& options) {
  std::vector<Plate> cut = jointedPlates(plates, families, joints, clearance, options);
  validatePlates(cut, geometry, "the jointed plates");
  return regularizedPlates(cut, geometry, PlateOrigin::Computed);
}

JointedPlan cutPlan(const std::vector<Plate>& plates, const JointFamilies& families, const std::vector<PlateJoint>& joints,
                    const std::vector<int>& order, const std::vector<Vec3>& directions, const PlateOptions& geometry,
                    const JointCutOptions& options) {
  JointedPlan plan;
  plan.plates = cutPlates(plates, families, joints, geometry, 0, options);
  std::vector<Plate> inRemovalOrder;
  for (int plate : order) inRemovalOrder.push_back(plan.plates[plate]);
  plan.verification = verifyJointedPlates(inRemovalOrder, directions, geometry);
  return plan;
}

}  // namespace desia
