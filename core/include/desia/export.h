// SPDX-License-Identifier: GPL-3.0-or-later
// Exports: meshes, prints, cut sheets, and the format registry the CLI and the package ask.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/model.h"
#include "desia/voxel.h"

namespace desia {

// File exports of voxel assemblies: per-part surface meshes (STL, OBJ) for 3D printing and
// rendering, print-ready parts (a clearance between parts, one STL per part in a ZIP, or all parts
// laid flat on a build plate), and BurrTools .xmpuzzle files holding desia's assembly and its
// disassembly as a solution. The bytes are deterministic: the same document and options give the
// same file natively and in WebAssembly.

enum class ExportFormat {
  StlBinary,  // "stl": binary STL, one triangle soup (one part, or all parts in one file)
  StlAscii,   // "stl-ascii": ASCII STL, one solid
  Obj,        // "obj": Wavefront OBJ, one `o partN` object per part, indexed vertices
  XmPuzzle,   // "xmpuzzle": BurrTools puzzle (gzip-compressed XML), always the whole puzzle
  StlZip,         // "stl-zip": a ZIP archive (stored) of binary STLs, one per part: part-01.stl, ...
  BuildPlateStl,  // "build-plate-stl": one binary STL, every part turned to lie flat on z = 0
};

// "stl", "stl-ascii", "obj", "xmpuzzle", "stl-zip", "build-plate-stl"; throws BadInput naming the
// value otherwise.
ExportFormat parseExportFormat(const std::string& name);
const char* exportFormatName(ExportFormat format);

struct ExportOptions {
  int part = 0;                    // 0 = all parts; k >= 1 = only part k (meshes only)
  double voxelSize = 1.0;          // edge length of a voxel in the mesh's units (1e-6 to 1e6); ignored by xmpuzzle
  // Take the voxel size from the document (a .puz file's voxel-size line) when it gives one.
  bool voxelSizeFromDocument = false;
  // Voxel meshes: every face of a part against another part moves in by this much (0 <= c <
  // voxelSize / 2), so two touching parts print with a gap of twice the clearance; faces against
  // empty space stay. 0 for xmpuzzle and plates.
  double clearance = 0.0;
  // build-plate-stl: the gap between the parts' boxes on the plate (0 to 1e6; default one voxel).
  std::optional<double> spacing;
  std::string source = "<input>";  // names the input in error messages
};

// The file bytes of `document` (a voxel assembly) in `format`. Throws BadInput for non-voxel
// documents, an assembly without voxels, an unknown part, a bad voxel size, clearance or spacing,
// or a part chosen for xmpuzzle; TooLarge when the file would exceed kMaxExportBytes.
std::vector<uint8_t> exportAssembly(const AssemblyDocument& document, ExportFormat format,
                                    const ExportOptions& options = {});

constexpr int64_t kMaxExportBytes = 512LL << 20;

// The surface of one part ready to draw: non-indexed triangles (3 floats per vertex, 9 per
// triangle) with flat per-face normals along the grid axes, outward, counter-clockwise seen from
// outside, in voxel units. The same triangles as the part's STL/OBJ export, so a viewer draws
// exactly what gets printed.
struct PartSurface {
  int partId = 0;
  std::vector<float> positions;
  std::vector<float> normals;
};

// The surface of every part of `document` (a voxel assembly), parts in increasing id. Same checks
// and errors as exportAssembly (BadInput for a non-voxel document, no voxels or an empty part;
// TooLarge past kMaxExportBytes of floats); `source` names the input in messages.
std::vector<PartSurface> partSurfaces(const AssemblyDocument& document, const std::string& source = "<input>");

// The BurrTools XML (before compression) and the .xmpuzzle bytes (that XML, gzip-compressed).
// Same checks as exportAssembly; `source` names the input in messages.
std::string xmpuzzleXml(const AssemblyDocument& document, const std::string& source = "<input>");
std::vector<uint8_t> xmpuzzleFile(const AssemblyDocument& document, const std::string& source = "<input>");

// A gzip member (RFC 1952) holding `data` in DEFLATE stored blocks (RFC 1951, BTYPE 00).
std::vector<uint8_t> gzipStored(const std::string& data);

// A ZIP archive (APPNOTE 6.3.x) of the given files, stored (method 0) with their CRC-32, every
// entry dated 1980-01-01 00:00 (the first DOS date), so the bytes depend on the content only.
// Throws TooLarge past 65,535 entries or 4 GiB (no ZIP64).
struct ZipEntry {
  std::string name;
  std::string data;
};
std::vector<uint8_t> zipStored(const std::vector<ZipEntry>& entries);

// Cut files of a plate structure for a laser cutter or a CNC router: every plate laid flat,
// nested onto sheets, as SVG at true size (millimetres) or DXF (R12, $INSUNITS = mm). Outer cuts,
// inner cuts (mortises and holes) and engraving (plate ids, the id of the plate that stands on a
// face next to its joint) are told apart by colour in SVG and by layer in DXF.

enum class CutFileFormat { Svg, Dxf };

// "svg" or "dxf"; BadInput naming the value else.
CutFileFormat parseCutFileFormat(const std::string& name);

struct CutSheetOptions {
  // The sheet in mm; 0 x 0 = one sheet as large as the parts need.
  double sheetWidth = 0, sheetHeight = 0;
  double kerf = 0;        // mm the beam removes: outlines move out by half of it, holes in
  double spacing = 5;     // mm between parts and from the sheet's edges
  bool hairline = false;  // SVG strokes 0.01 mm wide (lasers that cut hairlines only) instead of 0.1 mm
  std::string source = "<input>";
};

// "600x400" (mm); BadInput naming the text else.
void parseSheetSize(const std::string& text, CutSheetOptions* options);

// Options as the package passes them ({sheet: "600x400", kerf, spacing, hairline, source});
// unknown names and bad values are BadInput.
CutSheetOptions parseCutSheetOptionsJson(const std::string& text);

// One file per sheet, in order. The plates are the document's `fabricationPlates` (a result cut
// with a clearance) or its `plates`; each is laid flat on its first face (a plate with mitred
// edges: the blank holding both faces), turned to its smallest bounding box, and shelf-packed in
// order of height. Throws BadInput for a document without plates, a sheet too small for a plate
// (named, with its size), a kerf or spacing out of range.
std::vector<std::string> plateCutSheets(const AssemblyDocument& document, CutFileFormat format,
                                        const CutSheetOptions& options);

// Every file format desia writes, for every kind of assembly, in one registry: the CLI's `export`
// and the package's exportAssembly both ask it which formats exist, which kinds each takes and
// which options apply, and write through exportFiles. A new format is one entry here and its
// writer.

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
