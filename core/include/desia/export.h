// SPDX-License-Identifier: GPL-3.0-or-later
// File exports of voxel assemblies: per-part surface meshes (STL, OBJ) for 3D printing and
// rendering, print-ready parts (a clearance between parts, one STL per part in a ZIP, or all parts
// laid flat on a build plate), and BurrTools .xmpuzzle files holding desia's assembly and its
// disassembly as a solution. The bytes are deterministic: the same document and options give the
// same file natively and in WebAssembly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/mesh.h"
#include "desia/voxel_grid.h"
#include "desia/voxel_surface.h"

namespace desia {

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

}  // namespace desia
