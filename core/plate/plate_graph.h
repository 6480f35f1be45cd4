// SPDX-License-Identifier: GPL-3.0-or-later
// The parts-graph of a plate structure as the joint planner reads it (paper Section 5.2): who
// touches whom, along which edge, through which contacts.
#pragma once

#include <vector>

#include "desia/plate.h"

namespace desia {

struct PlateGraph {
  int plateCount = 0;
  std::vector<std::vector<int>> neighbours;  // sorted plate indices
  std::vector<std::vector<Vec3>> edgeTo;     // edgeTo[p][k]: edge direction shared with neighbours[p][k]
  std::vector<std::vector<int>> contactsOf;  // contact indices per plate
  // The contacts, for milled joints with their normals made square to their shared edges (see
  // buildPlateGraph); `computedContacts` as computePlateContacts gave them (the same indices):
  // the edge joints' sites (tenons, dovetails) are found on those.
  std::vector<PlateContact> contacts;
  std::vector<PlateContact> computedContacts;
  std::vector<Vec3> thicknessAxis;
  std::vector<Plate> plates;  // the plates as given
};

PlateGraph buildPlateGraph(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                           JointRealization realization);

// Two unit vectors within about half a degree count as parallel (edge vectors of one design).
bool parallel(const Vec3& a, const Vec3& b);

// The crossing between two plates (an index into the contacts), or -1.
int crossingBetween(const PlateGraph& graph, int p, int q);

// Can `plate` leave each plate in `others` along d without pushing into it (its contact faces)?
bool leavesWithoutPushing(const PlateGraph& graph, int plate, const std::vector<bool>& inOthers, const Vec3& d);

}  // namespace desia
