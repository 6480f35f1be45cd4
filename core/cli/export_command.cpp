// SPDX-License-Identifier: GPL-3.0-or-later
// `desia export`: a voxel assembly as part meshes (STL, OBJ), print-ready parts (a clearance, one
// STL per part in a ZIP, a build plate) or a BurrTools .xmpuzzle; a plate structure as meshes or cut
// files (SVG, DXF); a frame as meshes, .fpuz or a cut list.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "desia/cut_sheets.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/frame_format.h"

namespace {

constexpr int kExitBadInput = 2;

const char* kExportUsage =
    "usage: desia export FILE --format stl|stl-ascii|obj|xmpuzzle|stl-zip|build-plate-stl|svg|dxf|fpuz|csv|puz|voxel-json|pieces-obj|joint-pieces-stl\n"
    "             [--part N] [--voxel-size S] [--clearance MM] [--spacing MM]\n"
    "             [--sheet WxH] [--kerf MM] [--spacing MM] [--hairline] --output OUT\n";

using desia::cli::UsageError;

int parsePart(const std::string& text) {
  return desia::cli::parseDigits(text, "--part needs a part number (0 = all parts), got '" + text + "'");
}

double parseVoxelSize(const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size()) throw UsageError{"--voxel-size needs a number, got '" + text + "'"};
  return value;  // the range is checked by the core
}

// `args` without `flag` (an option without a value); `*present` tells whether it was there.
std::vector<std::string> withoutFlag(const std::vector<std::string>& args, const std::string& flag, bool* present) {
  std::vector<std::string> rest;
  for (const std::string& arg : args) {
    if (arg == flag) *present = true;
    else rest.push_back(arg);
  }
  return rest;
}

// OUT.svg for one sheet; OUT-1.svg, OUT-2.svg, ... for several.
std::string sheetFileName(const std::string& output, size_t sheet, size_t sheets) {
  if (sheets == 1) return output;
  const size_t dot = output.find_last_of('.');
  const size_t slash = output.find_last_of('/');
  const bool extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (extension ? output.substr(0, dot) : output) + "-" + std::to_string(sheet + 1) + (extension ? output.substr(dot) : "");
}

int exportCutSheets(const desia::AssemblyDocument& document, const std::string& input, const std::string& format,
                    const desia::CutSheetOptions& cut, const std::string& output) {
  const std::vector<std::string> sheets = desia::plateCutSheets(document, desia::parseCutFileFormat(format), cut);
  for (size_t s = 0; s < sheets.size(); ++s) desia::cli::writeOutputFile(sheetFileName(output, s, sheets.size()), sheets[s]);
  std::cout << input << ": " << document.plates.size() << " plates on " << sheets.size() << (sheets.size() == 1 ? " sheet" : " sheets")
            << " as " << format << "; wrote " << sheetFileName(output, 0, sheets.size())
            << (sheets.size() > 1 ? " to " + sheetFileName(output, sheets.size() - 1, sheets.size()) : std::string()) << "\n";
  return 0;
}

