// SPDX-License-Identifier: GPL-3.0-or-later
// Plates snapped to their design on reading (regularizedPlates in desia/plate.h).
#include "desia/plate.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/normal_classes.h"

namespace desia {

namespace {

struct Plane {
  Vec3 normal;
  double offset = 0;  // normal·p for p on the plane
};

// Where the planes of one solid (a plate or an attached solid) sit in the list of all planes:
// its two faces, then for loop k of its faces, side i (joining vertices i and i+1).
struct SolidPlanes {
  size_t first = 0;
  std::vector<size_t> loopStart;  // the index of loop k's first side
};

Vec3 quadNormal(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return loopNormal(Loop{a, b, c, d});
}

// The planes' normals of one solid, appended to `normals` (unnormalised lengths are areas; a zero
// one makes the solid unsnappable).
SolidPlanes collectNormals(const Plate& solid, std::vector<Vec3>* normals, bool* degenerate) {
  SolidPlanes planes;
  planes.first = normals->size();
  normals->push_back(loopNormal(solid.bottom[0]));
  normals->push_back(loopNormal(solid.top[0]));
  for (size_t k = 0; k < solid.bottom.size(); ++k) {
    planes.loopStart.push_back(normals->size());
    const Loop& b = solid.bottom[k];
    const Loop& t = solid.top[k];
    for (size_t i = 0; i < b.size(); ++i) {
      const size_t j = (i + 1) % b.size();
      normals->push_back(quadNormal(b[i], b[j], t[j], t[i]));
    }
  }
  for (size_t k = planes.first; k < normals->size(); ++k) {
    if (!(norm((*normals)[k]) > tolerance::kNoTwiceAreaMm2)) *degenerate = true;
  }
  return planes;
}

double meanOffset(const Vec3& normal, const std::vector<Vec3>& points) {
  double sum = 0;
  for (const Vec3& p : points) sum += dot(normal, p);
  return sum / static_cast<double>(points.size());
}

// The point on planes p, q and r (Cramer's rule), or none when they do not meet in one point.
std::optional<Vec3> crossingOf(const Plane& p, const Plane& q, const Plane& r) {
  const Vec3 qr = cross(q.normal, r.normal);
  const double det = dot(p.normal, qr);
  if (std::abs(det) < tolerance::kDirection) return std::nullopt;
  const Vec3 sum = plus(plus(scaled(qr, p.offset), scaled(cross(r.normal, p.normal), q.offset)),
                        scaled(cross(p.normal, q.normal), r.offset));
  return scaled(sum, 1 / det);
}

// The point of planes p and q nearest `near` (their line is p ∩ q; p and q not parallel).
std::optional<Vec3> nearestOnLine(const Plane& p, const Plane& q, const Vec3& near) {
  const Vec3 along = cross(p.normal, q.normal);
  if (norm(along) < tolerance::kDirection) return std::nullopt;
  const Plane through{normalized(along), dot(normalized(along), near)};
  return crossingOf(p, q, through);
}

// Vertex i of a face's loop: on the face's plane and the planes of sides i-1 and i, or, where
// those sides are within kStraightSideSine of parallel (a straight edge drawn in two pieces, a fine curve),
// the point of the face and side i nearest the vertex given: their crossing would move the vertex
// by the planes' rounding over the angle between them.
std::optional<Vec3> snappedVertex(const Plane& face, const Plane& before, const Plane& after, const Vec3& given) {
  if (norm(cross(before.normal, after.normal)) < tolerance::kStraightSideSine) return nearestOnLine(face, after, given);
  return crossingOf(face, before, after);
}

// How far a vertex may move (tolerance::kLargestVertexSnapMm); more is a shape no plane fits.
double largestSnap(const PlateOptions& options) {
  return std::min(options.contactTolerance, tolerance::kLargestVertexSnapMm);
}

// The solid with its vertices on the snapped planes, or none when one would move further than
// `tolerance` or not be found.
std::optional<Plate> snappedSolid(const Plate& solid, const SolidPlanes& at, const std::vector<Vec3>& normals,
                                  double tolerance) {
  Plate snapped = solid;
  snapped.attached.clear();
  const Plane bottom{normals[at.first], meanOffset(normals[at.first], solid.bottom[0])};
  const Plane top{normals[at.first + 1], meanOffset(normals[at.first + 1], solid.top[0])};
  for (size_t k = 0; k < solid.bottom.size(); ++k) {
    const Loop& b = solid.bottom[k];
    const Loop& t = solid.top[k];
    const size_t n = b.size();
    std::vector<Plane> sides;
    for (size_t i = 0; i < n; ++i) {
      const Vec3& normal = normals[at.loopStart[k] + i];
      sides.push_back({normal, meanOffset(normal, {b[i], b[(i + 1) % n], t[(i + 1) % n], t[i]})});
    }
    for (size_t i = 0; i < n; ++i) {
      const Plane& before = sides[(i + n - 1) % n];
      const std::optional<Vec3> onBottom = snappedVertex(bottom, before, sides[i], b[i]);
      const std::optional<Vec3> onTop = snappedVertex(top, before, sides[i], t[i]);
      if (!onBottom || !onTop || norm(minus(*onBottom, b[i])) > tolerance || norm(minus(*onTop, t[i])) > tolerance)
        return std::nullopt;
      snapped.bottom[k][i] = *onBottom;
      snapped.top[k][i] = *onTop;
    }
  }
  return snapped;
}

// A snapped solid that validatePlates refuses where the given one passed: jointed plates have
// cuts that end exactly on another edge (a notch at a mitre's corner), which a move of 1e-12 mm
// turns into a crossing. Such a solid keeps its given vertices.
bool stillValid(const Plate& solid, const PlateOptions& options) {
  try {
    validatePlates({solid}, options, "");
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

std::vector<Plate> regularizedPlates(const std::vector<Plate>& plates, const PlateOptions& options, PlateOrigin origin) {
  // Every solid's planes, all plates at once: parallel faces of different plates become one normal.
  std::vector<const Plate*> solids;
  for (const Plate& plate : plates) {
    solids.push_back(&plate);
    for (const Plate& attached : plate.attached) solids.push_back(&attached);
  }
  std::vector<Vec3> normals;
  std::vector<SolidPlanes> planes;
  std::vector<bool> degenerate(solids.size(), false);
  for (size_t s = 0; s < solids.size(); ++s) {
    bool bad = solids[s]->bottom.empty() || solids[s]->top.size() != solids[s]->bottom.size();
    for (size_t k = 0; !bad && k < solids[s]->bottom.size(); ++k)
      bad = solids[s]->bottom[k].size() < 3 || solids[s]->top[k].size() != solids[s]->bottom[k].size();
    degenerate[s] = bad;
    planes.push_back(bad ? SolidPlanes{} : collectNormals(*solids[s], &normals, &bad));
    degenerate[s] = bad;
  }
  for (Vec3& n : normals) n = norm(n) > 0 ? normalized(n) : n;
  const std::vector<Vec3> snapped = snappedDirections(
      normals, origin == PlateOrigin::Drawn ? tolerance::kDrawnDirectionRad : tolerance::kComputedDirectionRad);
  std::vector<Plate> result;
  size_t s = 0;
  for (const Plate& plate : plates) {
    const auto snappedOrGiven = [&](const Plate& solid) {
      std::optional<Plate> snappedOne;
      if (!degenerate[s]) snappedOne = snappedSolid(solid, planes[s], snapped, largestSnap(options));
      if (snappedOne && !stillValid(*snappedOne, options)) snappedOne.reset();
      ++s;
      if (snappedOne) return *snappedOne;
      Plate given = solid;
      given.attached.clear();
      return given;
    };
    Plate out = snappedOrGiven(plate);
    for (const Plate& attached : plate.attached) out.attached.push_back(snappedOrGiven(attached));
    result.push_back(std::move(out));
  }
  return result;
}

}  // namespace desia
