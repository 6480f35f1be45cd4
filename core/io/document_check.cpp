// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/document_check.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/frame.h"
#include "desia/frame_design.h"
#include "desia/frame_format.h"
#include "desia/plate_design.h"

namespace desia {
namespace {

using nlohmann::json;

// The planned directions of a plate result's `removal`: part k + 1 leaves along the k-th; the
// last part stays (null). Plates are numbered in removal order by the designer.
std::vector<Vec3> plateRemovalDirections(const json& removal, size_t plates) {
  const std::string where = "removal";
  if (!removal.is_array() || removal.size() != plates) {
    throwBadInput("", where + ": expected one entry per plate (" + std::to_string(plates) + ")");
  }
  std::vector<Vec3> directions;
  for (size_t k = 0; k + 1 < removal.size(); ++k) {
    const json& entry = removal[k];
    const std::string path = where + "[" + std::to_string(k) + "]";
    if (!entry.is_object() || !entry.contains("part") || entry["part"] != static_cast<int>(k) + 1) {
      throwBadInput("", path + ": expected part " + std::to_string(k + 1) + " (parts leave in id order)");
    }
    const json& d = entry.contains("direction") ? entry["direction"] : json();
    if (!d.is_array() || d.size() != 3 || !d[0].is_number() || !d[1].is_number() || !d[2].is_number()) {
      throwBadInput("", path + ".direction: expected [x, y, z], found " + d.dump());
    }
    Vec3 v{d[0].get<double>(), d[1].get<double>(), d[2].get<double>()};
    const double length = std::sqrt(dot(v, v));
    if (!(length > 1e-9) || !std::isfinite(length)) throwBadInput("", path + ".direction: not a direction");
    directions.push_back(scaled(v, 1 / length));
  }
  return directions;
}

std::optional<ShapeRemovalCheck> plateShapeRemoval(const AssemblyDocument& document, const json& geometry) {
  const std::string realization = geometry.value("jointGeometry", "");
  if (!geometry.contains("removal") || (realization != "cut" && realization != "milled")) return std::nullopt;
  std::vector<Plate> inOrder;  // plates by part id = removal order
  for (const Part& part : document.assembly.parts) {
    for (const Plate& plate : document.plates) {
      if (plate.id == part.id) inOrder.push_back(plate);
    }
  }
  if (inOrder.size() != document.assembly.parts.size()) return std::nullopt;
  ShapeRemovalCheck check;
  check.checked =
      "contacts recomputed from the jointed plates (dbg and lp, key = part 1), and each plate swept along its "
      "direction in the planned order";
  check.failure = jointedPlatesFailure(inOrder, plateRemovalDirections(geometry["removal"], inOrder.size()),
                                       document.plateOptions);
  return check;
}

std::optional<ShapeRemovalCheck> frameShapeRemoval(const AssemblyDocument& document) {
  const FrameDocument frame = frameFromAssemblyDocument(document);
  if (frame.labels.empty() || frame.directions.empty()) return std::nullopt;
  ShapeRemovalCheck check;
  check.checked = "each beam, its body and joint voxels, swept along its axis in the planned order";
  std::vector<bool> present(frame.layout.frame.beams.size(), true);
  for (size_t k = 0; k < frame.directions.size() && k < frame.order.size(); ++k) {
    const int beam = frame.order[k];
    const std::string obstacle = frameSweepObstacle(frame.layout, frame.labels, beam, frame.directions[k], present);
    if (!obstacle.empty()) {
      check.failure = "beam " + std::to_string(frame.layout.frame.beams[beam].id) + " cannot leave along " +
                      directionLabel(frame.directions[k]) + ": it hits " + obstacle;
      break;
    }
    present[beam] = false;
  }
  return check;
}

}  // namespace

CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options) {
  CheckReport report = checkAssembly(document, options);
  if (document.kind == AssemblyKind::Plate && !document.plates.empty() && !document.geometryJson.empty()) {
    report.shapeRemoval = plateShapeRemoval(document, json::parse(document.geometryJson));
  } else if (document.kind == AssemblyKind::Frame && document.contactsFromGeometry) {
    report.shapeRemoval = frameShapeRemoval(document);
  }
  return report;
}

bool checkPassed(const CheckReport& report) {
  return report.result.verdict == Verdict::Interlocking && (!report.shapeRemoval || report.shapeRemoval->failure.empty());
}

}  // namespace desia
