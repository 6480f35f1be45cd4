// SPDX-License-Identifier: GPL-3.0-or-later
// The plates' and frames' entry points for io's kind-independent dispatch (reading, writing,
// checking, designing, exporting and drawing a document), as one constant table. The build picks
// the table by the source file it links (docs/architecture.md, "Two WebAssembly modules"):
// io/plate_frame_entries.cpp points into io/plate and io/frame (the CLI, the tests and the full
// WebAssembly module); io/light_entries.cpp throws ErrorCode::KindNotBuilt from every entry, so
// the light module's linker keeps none of the plates' and frames' code (about 40 % of the core).
// Nothing registers itself at start-up and nothing in the table changes.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/export.h"

namespace desia {

struct PlateFrameEntries {
  // Reading: a frame document with `beams`, a .fpuz file, a plate design with `plates` (contacts
  // from the geometry), a plan's plates (`section`: "plates" or "fabricationPlates", validated).
  AssemblyDocument (*frameFromJson)(const nlohmann::json& root, const std::string& source, const std::string& name);
  AssemblyDocument (*frameFromFpuz)(const std::string& text, const std::string& source);
  AssemblyDocument (*plateDesignFromJson)(const nlohmann::json& root, const PlateOptions& options,
                                          const std::string& source, const std::string& name);
  std::vector<Plate> (*readPlanPlates)(const nlohmann::json& root, const char* section, const std::string& source,
                                       const PlateOptions& options);
  // Writing: a frame's geometry sections, plates as JSON.
  nlohmann::json (*frameSections)(const FrameDocument& frame);
  nlohmann::json (*platesJson)(const std::vector<Plate>& plates);
  // Checking: a plate result verified again; a designed frame's joint pieces swept out.
  CheckReport (*checkPlateResult)(const AssemblyDocument& document, const CheckOptions& options);
  std::optional<ShapeRemovalCheck> (*frameShapeRemoval)(const AssemblyDocument& document);
  // Designing step by step.
  std::unique_ptr<DesignSession> (*openPlateSession)(AssemblyDocument design, const std::string& optionsJson);
  std::unique_ptr<DesignSession> (*openFrameSession)(const std::string& text, const std::string& source,
                                                     const std::string& optionsJson);
  // Exporting and drawing: cut sheets (format "svg" or "dxf"), a frame's files, plates' meshes.
  std::vector<std::string> (*cutSheets)(const AssemblyDocument& document, const std::string& format,
                                        const CutSheetOptions& options);
  std::vector<uint8_t> (*exportFrame)(const AssemblyDocument& document, const std::string& format, int part,
                                      const std::string& source);
  std::vector<uint8_t> (*exportPlates)(const AssemblyDocument& document, ExportFormat format,
                                       const ExportOptions& options);
  std::vector<PartSurface> (*plateSurfaces)(const AssemblyDocument& document);
  std::vector<PartSurface> (*frameSurfaces)(const AssemblyDocument& document, const std::string& source);
};

// The table this build links (one of the two files above defines it).
const PlateFrameEntries& plateFrameEntries();

}  // namespace desia
