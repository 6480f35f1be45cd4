// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/exact_vertices.h"

#include <cmath>

#include "desia/tolerances.h"

namespace desia {
namespace {

// A result vertex lies on an input edge within Clipper's rounding (half a grid step per
// coordinate, and the crossings it computes): two steps is generous and still 0.2 µm.
constexpr double kOnEdge = 2.0 / kClipperScale;

}  // namespace

// The loops given may lie off the frame's plane (cut loops of the other face): their points are
// taken in it, as Clipper takes them.
Vec3 ExactVertices::inPlane(double x, double y) const {
  return plus(frame_.origin, plus(scaled(frame_.u, x), scaled(frame_.v, y)));
}

ExactVertices::ExactVertices(const PlaneFrame& frame, const std::vector<const std::vector<Loop>*>& inputs)
    : frame_(frame) {
  for (const std::vector<Loop>* loops : inputs) {
    for (const Loop& loop : *loops) {
      for (size_t k = 0; k < loop.size(); ++k) {
        const Vec3& a = loop[k];
        const Vec3& b = loop[(k + 1) % loop.size()];
        const ClipperLib::IntPoint rounded = frame.toClipper(a);
        const Vec3 da = frame.offset(a), db = frame.offset(b);
        const Edge edge{dot(da, frame.u), dot(da, frame.v), dot(db, frame.u), dot(db, frame.v)};
        vertices_.emplace(std::make_pair(rounded.X, rounded.Y), inPlane(edge.x0, edge.y0));
        edges_.push_back(edge);
      }
    }
  }
}

Vec3 ExactVertices::at(const ClipperLib::IntPoint& point) const {
  const auto known = vertices_.find({point.X, point.Y});
  if (known != vertices_.end()) return known->second;
  const double x = static_cast<double>(point.X) / kClipperScale, y = static_cast<double>(point.Y) / kClipperScale;
  // The input edges through the point.
  std::vector<const Edge*> through;
  for (const Edge& edge : edges_) {
    const double ex = edge.x1 - edge.x0, ey = edge.y1 - edge.y0, length = std::hypot(ex, ey);
    if (length < kOnEdge) continue;
    const double along = ((x - edge.x0) * ex + (y - edge.y0) * ey) / length;
    const double off = ((x - edge.x0) * ey - (y - edge.y0) * ex) / length;
    if (std::abs(off) <= kOnEdge && along >= -kOnEdge && along <= length + kOnEdge) through.push_back(&edge);
  }
  // The crossing of the two least parallel of them, on the first one's exact segment.
  const Edge* first = nullptr;
  const Edge* second = nullptr;
  double best = 0;
  for (size_t i = 0; i < through.size(); ++i) {
    for (size_t j = i + 1; j < through.size(); ++j) {
      const Edge& p = *through[i];
      const Edge& q = *through[j];
      const double px = p.x1 - p.x0, py = p.y1 - p.y0, qx = q.x1 - q.x0, qy = q.y1 - q.y0;
      const double sine = std::abs(px * qy - py * qx) / (std::hypot(px, py) * std::hypot(qx, qy));
      if (sine > best) {
        best = sine;
        first = &p;
        second = &q;
      }
    }
  }
  if (first == nullptr || best < tolerance::kEdgeCrossingSine) return frame_.fromClipper(point);
  const double px = first->x1 - first->x0, py = first->y1 - first->y0;
  const double qx = second->x1 - second->x0, qy = second->y1 - second->y0;
  const double t = ((second->x0 - first->x0) * qy - (second->y0 - first->y0) * qx) / (px * qy - py * qx);
  const double cx = first->x0 + t * px, cy = first->y0 + t * py;
  // Keep the rounded point if the crossing is not where Clipper put it (edges that only pass near).
  if (std::hypot(cx - x, cy - y) > kOnEdge) return frame_.fromClipper(point);
  return inPlane(cx, cy);
}

Loop ExactVertices::loop(const ClipperLib::Path& path) const {
  Loop result;
  result.reserve(path.size());
  for (const ClipperLib::IntPoint& point : path) result.push_back(at(point));
  return result;
}

std::vector<Loop> ExactVertices::loops(const ClipperLib::Paths& paths) const {
  std::vector<Loop> result;
  result.reserve(paths.size());
  for (const ClipperLib::Path& path : paths) result.push_back(loop(path));
  return result;
}

}  // namespace desia
