// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/plate_graph.h"

#include <algorithm>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

bool parallel(const Vec3& a, const Vec3& b) { return norm(cross(a, b)) < tolerance::kPlannedParallelSine; }

PlateGraph buildPlateGraph(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                           JointRealization realization) {
  PlateGraph graph;
  graph.plateCount = static_cast<int>(plates.size());
  graph.contacts = contacts;
  // A contact's face holds its shared edge (the plates' planes' crossing line, exact to rounding of
  // doubles): its normal, computed from the face's vertices, is made exactly square to it. In a
  // design given to a micrometre they disagree by 1e-9, and a plate sliding along the edge (a
  // milled slide) would push into the face by more than the blocking tests' tolerance::kDirection.
  // Only for milled joints: it splits normals that were one into many 1e-9 apart, whose extra base
  // directions a planned design would pay for in time.
  for (PlateContact& contact : graph.contacts) {
    if (realization != JointRealization::Milled) break;
    if (contact.crossing || norm(contact.edgeDirection) == 0) continue;
    const Vec3 squared = minus(contact.normal, scaled(contact.edgeDirection, dot(contact.normal, contact.edgeDirection)));
    if (norm(squared) > 0.5) contact.normal = normalized(squared);
  }
  graph.neighbours.resize(plates.size());
  graph.contactsOf.resize(plates.size());
  for (size_t c = 0; c < contacts.size(); ++c) {
    graph.contactsOf[contacts[c].a].push_back(static_cast<int>(c));
    graph.contactsOf[contacts[c].b].push_back(static_cast<int>(c));
    graph.neighbours[contacts[c].a].push_back(contacts[c].b);
    graph.neighbours[contacts[c].b].push_back(contacts[c].a);
  }
  graph.edgeTo.resize(plates.size());
  for (int p = 0; p < graph.plateCount; ++p) {
    auto& list = graph.neighbours[p];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (int q : list) {
      // The edge of the pair's largest contact.
      const PlateContact* best = nullptr;
      for (int c : graph.contactsOf[p]) {
        const PlateContact& contact = contacts[c];
        if ((contact.a == q || contact.b == q) && (!best || contact.area > best->area)) best = &contact;
      }
      graph.edgeTo[p].push_back(best->edgeDirection);
    }
  }
  for (const Plate& plate : plates) graph.thicknessAxis.push_back(plateThicknessAxis(plate));
  graph.plates = plates;
  graph.computedContacts = contacts;
  return graph;
}

int crossingBetween(const PlateGraph& graph, int p, int q) {
  for (int c : graph.contactsOf[p]) {
    const PlateContact& contact = graph.contacts[c];
    if (contact.crossing && (contact.a == q || contact.b == q)) return c;
  }
  return -1;
}

bool leavesWithoutPushing(const PlateGraph& graph, int plate, const std::vector<bool>& inOthers, const Vec3& d) {
  for (int c : graph.contactsOf[plate]) {
    const PlateContact& contact = graph.contacts[c];
    const int other = contact.a == plate ? contact.b : contact.a;
    if (!inOthers[other]) continue;
    const double push = dot(d, contact.a == plate ? contact.normal : negated(contact.normal));
    if (push > tolerance::kDirection) return false;
  }
  return true;
}

}  // namespace desia
