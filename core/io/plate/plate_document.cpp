// SPDX-License-Identifier: GPL-3.0-or-later
// The plates of a JSON document (docs/json-schema.md), read into millimetres: a plate design (its
// contacts computed from the geometry, paper Section 5.2) or a plan's plates. The document reader
// (io/json_document.cpp) reaches them through the full build's table (io/plate_frame_entries.cpp).
#include "io/plate/plate_document.h"

#include "desia/error.h"
#include "desia/plate.h"
#include "io/plate/plate_format.h"

namespace desia {
namespace {

using nlohmann::json;

// Millimetres per unit of a plate document's coordinates: "unit" is "mm" (the default), "cm", "m"
// or "in" (CAD tools export in any of them). Plates are read into millimetres, in which every
// tolerance and joint size is given, so a design in metres designs as the same design in mm.
double millimetresPerUnit(const json& root, const std::string& source) {
  if (!root.contains("unit")) return 1;
  const json& unit = root["unit"];
  if (unit == "mm") return 1;
  if (unit == "cm") return 10;
  if (unit == "m") return 1000;
  if (unit == "in") return 25.4;
  throwBadInput(source, "unit: expected \"mm\", \"cm\", \"m\" or \"in\", found " + unit.dump());
  return 1;
}

std::vector<Plate> scaledPlates(std::vector<Plate> plates, double factor) {
  if (factor == 1) return plates;
  const auto scaleSolid = [factor](Plate* solid) {
    for (std::vector<Loop>* face : {&solid->bottom, &solid->top}) {
      for (Loop& loop : *face) {
        for (Vec3& p : loop) p = {p[0] * factor, p[1] * factor, p[2] * factor};
      }
    }
  };
  for (Plate& plate : plates) {
    scaleSolid(&plate);
    for (Plate& attached : plate.attached) scaleSolid(&attached);
  }
  return plates;
}

}  // namespace

std::vector<Plate> readPlates(const json& root, const char* section, const std::string& source) {
  return scaledPlates(parsePlates(root[section], source), millimetresPerUnit(root, source));
}

std::vector<Plate> readPlanPlates(const json& root, const char* section, const std::string& source,
                                  const PlateOptions& options) {
  std::vector<Plate> plates = readPlates(root, section, source);
  validatePlates(plates, options, source);
  return regularizedPlates(plates, options, PlateOrigin::Computed);
}

AssemblyDocument documentFromPlates(std::vector<Plate> plates, const PlateOptions& options, const std::string& source,
                                    std::string name) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Plate;
  document.name = std::move(name);
  document.plateOptions = options;
  validatePlates(plates, options, source);
  plates = regularizedPlates(plates, options, PlateOrigin::Drawn);
  std::vector<PlateContact> contacts;
  try {
    contacts = computePlateContacts(plates, options);
  } catch (const Error& error) {  // overlaps found by the geometry: name the file too
    if (error.code() != ErrorCode::BadInput || source.empty()) throw;
    throwBadInput(source, error.what());
  }
  requireConnectedPlates(plates, contacts, source);
  document.assembly = assemblyFromPlates(plates, contacts);
  document.plateCutPoints = plateCutPoints(static_cast<int>(plates.size()), contacts);
  document.contactsFromGeometry = true;
  document.plateContacts = std::move(contacts);
  document.plates = std::move(plates);
  return document;
}

AssemblyDocument plateDesignFromJson(const json& root, const PlateOptions& options, const std::string& source,
                                     const std::string& name) {
  return documentFromPlates(readPlates(root, "plates", source), options, source, name);
}

}  // namespace desia