int exportFile(const std::vector<std::string>& args) {
  std::string input, output, format;
  desia::ExportOptions options;
  desia::CutSheetOptions cut;
  std::optional<double> spacing;
  const desia::cli::Arguments arguments =
      desia::cli::splitArguments(withoutFlag(args, "--hairline", &cut.hairline), {"--format", "--part", "--voxel-size", "--clearance", "--output", "--sheet", "--kerf", "--spacing"});
  if (arguments.positional.size() > 1) throw UsageError{"export takes one FILE, got also " + arguments.positional[1]};
  if (!arguments.positional.empty()) input = arguments.positional[0];
  for (const auto& [name, value] : arguments.named) {
    if (name == "--format") format = value;
    if (name == "--output") output = value;
    if (name == "--part") options.part = parsePart(value);
    if (name == "--voxel-size") options.voxelSize = parseVoxelSize(value);
    // Range checks against the voxel size are the core's (the clearance below half a voxel).
    if (name == "--clearance") options.clearance = desia::cli::numberOption(name, value, 0, 1e6);
    if (name == "--sheet") desia::parseSheetSize(value, &cut);
    if (name == "--kerf") cut.kerf = desia::cli::numberOption(name, value, 0, 5);
    if (name == "--spacing") spacing = cut.spacing = desia::cli::numberOption(name, value, 0, 1000);
  }
  // --spacing: the gaps between plates on a cut sheet, or between parts on a build plate.
  if (format == "build-plate-stl") options.spacing = spacing;
  if (input.empty()) throw UsageError{"export needs a FILE (.puz or JSON voxel assembly)"};
  if (format.empty()) throw UsageError{"export needs --format stl|stl-ascii|obj|xmpuzzle|stl-zip|build-plate-stl"};
  if (output.empty()) throw UsageError{"export needs --output OUT"};
  static const std::vector<std::string> kFormats{"stl", "stl-ascii", "obj", "xmpuzzle", "stl-zip", "build-plate-stl", "svg",
                                                 "dxf", "fpuz", "csv", "puz", "voxel-json", "pieces-obj", "joint-pieces-stl"};
  if (std::find(kFormats.begin(), kFormats.end(), format) == kFormats.end()) {
    std::string known;
    for (const std::string& name : kFormats) known += (known.empty() ? "" : ", ") + name;
    throw desia::Error(desia::ErrorCode::BadInput, "unknown export format '" + format + "' (expected one of: " + known +
                                                       "; svg and dxf are plate cut sheets, fpuz to joint-pieces-stl frames)");
  }
  if (format == "svg" || format == "dxf") {
    // Cut files of a plate structure (core/io/cut_sheets.cpp): a voxel size, a part or a
    // clearance would silently change nothing there.
    for (const auto& [flag, value] : arguments.named) {
      if (flag == "--part" || flag == "--voxel-size" || flag == "--clearance") {
        throw desia::Error(desia::ErrorCode::BadInput, input + ": " + flag + " does not apply to " + format +
                                                           " cut sheets (they hold every plate as designed; the clearance is the design's --clearance)");
      }
    }
    cut.source = input;
    return exportCutSheets(desia::parseAssemblyText(desia::cli::readInputFile(input), input), input, format, cut, output);
  }
  // .fpuz and the cut list are for frames only; so are puz and voxel-json here: a frame on a voxel
  // grid as the voxel assembly it is (core/frame/frame_voxels.cpp).
  const bool frameOnlyFormat = format == "fpuz" || format == "csv" || format == "puz" || format == "voxel-json" ||
                               format == "pieces-obj" || format == "joint-pieces-stl";
  const desia::ExportFormat exportFormat = frameOnlyFormat ? desia::ExportFormat::StlBinary : desia::parseExportFormat(format);

  options.source = input;
  const desia::AssemblyDocument document = desia::parseAssemblyText(desia::cli::readInputFile(input), input);
  if (document.kind == desia::AssemblyKind::Frame && document.contactsFromGeometry) {
    if (options.clearance != 0) {
      throw desia::Error(desia::ErrorCode::BadInput, input + ": --clearance applies to voxel assemblies, not to frames");
    }
    // Frames (paper Section 5.3): part meshes, .fpuz, the cut list, or (axis-aligned on a voxel grid)
    // .puz, voxel JSON, .xmpuzzle (core/io/frame_export.cpp).
    const std::vector<uint8_t> bytes = desia::exportFrame(desia::frameFromAssemblyDocument(document, input), format, options.part, input);
    desia::cli::writeOutputFile(output, std::string(bytes.begin(), bytes.end()));
    std::cout << input << ": frame of " << document.assembly.partCount() << " beams as " << format << ", " << bytes.size() << " bytes; wrote " << output << "\n";
    return 0;
  }
  if (frameOnlyFormat) throw desia::Error(desia::ErrorCode::BadInput, input + ": ." + format + " exports are for frame structures");
  const std::vector<uint8_t> bytes = desia::exportAssembly(document, exportFormat, options);
  desia::cli::writeOutputFile(output, std::string(bytes.begin(), bytes.end()));
  const int parts = document.kind == desia::AssemblyKind::Voxel ? document.voxels.maxLabel() : document.assembly.partCount();
  std::cout << input << ": "
            << (options.part == 0 ? (parts == 1 ? std::string("1 part") : "all " + std::to_string(parts) + " parts")
                                  : "part " + std::to_string(options.part) + " of " + std::to_string(parts))
            << " as " << desia::exportFormatName(exportFormat) << ", " << bytes.size() << " bytes; wrote " << output
            << "\n";
  return 0;
}

}  // namespace

int runExportCommand(const std::vector<std::string>& args) {
  try {
    return exportFile(args);
  } catch (const UsageError& e) {
    std::cerr << "desia: export: " << e.message << "\n" << kExportUsage;
    return kExitBadInput;
  }
}
