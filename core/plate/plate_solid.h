// SPDX-License-Identifier: GPL-3.0-or-later
// A plate as a solid, as its geometry's checks see it (validation, crossings, contacts): its faces
// with their outward normals, its box, and how messages name it and its sizes.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "desia/plate.h"
#include "plate/plane_frame.h"

namespace desia {
namespace geometry {

// The mean of a loop's vertices.
Vec3 centroidOf(const Loop& loop);

// "plate 7 (shelf)": how messages name a plate.
std::string plateName(const Plate& plate);

// "0.123 mm" (3 significant digits), and with enough digits to tell apart values that differ by
// more than a micrometre.
std::string millimetres(double value);
std::string preciseMillimetres(double value);

// One planar face of a plate solid: its loops (outline and holes, or one side quad) and its
// outward unit normal.
struct SolidFace {
  std::vector<Loop> loops;
  Vec3 normal;
};

// The plate's faces: its first and second face, then its sides, loop by loop.
std::vector<SolidFace> solidFaces(const Plate& plate);

// How far the loops' vertices lie off the frame's plane, at most.
double maxDistanceToPlane(const std::vector<Loop>& loops, const PlaneFrame& frame);

// An axis-aligned box.
struct Box {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  bool touches(const Box& o, double tolerance) const {
    for (int k = 0; k < 3; ++k) {
      if (lo[k] > o.hi[k] + tolerance || o.lo[k] > hi[k] + tolerance) return false;
    }
    return true;
  }
};

Box boxOf(const Plate& plate);

}  // namespace geometry
}  // namespace desia
