// SPDX-License-Identifier: GPL-3.0-or-later
// `desia export`: a voxel assembly as part meshes (STL, OBJ), print-ready parts (a clearance, one
// STL per part in a ZIP, a build plate) or a BurrTools .xmpuzzle; a plate structure as meshes or cut
// files (SVG, DXF); a frame as meshes, .fpuz or a cut list.
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"

namespace {

constexpr int kExitBadInput = 2;

// The usage line lists the registry's formats (desia/export.h).
std::string exportUsage() {
  std::string formats;
  for (const desia::ExportFormatInfo& format : desia::exportFormats()) formats += (formats.empty() ? "" : "|") + std::string(format.name);
  return "usage: desia export FILE --format " + formats +
         "\n"
         "             [--part N] [--voxel-size S] [--clearance MM] [--spacing MM]\n"
         "             [--sheet WxH] [--kerf MM] [--spacing MM] [--hairline] --output OUT\n";
}

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

void writeCutSheets(const std::vector<std::string>& sheets, const desia::AssemblyDocument& document,
                    const std::string& input, const std::string& format, const std::string& output) {
  for (size_t s = 0; s < sheets.size(); ++s) desia::cli::writeOutputFile(sheetFileName(output, s, sheets.size()), sheets[s]);
  std::cout << input << ": " << document.plates.size() << " plates on " << sheets.size() << (sheets.size() == 1 ? " sheet" : " sheets")
            << " as " << format << "; wrote " << sheetFileName(output, 0, sheets.size())
            << (sheets.size() > 1 ? " to " + sheetFileName(output, sheets.size() - 1, sheets.size()) : std::string()) << "\n";
}

void reportFile(const desia::AssemblyDocument& document, const desia::ExportOptions& options, const std::string& input,
                const std::string& format, size_t bytes, const std::string& output) {
  if (desia::isFrameDocument(document)) {
    std::cout << input << ": frame of " << document.assembly.partCount() << " beams as " << format << ", " << bytes << " bytes; wrote " << output << "\n";
    return;
  }
  const int parts = document.kind == desia::AssemblyKind::Voxel ? document.voxels.maxLabel() : document.assembly.partCount();
  std::cout << input << ": "
            << (options.part == 0 ? (parts == 1 ? std::string("1 part") : "all " + std::to_string(parts) + " parts")
                                  : "part " + std::to_string(options.part) + " of " + std::to_string(parts))
            << " as " << format << ", " << bytes << " bytes; wrote " << output << "\n";
}

// Flags that the format would silently ignore are refused, naming the flag.
void refuseFlagsNotRead(const desia::cli::Arguments& arguments, bool hairline, const desia::ExportFormatInfo& format,
                        const std::string& input) {
  using desia::ExportOptionGroup;
  for (const auto& [flag, value] : arguments.named) {
    const bool meshFlag = flag == "--part" || flag == "--voxel-size" || flag == "--clearance";
    if (format.perSheet && meshFlag) {
      // Cut files hold every plate as designed; a voxel size, a part or a clearance change nothing there.
      throw desia::Error(desia::ErrorCode::BadInput, input + ": " + flag + " does not apply to " + format.name +
                                                         " cut sheets (they hold every plate as designed; the clearance is the design's --clearance)");
    }
    const bool sheetFlag = flag == "--sheet" || flag == "--kerf";
    if ((sheetFlag && !desia::formatReads(format, ExportOptionGroup::Sheet)) ||
        (flag == "--spacing" && !desia::formatReads(format, ExportOptionGroup::Spacing))) {
      throw desia::Error(desia::ErrorCode::BadInput, input + ": " + flag + " does not apply to " + format.name +
                                                         " (it sets cut sheets: svg, dxf" +
                                                         (flag == "--spacing" ? "; and build-plate-stl's gaps)" : ")"));
    }
  }
  if (hairline && !desia::formatReads(format, ExportOptionGroup::Sheet)) {
    throw desia::Error(desia::ErrorCode::BadInput, input + ": --hairline does not apply to " + std::string(format.name) +
                                                       " (it sets cut sheets: svg, dxf)");
  }
}

int exportFile(const std::vector<std::string>& args) {
  std::string input, output, format;
  desia::ExportSettings settings;
  desia::ExportOptions& options = settings.mesh;
  desia::CutSheetOptions& cut = settings.sheets;
  std::optional<double> spacing;
  options.voxelSizeFromDocument = true;  // a .puz file's voxel-size line, unless --voxel-size says otherwise
  const desia::cli::Arguments arguments =
      desia::cli::splitArguments(withoutFlag(args, "--hairline", &cut.hairline), {"--format", "--part", "--voxel-size", "--clearance", "--output", "--sheet", "--kerf", "--spacing"});
  if (arguments.positional.size() > 1) throw UsageError{"export takes one FILE, got also " + arguments.positional[1]};
  if (!arguments.positional.empty()) input = arguments.positional[0];
  for (const auto& [name, value] : arguments.named) {
    if (name == "--format") format = value;
    if (name == "--output") output = value;
    if (name == "--part") options.part = parsePart(value);
    if (name == "--voxel-size") {
      options.voxelSize = parseVoxelSize(value);
      options.voxelSizeFromDocument = false;
    }
    // Range checks against the voxel size are the core's (the clearance below half a voxel).
    if (name == "--clearance") options.clearance = desia::cli::numberOption(name, value, 0, 1e6);
    if (name == "--sheet") desia::parseSheetSize(value, &cut);
    if (name == "--kerf") cut.kerf = desia::cli::numberOption(name, value, 0, 5);
    if (name == "--spacing") spacing = cut.spacing = desia::cli::numberOption(name, value, 0, 1000);
  }
  if (input.empty()) throw UsageError{"export needs a FILE (.puz or JSON voxel assembly)"};
  if (format.empty()) throw UsageError{"export needs --format stl|stl-ascii|obj|xmpuzzle|stl-zip|build-plate-stl"};
  if (output.empty()) throw UsageError{"export needs --output OUT"};
  const desia::ExportFormatInfo& info = desia::exportFormatNamed(format);
  refuseFlagsNotRead(arguments, cut.hairline, info, input);
  // --spacing: the gaps between plates on a cut sheet, or between parts on a build plate.
  if (!info.perSheet) options.spacing = spacing;
  options.source = cut.source = input;
  const desia::AssemblyDocument document = desia::parseAssemblyText(desia::cli::readInputFile(input), input);
  const std::vector<std::string> files = desia::exportFiles(document, info, settings);
  if (info.perSheet) {
    writeCutSheets(files, document, input, format, output);
  } else {
    desia::cli::writeOutputFile(output, files.front());
    reportFile(document, options, input, format, files.front().size(), output);
  }
  return 0;
}

}  // namespace

int runExportCommand(const std::vector<std::string>& args) {
  try {
    return exportFile(args);
  } catch (const UsageError& e) {
    std::cerr << "desia: export: " << e.message << "\n" << exportUsage();
    return kExitBadInput;
  }
}
