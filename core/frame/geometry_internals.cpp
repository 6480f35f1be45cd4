// SPDX-License-Identifier: GPL-3.0-or-later
#include "frame/geometry_internals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace desia::frame_geometry {

Aabb boxBounds(const OrientedBox& box) {
  Aabb bounds;
  for (int k = 0; k < 3; ++k) {
    double r = 0;
    for (int i = 0; i < 3; ++i) r += box.halfExtents[i] * std::abs(box.axes[i][k]);
    bounds.lo[k] = box.centre[k] - r;
    bounds.hi[k] = box.centre[k] + r;
  }
  return bounds;
}

bool boundsOverlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] <= b.lo[k] || b.hi[k] <= a.lo[k]) return false;
  }
  return true;
}

Aabb sweptBounds(Aabb bounds, const Vec3& direction) {
  for (int k = 0; k < 3; ++k) {
    if (direction[k] > 0) bounds.hi[k] = std::numeric_limits<double>::infinity();
    if (direction[k] < 0) bounds.lo[k] = -std::numeric_limits<double>::infinity();
  }
  return bounds;
}

Aabb cubeBounds(const FrameLayout& layout, int joint) {
  const double half = layout.frame.jointSize / 2;
  const Vec3& p = layout.frame.joints[joint].position;
  return {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}};
}

OrientedBox boxFromBounds(const Aabb& bounds) {
  OrientedBox box;
  for (int k = 0; k < 3; ++k) {
    box.centre[k] = (bounds.lo[k] + bounds.hi[k]) / 2;
    box.halfExtents[k] = (bounds.hi[k] - bounds.lo[k]) / 2;
  }
  return box;
}

void include(Aabb& bounds, const Aabb& more) {
  for (int k = 0; k < 3; ++k) {
    bounds.lo[k] = std::min(bounds.lo[k], more.lo[k]);
    bounds.hi[k] = std::max(bounds.hi[k], more.hi[k]);
  }
}

OrientedBox segmentBox(const Vec3& a, const Vec3& b, double section) {
  OrientedBox box;
  const Vec3 along = minus(b, a);
  const double length = norm(along);
  box.axes[0] = scaled(along, 1.0 / length);
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(box.axes[0][k]) < std::abs(box.axes[0][least])) least = k;
  }
  Vec3 axis{0, 0, 0};
  axis[least] = 1;
  box.axes[1] = normalized(cross(box.axes[0], axis));
  box.axes[2] = cross(box.axes[0], box.axes[1]);
  box.centre = scaled(plus(a, b), 0.5);
  box.halfExtents = {length / 2 + section / 2, section / 2, section / 2};
  return box;
}

std::string beamName(const Frame& frame, int beam) { return "beam " + std::to_string(frame.beams[beam].id); }
std::string jointName(const Frame& frame, int joint) { return "joint " + std::to_string(frame.joints[joint].id); }

}  // namespace desia::frame_geometry
