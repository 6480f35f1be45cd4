// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON assembly document (schema in docs/json-schema.md): one format for voxel, plate and
// frame assemblies, or bare contact graphs, optionally carrying analysis results.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/plate.h"
#include "desia/voxel_grid.h"

namespace desia {

enum class AssemblyKind { Voxel, Plate, Frame, Contacts };
const char* assemblyKindName(AssemblyKind kind);

// A plate design result's plan (docs/json-schema.md "Plate results"), read by part id with the
// document: `removal` names every part once, the key first; the last part stays.
struct PlateResultPlan {
  std::string jointGeometry;      // "cut", "milled" (jointed plates) or "planned" (nothing cut)
  std::vector<int> removalOrder;  // part ids in the order they leave
  std::vector<Vec3> directions;   // unit vectors: removalOrder[k] leaves along directions[k]
  double clearance = 0;           // mm of play in `fabricationPlates`
};

struct AssemblyDocument {
  AssemblyKind kind = AssemblyKind::Voxel;
  std::string name;
  VoxelGrid voxels;          // kind == Voxel
  // kind == Voxel: the voxel edge lengths a .puz file gives (x, y, z), the default size of exports.
  std::optional<std::array<double, 3>> voxelSize;
  Assembly assembly;         // parts and contacts (derived from the grid for voxel documents)
  std::string geometryJson;  // plate / frame geometry sections, kept verbatim for round trips
  std::vector<Plate> plates;          // kind == Plate, read from geometry (then contacts are computed)
  std::vector<Plate> fabricationPlates;  // a design result with a clearance: the plates as they are cut
  // Parts (internal indices) that are cut points of the parts-graph: plates (plates in contact), or
  // a frame's beams (beams sharing a joint). The check report's `cutPoints`.
  std::vector<int> plateCutPoints;
  // kind == Plate with contactsFromGeometry: the plates' contacts as computed when they were read
  // (the designer and the cut sheets take them from here rather than computing them again).
  std::vector<PlateContact> plateContacts;
  PlateOptions plateOptions;          // the contact tolerance the plates were read with
  bool contactsFromGeometry = false;  // the contacts were computed from `plates` (a design, not a plan)
  std::optional<PlateResultPlan> plateResult;  // kind == Plate with `removal`: a design result
};

// Reads .puz or JSON text (detected from the content). `source` names the input in messages.
AssemblyDocument parseAssemblyText(const std::string& text, const std::string& source = "<input>");
// The same, letting the text go as soon as it is parsed (less memory for large documents).
AssemblyDocument parseAssemblyText(std::string&& text, const std::string& source = "<input>");
AssemblyDocument parseJsonDocument(const std::string& text, const std::string& source = "<input>");
AssemblyDocument documentFromVoxels(VoxelGrid grid, std::string name = "");
// A plate design: the plates validated, their contacts computed (they must all be connected), and
// the parts-graph's cut points found. Throws BadInput naming `source` and the plate.
AssemblyDocument documentFromPlates(std::vector<Plate> plates, const PlateOptions& options, const std::string& source,
                                    std::string name = "");

// Serializes a document (without results). `indent` < 0 gives one line.
std::string documentToJson(const AssemblyDocument& document, int indent = 2);

}  // namespace desia
