// SPDX-License-Identifier: GPL-3.0-or-later
// Every file format desia writes, for every kind of assembly, in one registry: the CLI's `export`
// and the package's exportAssembly both ask it which formats exist, which kinds each takes and
// which options apply, and write through exportFiles. A new format is one entry here and its
// writer.
#pragma once

#include <string>
#include <vector>

#include "desia/cut_sheets.h"
#include "desia/document.h"
#include "desia/export.h"

namespace desia {

// Which options a format reads: the rest would silently change nothing, so callers refuse them.
enum class ExportOptionGroup {
  Part,       // one part only (0 = all)
  VoxelSize,  // model units per voxel
  Clearance,  // faces between voxel parts moved in (printing)
  Spacing,    // gaps between parts laid out (build plate, cut sheets)
  Sheet,      // sheet size, kerf, hairline (cut files)
};

struct ExportFormatInfo {
  const char* name;                         // as the CLI's --format and the package's `format`
  std::vector<AssemblyKind> kinds;          // the assemblies it exports
  std::vector<ExportOptionGroup> options;   // the options it reads
  bool perSheet;                            // one file per sheet (cut files), else one file
  const char* what;                         // one line for usage and errors
};

// In the order the usage lists them.
const std::vector<ExportFormatInfo>& exportFormats();

// The format called `name`; BadInput listing every format otherwise.
const ExportFormatInfo& exportFormatNamed(const std::string& name);

bool formatReads(const ExportFormatInfo& format, ExportOptionGroup option);
const char* exportOptionGroupName(ExportOptionGroup option);  // "part", "voxelSize", ...

struct ExportSettings {
  ExportOptions mesh;      // part, voxel size, clearance, build-plate spacing, source
  CutSheetOptions sheets;  // sheet, kerf, spacing, hairline (cut files)
};

// The file(s) of `document` in `format`: one, or one per sheet for cut files. BadInput when the
// format does not take this kind of assembly (naming both), or as each writer refuses its input.
std::vector<std::string> exportFiles(const AssemblyDocument& document, const ExportFormatInfo& format,
                                     const ExportSettings& settings);

}  // namespace desia
