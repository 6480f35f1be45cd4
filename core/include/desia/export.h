// SPDX-License-Identifier: GPL-3.0-or-later
// File exports of voxel assemblies: per-part surface meshes (STL, OBJ) for 3D printing and
// rendering, and BurrTools .xmpuzzle files for solving and disassembly in BurrTools. The bytes
// are deterministic: the same document and options give the same file natively and in WebAssembly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/mesh.h"
#include "desia/voxel_grid.h"

namespace desia {

enum class ExportFormat {
  StlBinary,  // "stl": binary STL, one triangle soup (one part, or all parts in one file)
  StlAscii,   // "stl-ascii": ASCII STL, one solid
  Obj,        // "obj": Wavefront OBJ, one `o partN` object per part, indexed vertices
  XmPuzzle,   // "xmpuzzle": BurrTools puzzle (gzip-compressed XML), always the whole puzzle
};

// "stl", "stl-ascii", "obj", "xmpuzzle"; throws BadInput naming the value otherwise.
ExportFormat parseExportFormat(const std::string& name);
const char* exportFormatName(ExportFormat format);

struct ExportOptions {
  int part = 0;                    // 0 = all parts; k >= 1 = only part k (meshes only)
  double voxelSize = 1.0;          // edge length of a voxel in the mesh's units (1e-6 to 1e6); ignored by xmpuzzle
  std::string source = "<input>";  // names the input in error messages
};

// The file bytes of `document` (a voxel assembly) in `format`. Throws BadInput for non-voxel
// documents, an assembly without voxels, an unknown part, a bad voxel size, or a part chosen for
// xmpuzzle; TooLarge when the file would exceed kMaxExportBytes.
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

// The closed surface of part `partId`: one square per voxel face that does not touch the same
// part (faces against empty space, another part or the grid's border), as outward triangles, in
// grid coordinates times `voxelSize` (voxel (x, y, z) spans [x, x+1] x [y, y+1] x [z, z+1]).
// Every edge is used by exactly two triangles, in opposite directions, even where two voxels of
// the part touch only along an edge (see the definition for how). Throws BadInput for a part
// without voxels.
TriangleMesh partSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize = 1.0);

// The BurrTools XML (before compression) and the .xmpuzzle bytes (that XML, gzip-compressed).
// Same checks as exportAssembly; `source` names the input in messages.
std::string xmpuzzleXml(const AssemblyDocument& document, const std::string& source = "<input>");
std::vector<uint8_t> xmpuzzleFile(const AssemblyDocument& document, const std::string& source = "<input>");

// A gzip member (RFC 1952) holding `data` in DEFLATE stored blocks (RFC 1951, BTYPE 00).
std::vector<uint8_t> gzipStored(const std::string& data);

}  // namespace desia
