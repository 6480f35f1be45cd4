// SPDX-License-Identifier: GPL-3.0-or-later
// A plane with a 2D frame in it, and the integer coordinates Clipper works on: shared by the plate
// geometry (contacts) and the joint cuts.
#pragma once

#include <polyclipping/clipper.hpp>

#include <cmath>

#include "analysis/vec3.h"
#include "desia/plate.h"

namespace desia {

// Clipper works on integers: 1e-4 mm steps, far below any tolerance, far from its range limit.
constexpr double kClipperScale = 1e4;

// A plane through `origin` with unit normal `normal`, and a 2D frame (u, v) in it.
struct PlaneFrame {
  Vec3 origin, normal, u, v;
  explicit PlaneFrame(const Vec3& origin_, const Vec3& normal_) : origin(origin_), normal(normalized(normal_)) {
    const Vec3 axis = std::abs(normal[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u = normalized(cross(normal, axis));
    v = cross(normal, u);
  }
  Vec3 offset(const Vec3& p) const { return {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]}; }
  ClipperLib::IntPoint toClipper(const Vec3& p) const {
    const Vec3 d = offset(p);
    return {static_cast<ClipperLib::cInt>(std::llround(dot(d, u) * kClipperScale)),
            static_cast<ClipperLib::cInt>(std::llround(dot(d, v) * kClipperScale))};
  }
  Vec3 fromClipper(const ClipperLib::IntPoint& p) const {
    const double x = static_cast<double>(p.X) / kClipperScale, y = static_cast<double>(p.Y) / kClipperScale;
    return {origin[0] + u[0] * x + v[0] * y, origin[1] + u[1] * x + v[1] * y, origin[2] + u[2] * x + v[2] * y};
  }
};

// A loop, or loops, in a frame's integer coordinates (their offsets along the normal dropped).
inline ClipperLib::Path clipperPath(const Loop& loop, const PlaneFrame& frame) {
  ClipperLib::Path path;
  for (const Vec3& p : loop) path.push_back(frame.toClipper(p));
  return path;
}

inline ClipperLib::Paths clipperPaths(const std::vector<Loop>& loops, const PlaneFrame& frame) {
  ClipperLib::Paths paths;
  for (const Loop& loop : loops) paths.push_back(clipperPath(loop, frame));
  return paths;
}

}  // namespace desia
