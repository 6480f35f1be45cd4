// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/missing_joints.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/slanted_tenon.h"
#include "plate/plate_graph.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

double degreesBetweenLines(const Vec3& a, const Vec3& b) {
  const double cosine = std::min(1.0, std::abs(dot(normalized(a), normalized(b))));
  return std::acos(cosine) * 180 / M_PI;
}

std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f degrees", value);
  return text;
}

// The index (into graph.contacts) of the pair's largest contact (the one the planner's edge
// comes from), or -1.
int largestContact(const PlateGraph& graph, int p, int q) {
  int best = -1;
  for (int c : graph.contactsOf[static_cast<size_t>(p)]) {
    const PlateContact& contact = graph.contacts[static_cast<size_t>(c)];
    if ((contact.a == q || contact.b == q) &&
        (best < 0 || contact.area > graph.contacts[static_cast<size_t>(best)].area))
      best = c;
  }
  return best;
}

// How two plates meet at a contact: crossing, face on face, edge on face or edge to edge (the
// contact's normal along both plates' axes, one of them, or neither).
std::string howTheyMeet(const PlateContact& contact, const Vec3& axisA, const Vec3& axisB) {
  if (contact.crossing) return "crossing";
  const bool onA = norm(cross(contact.normal, axisA)) < tolerance::kParallelSine;
  const bool onB = norm(cross(contact.normal, axisB)) < tolerance::kParallelSine;
  if (onA && onB) return "face on face";
  if (onA || onB) return "edge on face";
  return "edge to edge";
}

// Where a slanted tenon fits the pair's contact but lets the mover out another way than the
// plan's (IBOIS's hexboxes: the plan slides plates along their edges, a tenon lets them out
// along the tenon plate's plane only): that way and how far it is from the plan's, else "".
std::string slantedTenonElsewhere(const PlateGraph& graph, int contact, const PlateJoint& joint,
                                  const JointCutOptions& options) {
  const std::optional<SlantedTenonSite> site =
      slantedTenonSiteOf(graph.plates, graph.computedContacts[static_cast<size_t>(contact)], options);
  if (!site) return "";
  const Vec3 exit = site->tenonPlate == joint.mover ? negated(site->out) : site->out;
  const double cosine = std::max(-1.0, std::min(1.0, dot(exit, normalized(joint.direction))));
  return "; a slanted tenon fits there but lets " +
         geometry::plateName(graph.plates[static_cast<size_t>(joint.mover)]) + " out only " +
         degrees(std::acos(cosine) * 180 / M_PI) + " off that way";
}

}  // namespace

std::vector<std::string> jointsNothingMakes(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                            const std::vector<PlateJoint>& planned, const JointCutOptions& options) {
  const PlateGraph graph = buildPlateGraph(plates, contacts, JointRealization::Milled);
  const JointFamilies made(graph, options, JointRealization::Milled);
  std::vector<std::string> missing;
  for (const PlateJoint& joint : planned) {
    if (joint.type == JointType::Empty) continue;  // the plan needs no joint there
    const std::optional<PlateJoint> madeJoint = made.jointFor(joint.mover, joint.other, joint.direction);
    if (madeJoint && madeJoint->type != JointType::Empty) continue;
    const int largest = largestContact(graph, joint.mover, joint.other);
    const Plate& mover = plates[static_cast<size_t>(joint.mover)];
    const Plate& other = plates[static_cast<size_t>(joint.other)];
    std::string said = geometry::plateName(mover) + " and " + geometry::plateName(other);
    if (largest >= 0) {
      const PlateContact& contact = graph.contacts[static_cast<size_t>(largest)];
      const Vec3& axisMover = graph.thicknessAxis[static_cast<size_t>(joint.mover)];
      const Vec3& axisOther = graph.thicknessAxis[static_cast<size_t>(joint.other)];
      said += ": " + howTheyMeet(contact, axisMover, axisOther) + ", their planes " +
              degrees(degreesBetweenLines(axisMover, axisOther)) + " apart, " + geometry::plateName(mover) +
              " leaving at " + degrees(degreesBetweenLines(contact.edgeDirection, joint.direction)) + " to their " +
              (contact.crossing ? "crossing line" : "edge");
      // Tenons leave their mortises across the face they stand on (square to it), slides along the edge.
      if (!contact.crossing)
        said += " and " + degrees(degreesBetweenLines(contact.normal, joint.direction)) + " to the contact's normal";
      said += slantedTenonElsewhere(graph, largest, joint, options);
      said += std::string(" (the plan's ") + jointTypeName(joint.type) + ")";
    }
    missing.push_back(said);
  }
  return missing;
}

std::string jointsNothingMakesSentence(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                       const std::vector<PlateJoint>& planned, const JointCutOptions& options,
                                       size_t shown) {
  const std::vector<std::string> missing = jointsNothingMakes(plates, contacts, planned, options);
  if (missing.empty()) return "";
  size_t needed = 0;
  for (const PlateJoint& joint : planned) needed += joint.type == JointType::Empty ? 0 : 1;
  std::string sentence = "no joint that can be cut or milled for " + std::to_string(missing.size()) +
                         " of the plan's " + std::to_string(needed) + " joints: ";
  for (size_t k = 0; k < missing.size() && k < shown; ++k) sentence += (k ? "; " : "") + missing[k];
  if (missing.size() > shown) sentence += "; and " + std::to_string(missing.size() - shown) + " more";
  return sentence;
}

}  // namespace desia
