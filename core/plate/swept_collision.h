// SPDX-License-Identifier: GPL-3.0-or-later
// The swept collision test of plate plans (paper Section 5.2: each plate must leave along its
// direction past the plates still in place): whether a solid moved along a direction by any
// distance passes through another.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "desia/model.h"
#include "desia/plate.h"
#include "plate/median_split_tree.h"

namespace desia {

// True when `mover`, moved along the unit direction d by any distance, would pass through
// `obstacle` (their interiors meet). Exact for the plates' polyhedra: two surface triangles whose
// shadows along d overlap with positive area, with the obstacle's triangle ahead, mean a collision.
bool plateCollidesAlong(const Plate& mover, const Plate& obstacle, const Vec3& d, double tolerance);
// The same for closed meshes (plateMesh of each plate, made once when many pairs are tested).
bool meshCollidesAlong(const TriangleMesh& mover, const TriangleMesh& obstacle, const Vec3& d, double tolerance);

// Axis-aligned bounds.
struct Box {
  Vec3 lo, hi;
};

// The bounds of many meshes in a tree (median splits, explicit stacks), asked which may stand in
// the way of one of them moving along a direction: those whose bounds reach into the region its
// bounds sweep (meshCollidesAlong's first test), found in O(log n + k) instead of by a look at
// every mesh (a long table of 9,998 plates: every plate's every way out against every plate).
class SweptBoxIndex {
 public:
  explicit SweptBoxIndex(const std::vector<TriangleMesh>& meshes);
  // Calls `visit` with each mesh other than `mover` that may stand in its way along d, until it
  // returns true; true if it did.
  bool anyInTheWay(int mover, const Vec3& d, double tolerance, const std::function<bool(int)>& visit) const;

 private:
  std::vector<Box> boxes_;
  std::vector<int> order_;
  std::vector<SplitTreeNode> nodes_;
};

}  // namespace desia
