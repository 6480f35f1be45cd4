// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/joint_geometry.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

double areaOf(const ClipperLib::Paths& paths) {
  double area = 0;
  for (const ClipperLib::Path& path : paths) area += ClipperLib::Area(path);
  return std::abs(area) / (kClipperScale * kClipperScale);
}

// Area of the loops' region (non-zero) inside or outside `face` (its outline minus its holes).
double areaAgainst(const std::vector<Loop>& loops, const std::vector<Loop>& face, const PlaneFrame& frame,
                   bool outside) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(loops, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths(face, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths result;
  clipper.Execute(outside ? ClipperLib::ctDifference : ClipperLib::ctIntersection, result, ClipperLib::pftNonZero,
                  ClipperLib::pftEvenOdd);
  return areaOf(result);
}

std::pair<double, double> extentAlong(const Loop& region, const Vec3& origin, const Vec3& direction) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Vec3& p : region) {
    const double s = dot(minus(p, origin), direction);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return {lo, hi};
}

std::optional<int> touchingPartnerOf(const PlateContact& contact, int plate) {
  if (contact.crossing || (contact.a != plate && contact.b != plate)) return std::nullopt;
  return contact.a == plate ? contact.b : contact.a;
}

// How many of the two plates have a face on the contact: 0 where they meet edge to edge (a
// mitre), 2 where they lie face to face (a lap), 1 for an edge on a face (T and L joints).
int facesOnContact(const std::vector<Plate>& plates, const PlateContact& contact) {
  int faces = 0;
  for (int plate : {contact.a, contact.b})
    faces += std::abs(dot(contact.normal, plateThicknessAxis(plates[plate]))) > 1 - tolerance::kFacingCosine ? 1 : 0;
  return faces;
}

Plate solidOf(Loop first, Loop second) {
  if (dot(loopNormal(first), minus(second[0], first[0])) < 0) {
    std::reverse(first.begin(), first.end());
    std::reverse(second.begin(), second.end());
  }
  Plate solid;
  solid.bottom = {std::move(first)};
  solid.top = {std::move(second)};
  return solid;
}

}  // namespace desia
