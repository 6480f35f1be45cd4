// SPDX-License-Identifier: GPL-3.0-or-later
// Clipper's results back in exact coordinates. Clipper rounds every vertex to its 1e-4 mm grid,
// which turns a short cut face on a sloped edge by up to 1e-5 rad. The blocking tests count a
// contact as blocking a direction when d·n > tolerance::kDirection (README "Verdicts on computed
// normals"), so such a turned face blocks a plate that slides along it in the design. Every vertex
// of a boolean's result is an input vertex or the crossing of two input edges: it is recomputed
// from those in doubles.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "plate/plane_frame.h"

namespace desia {

class ExactVertices {
 public:
  // The loops given to the boolean (all of them, subject and clip), in `frame`'s plane.
  ExactVertices(const PlaneFrame& frame, const std::vector<const std::vector<Loop>*>& inputs);

  // The exact point a result vertex stands for: the input vertex it rounds from, else the
  // crossing of the two least parallel input edges through it, else the rounded point itself.
  Vec3 at(const ClipperLib::IntPoint& point) const;
  Loop loop(const ClipperLib::Path& path) const;
  std::vector<Loop> loops(const ClipperLib::Paths& paths) const;

 private:
  struct Edge {
    double x0, y0, x1, y1;  // in the frame, unrounded
  };
  Vec3 inPlane(double x, double y) const;
  const PlaneFrame& frame_;
  std::map<std::pair<ClipperLib::cInt, ClipperLib::cInt>, Vec3> vertices_;
  std::vector<Edge> edges_;
};

}  // namespace desia
