// SPDX-License-Identifier: GPL-3.0-or-later
// One verification of a plate plan, for the designer (before it reports a plan) and for `desia
// check` (of a result file) alike: the same function on the same data in the same order (the
// plates in removal order), so that what one accepts the other accepts.
#include "plate/plate_verification.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/plan_squaring.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"
#include "plate/swept_collision.h"

namespace desia {

namespace {

// The contact that stops `part` leaving along d, the most against d (isPartFreeAlong's test), named
// with the plate it is with, its normal out of `part`, its area and how far it faces against d.
std::string blockingContactText(const Assembly& model, const std::vector<bool>& present, int part, const Vec3& d) {
  const Contact* worst = nullptr;
  double against = 0;
  for (const Contact& contact : model.contacts) {
    if (!present[contact.a] || !present[contact.b] || (contact.a != part && contact.b != part)) continue;
    const double into = contact.a == part ? dot(d, contact.normal) : -dot(d, contact.normal);
    if (into > tolerance::kDirection && into > against) {
      against = into;
      worst = &contact;
    }
  }
  if (!worst) return "";
  const int other = worst->a == part ? worst->b : worst->a;
  const Vec3 normal = worst->a == part ? worst->normal : negated(worst->normal);
  char text[160];
  std::snprintf(text, sizeof text, ": its contact with plate %d (%.4g mm^2, normal %s) faces %.3g degrees against it",
                model.parts[other].id, worst->area, directionLabel(normal).c_str(),
                std::asin(std::min(1.0, against)) * 180 / M_PI);
  return text;
}

}  // namespace

std::string planFailure(const Assembly& model, const std::vector<Vec3>& directions) {
  const std::vector<BaseDirection> bases = computeBaseDirections(model);
  const InterlockingResult byGraphs = testInterlockingByGraphs(model, bases);
  if (byGraphs.verdict != Verdict::Interlocking || byGraphs.key != 0) return "dbg: " + byGraphs.reason;
  const InterlockingResult byInequalities = testInterlockingByInequalities(model, bases);
  if (byInequalities.verdict != Verdict::Interlocking || byInequalities.key != 0) return "lp: " + byInequalities.reason;
  std::vector<bool> present(model.partCount(), true);
  for (size_t k = 0; k < directions.size(); ++k) {
    if (!isPartFreeAlong(model, &present, static_cast<int>(k), directions[k])) {
      return "plate " + std::to_string(model.parts[k].id) + " cannot leave along its direction" +
             blockingContactText(model, present, static_cast<int>(k), directions[k]);
    }
    present[k] = false;
  }
  return "";
}

// Each plate in turn, along its direction, against every plate after it in the order: the first
// one it runs into (the earliest in the order) is named. Only plates whose bounds reach into the
// region its bounds sweep are tried (SweptBoxIndex): comparing every pair was quadratic.
std::string sweepFailure(const std::vector<Plate>& plates, const std::vector<int>& order,
                         const std::vector<Vec3>& directions, double tolerance, int* hitPosition,
                         const std::vector<std::pair<int, int>>& skip) {
  if (hitPosition) *hitPosition = -1;
  std::vector<TriangleMesh> meshes;
  for (const Plate& plate : plates) meshes.push_back(plateMesh(plate));
  const SweptBoxIndex index(meshes);
  std::vector<int> positionOf(plates.size(), -1);
  for (size_t k = 0; k < order.size(); ++k) positionOf[order[k]] = static_cast<int>(k);
  const auto skipped = [&](int a, int b) {
    return std::find(skip.begin(), skip.end(), std::make_pair(std::min(a, b), std::max(a, b))) != skip.end();
  };
  for (size_t k = 0; k < directions.size(); ++k) {
    int first = -1;  // the earliest position after k of a plate it runs into
    index.anyInTheWay(order[k], directions[k], tolerance, [&](int q) {
      const int j = positionOf[q];
      if (j <= static_cast<int>(k) || (first >= 0 && j >= first) || skipped(static_cast<int>(k), j)) return false;
      if (meshCollidesAlong(meshes[order[k]], meshes[q], directions[k], tolerance)) first = j;
      return false;
    });
    if (first >= 0) {
      if (hitPosition) *hitPosition = first;
      return "plate " + std::to_string(plates[order[k]].id) + " runs into plate " + std::to_string(plates[order[first]].id) +
             " when it leaves";
    }
  }
  return "";
}

namespace {

std::vector<int> identityOrder(size_t count) {
  std::vector<int> order(count);
  for (size_t k = 0; k < count; ++k) order[k] = static_cast<int>(k);
  return order;
}

std::string directionCountFailure(size_t plates, size_t directions) {
  if (plates < 2 || directions + 1 != plates) return "every plate but the last needs a removal direction";
  return "";
}

}  // namespace

PlateRemovalVerification verifyJointedPlates(const std::vector<Plate>& plates, const std::vector<Vec3>& directions,
                                             const PlateOptions& geometry) {
  PlateRemovalVerification verification;
  verification.failure = directionCountFailure(plates.size(), directions.size());
  if (!verification.failure.empty()) return verification;
  std::vector<Part> parts;
  for (const Plate& plate : plates) parts.push_back({plate.id, plate.name});
  const std::vector<int> order = identityOrder(plates.size());
  verification.directions = directions;
  verification.assembly =
      jointedAssembly(computePlateContacts(plates, geometry), order, std::move(parts), &verification.directions);
  verification.failure = planFailure(verification.assembly, verification.directions);
  if (!verification.failure.empty()) return verification;
  verification.failure = sweepFailure(plates, order, verification.directions, geometry.contactTolerance,
                                      &verification.hitPosition);
  return verification;
}

PlateRemovalVerification verifyPlannedPlates(const Assembly& model, const std::vector<Plate>& plates,
                                             const std::vector<Vec3>& directions, const PlateOptions& geometry) {
  PlateRemovalVerification verification;
  verification.failure = directionCountFailure(plates.size(), directions.size());
  if (!verification.failure.empty()) return verification;
  verification.directions = directions;
  verification.assembly = squaredPlanAssembly(model, &verification.directions);
  verification.failure = planFailure(verification.assembly, verification.directions);
  if (!verification.failure.empty()) return verification;
  // Nothing is cut: plates that cross pass through each other until their slots are cut, so those
  // pairs are not swept; every other pair must part as the plates are.
  std::vector<std::pair<int, int>> crossing;
  for (const PlateContact& contact : computePlateContacts(plates, geometry)) {
    if (contact.crossing) crossing.push_back({std::min(contact.a, contact.b), std::max(contact.a, contact.b)});
  }
  verification.failure = sweepFailure(plates, identityOrder(plates.size()), verification.directions,
                                      geometry.contactTolerance, &verification.hitPosition, crossing);
  return verification;
}

namespace {

// A face's region (its outline less its holes) in `frame`'s integer coordinates.
ClipperLib::Paths faceArea(const std::vector<Loop>& loops, const PlaneFrame& frame) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(loops, frame), ClipperLib::ptSubject, true);
  ClipperLib::Paths region;
  clipper.Execute(ClipperLib::ctUnion, region, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  return region;
}

ClipperLib::Paths grown(const ClipperLib::Paths& region, double millimetres) {
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(region, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths result;
  offset.Execute(result, millimetres * kClipperScale);
  return result;
}

// The area (mm^2) of `region` outside `container`.
double areaOutside(const ClipperLib::Paths& region, const ClipperLib::Paths& container) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(region, ClipperLib::ptSubject, true);
  clipper.AddPaths(container, ClipperLib::ptClip, true);
  ClipperLib::Paths outside;
  clipper.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  for (const ClipperLib::Path& path : outside) area += std::abs(ClipperLib::Area(path));
  return area / (kClipperScale * kClipperScale);
}

// Why the fabrication prism `made` is not `verified` with at most `clearance` of wood taken off
// its sides, or "": the same two face planes, `made`'s faces within `verified`'s (to the contact
// tolerance) and `verified`'s within `made`'s grown by the clearance.
std::string prismFailure(const Plate& verified, const Plate& made, double clearance, double tolerance) {
  const Vec3 axis = plateThicknessAxis(verified);
  const PlaneFrame frame(verified.bottom[0][0], axis);
  const double madeAxis = norm(cross(plateThicknessAxis(made), axis));
  const double firstPlane = std::abs(dot(frame.offset(made.bottom[0][0]), axis));
  const double secondPlane = std::abs(plateThickness(made) - plateThickness(verified));
  if (!(madeAxis < tolerance::kParallelSine) || !(firstPlane <= tolerance) || !(secondPlane <= tolerance))
    return "its faces are not the verified plate's";
  const double sliver = tolerance::kOutlineSliverMm2;
  for (const std::vector<Loop>* face : {&verified.bottom, &verified.top}) {
    const std::vector<Loop>& madeFace = face == &verified.bottom ? made.bottom : made.top;
    const ClipperLib::Paths verifiedArea = faceArea(*face, frame), madeArea = faceArea(madeFace, frame);
    if (areaOutside(madeArea, grown(verifiedArea, tolerance)) > sliver) return "it has wood the verified plate does not";
    if (areaOutside(verifiedArea, grown(madeArea, clearance + tolerance)) > sliver) {
      return "it lacks wood of the verified plate beyond the clearance of " + std::to_string(clearance) + " mm";
    }
  }
  return "";
}

// The attached solid `made` within `clearance` of `verified` (their bounding boxes), or why not.
std::string attachedFailure(const Plate& verified, const Plate& made, double clearance, double tolerance) {
  const auto box = [](const Plate& solid) {
    std::array<Vec3, 2> b{Vec3{1e300, 1e300, 1e300}, Vec3{-1e300, -1e300, -1e300}};
    for (const std::vector<Loop>* face : {&solid.bottom, &solid.top}) {
      for (const Vec3& p : (*face)[0]) {
        for (int k = 0; k < 3; ++k) b[0][k] = std::min(b[0][k], p[k]), b[1][k] = std::max(b[1][k], p[k]);
      }
    }
    return b;
  };
  const std::array<Vec3, 2> v = box(verified), m = box(made);
  for (int k = 0; k < 3; ++k) {
    if (std::abs(v[0][k] - m[0][k]) > clearance + tolerance || std::abs(v[1][k] - m[1][k]) > clearance + tolerance) {
      return "an attached solid is not the verified one's";
    }
  }
  return "";
}

}  // namespace

std::string fabricationPlatesFailure(const std::vector<Plate>& plates, const std::vector<Plate>& fabrication,
                                     double clearance, const PlateOptions& geometry) {
  std::map<int, const Plate*> madeById;
  for (const Plate& plate : fabrication) madeById[plate.id] = &plate;
  for (const Plate& plate : plates) {
    const auto made = madeById.find(plate.id);
    const std::string which = "fabricationPlates: plate " + std::to_string(plate.id) + ": ";
    if (made == madeById.end()) return which + "missing";
    std::string failure = prismFailure(plate, *made->second, clearance, geometry.contactTolerance);
    if (failure.empty() && made->second->attached.size() != plate.attached.size()) {
      failure = "it has " + std::to_string(made->second->attached.size()) + " attached solids, the verified plate " +
                std::to_string(plate.attached.size());
    }
    for (size_t k = 0; failure.empty() && k < plate.attached.size(); ++k) {
      failure = attachedFailure(plate.attached[k], made->second->attached[k], clearance, geometry.contactTolerance);
    }
    if (!failure.empty()) return which + failure;
  }
  if (fabrication.size() != plates.size()) return "fabricationPlates: not one per plate";
  return "";
}

}  // namespace desia
