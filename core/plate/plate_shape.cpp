// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/plate_shape.h"

#include <cmath>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/exact_vertices.h"
#include "plate/plane_frame.h"

namespace desia {

double plateThickness(const Plate& plate) {
  return std::abs(dot(minus(plate.top[0][0], plate.bottom[0][0]), plateThicknessAxis(plate)));
}

bool isPrism(const Plate& plate) {
  const Vec3 lift = scaled(plateThicknessAxis(plate), plateThickness(plate));
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    for (size_t k = 0; k < plate.bottom[l].size(); ++k) {
      if (norm(minus(plate.top[l][k], plus(plate.bottom[l][k], lift))) > tolerance::kPrismMm) return false;
    }
  }
  return true;
}

std::vector<Loop> faceRegion(const Plate& plate, ClipperLib::ClipType operation) {
  if (isPrism(plate)) return plate.bottom;
  const PlaneFrame frame(plate.bottom[0][0], plateThicknessAxis(plate));
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths(plate.top, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths region;
  clipper.Execute(operation, region, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  return ExactVertices(frame, {&plate.bottom, &plate.top}).loops(region);
}

Plate corePrism(const Plate& plate) {
  if (isPrism(plate)) return plate;
  Plate core;
  core.id = plate.id;
  core.name = plate.name;
  const Vec3 lift = scaled(plateThicknessAxis(plate), plateThickness(plate));
  for (const Loop& loop : faceRegion(plate, ClipperLib::ctIntersection)) {
    if (loop.size() < 3) continue;
    Loop top;
    for (const Vec3& p : loop) top.push_back(plus(p, lift));
    core.bottom.push_back(loop);
    core.top.push_back(top);
  }
  return core;
}

}  // namespace desia
