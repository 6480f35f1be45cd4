// SPDX-License-Identifier: GPL-3.0-or-later
// The export-format registry (desia/export.h) and the one way to write a format: cut files
// for plates, the frame exporter for frames, the mesh and puzzle exporter for the rest.
#include "desia/export.h"

#include <algorithm>

#include "desia/error.h"
#include "io/export_internals.h"
#include "desia/design_io.h"
#include "desia/formats.h"
#include "io/kind_entries.h"

namespace desia {
namespace {

using Kind = AssemblyKind;
using Option = ExportOptionGroup;

const std::vector<ExportFormatInfo>& registry() {
  static const std::vector<ExportFormatInfo> formats{
      {"stl", {Kind::Voxel, Kind::Plate, Kind::Frame}, {Option::Part, Option::VoxelSize, Option::Clearance}, false,
       "binary STL, one closed shell per part"},
      {"stl-ascii", {Kind::Voxel, Kind::Plate, Kind::Frame}, {Option::Part, Option::VoxelSize, Option::Clearance}, false,
       "ASCII STL"},
      {"obj", {Kind::Voxel, Kind::Plate, Kind::Frame}, {Option::Part, Option::VoxelSize, Option::Clearance}, false,
       "Wavefront OBJ, one object per part"},
      {"xmpuzzle", {Kind::Voxel, Kind::Frame}, {Option::Part, Option::Clearance}, false,
       "BurrTools puzzle with desia's disassembly as a solution"},
      {"stl-zip", {Kind::Voxel, Kind::Plate}, {Option::Part, Option::VoxelSize, Option::Clearance}, false,
       "a ZIP of one binary STL per part"},
      {"build-plate-stl", {Kind::Voxel}, {Option::Part, Option::VoxelSize, Option::Clearance, Option::Spacing}, false,
       "every part lying flat on z = 0, ready to print"},
      {"svg", {Kind::Plate}, {Option::Sheet, Option::Spacing}, true, "plate cut sheets at true size (mm)"},
      {"dxf", {Kind::Plate}, {Option::Sheet, Option::Spacing}, true, "plate cut sheets, DXF R12 in mm"},
      {"fpuz", {Kind::Frame}, {Option::Part}, false, "FrameInterlock's frame puzzle"},
      {"csv", {Kind::Frame}, {Option::Part}, false, "the frame's cut list"},
      {"puz", {Kind::Frame}, {Option::Part}, false, "a frame on a voxel grid as a DESIA .puz"},
      {"voxel-json", {Kind::Frame}, {Option::Part}, false, "a frame on a voxel grid as a voxel document"},
      {"pieces-obj", {Kind::Frame}, {Option::Part}, false, "each beam body and glued joint piece, in place"},
      {"joint-pieces-stl", {Kind::Frame}, {Option::Part}, false, "the joint pieces laid out on z = 0 to print"},
  };
  return formats;
}

bool takes(const ExportFormatInfo& format, Kind kind) {
  return std::find(format.kinds.begin(), format.kinds.end(), kind) != format.kinds.end();
}

}  // namespace

const std::vector<ExportFormatInfo>& exportFormats() { return registry(); }

const ExportFormatInfo& exportFormatNamed(const std::string& name) {
  for (const ExportFormatInfo& format : registry()) {
    if (name == format.name) return format;
  }
  std::string known;
  for (const ExportFormatInfo& format : registry()) known += (known.empty() ? "" : ", ") + std::string(format.name);
  throw Error(ErrorCode::BadInput, "unknown export format '" + name + "' (expected one of: " + known +
                                       "; svg and dxf are plate cut sheets, fpuz to joint-pieces-stl frames)");
}

bool formatReads(const ExportFormatInfo& format, ExportOptionGroup option) {
  return std::find(format.options.begin(), format.options.end(), option) != format.options.end();
}

const char* exportOptionGroupName(ExportOptionGroup option) {
  switch (option) {
    case Option::Part: return "part";
    case Option::VoxelSize: return "voxelSize";
    case Option::Clearance: return "clearance";
    case Option::Spacing: return "spacing";
    case Option::Sheet: return "sheet";
  }
  return "part";
}

namespace {

// A .puz file's voxel size, when the caller asked for it: its voxels must be cubes.
ExportOptions meshOptionsFor(const AssemblyDocument& document, ExportOptions options) {
  if (!options.voxelSizeFromDocument || !document.voxelSize) return options;
  const std::array<double, 3>& size = *document.voxelSize;
  if (size[0] != size[1] || size[0] != size[2]) {
    throwBadInput(options.source, "the file's voxels are not cubes (voxel size " + formatNumber(size[0]) + " x " +
                                      formatNumber(size[1]) + " x " + formatNumber(size[2]) +
                                      "): give the voxel size of the export (--voxel-size)");
  }
  options.voxelSize = size[0];
  return options;
}

}  // namespace

std::vector<std::string> exportFiles(const AssemblyDocument& document, const ExportFormatInfo& format,
                                     const ExportSettings& settings) {
  const std::string& source = settings.mesh.source;
  const PlateFrameEntries& kinds = plateFrameEntries();
  if (format.perSheet) return kinds.cutSheets(document, format.name, settings.sheets);
  std::vector<uint8_t> bytes;
  if (isFrameDocument(document)) {
    // Frames (paper Section 5.3): part meshes, .fpuz, the cut list, or (on a voxel grid) voxel files.
    if (settings.mesh.clearance != 0) throwBadInput(source, "the clearance applies to voxel assemblies, not to frames");
    bytes = kinds.exportFrame(document, format.name, settings.mesh.part, source);
  } else if (format.kinds.size() == 1 && takes(format, Kind::Frame)) {
    throwBadInput(source, "." + std::string(format.name) + " exports are for frame structures");
  } else {
    bytes = exportAssembly(document, parseExportFormat(format.name), meshOptionsFor(document, settings.mesh));
  }
  return {std::string(bytes.begin(), bytes.end())};
}

}  // namespace desia
