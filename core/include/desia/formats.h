// SPDX-License-Identifier: GPL-3.0-or-later
// Reading and writing files: .puz, frames (JSON, OBJ, .fpuz), OBJ/STL meshes and mesh assemblies.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/export.h"
#include "desia/frame.h"
#include "desia/mesh.h"
#include "desia/model.h"
#include "desia/voxel.h"

namespace desia {

// DESIA's .puz voxel format, read and written exactly as the original code does:
//   "Nx Ny Nz", then Nz layers (z) of Ny rows (y) of Nx integers (x fastest), a blank line after
//   each layer; 0 = empty, k >= 1 = part k (part 1 is the key, the highest id the last remainder).

// Parses .puz text strictly: every row on its own line with Nx values, Ny rows per layer, Nz
// layers, nothing after the grid. `source` (a file name) prefixes error locations ("a.puz:7:3").
// Also validates the parts (validateVoxelParts).
// A .puz file: the grid, and the voxel edge lengths when the file gives them (the line of three
// numbers after the header that later interlocking-puzzle research writes).
struct PuzFile {
  VoxelGrid grid;
  std::optional<std::array<double, 3>> voxelSize;
};

// Reads .puz text: "Nx Ny Nz", optionally a line of three voxel sizes, then the labels, either as
// Nz layers of Ny rows of Nx values or as one flat list (x fastest, then y, then z); lines that
// start with '#' are comments. Throws BadInput naming `source`, the line and the value.
PuzFile readPuz(const std::string& text, const std::string& source = "<input>");
VoxelGrid parsePuz(const std::string& text, const std::string& source = "<input>");

// Byte-for-byte the layout of the original writer: "v " per voxel, newline per row, an extra
// newline per layer.
std::string formatPuz(const VoxelGrid& grid);

// True when the text looks like .puz rather than JSON (first non-space character is a digit).
bool looksLikePuz(const std::string& text);

// Triangle meshes read from OBJ and STL files: the input shapes of the voxel puzzle designer.

// Limits checked while reading, before the big allocations (the CLI also caps the file size).
struct MeshLimits {
  static constexpr int64_t kMaxVertices = 10'000'000;
  static constexpr int64_t kMaxTriangles = 5'000'000;
};

// OBJ text: `v x y z [w]` (w and trailing vertex colours ignored) and `f` records with `a`, `a/b`,
// `a/b/c` or `a//c` references, negative (relative) indices, polygons fan-triangulated; every other
// record (vn, vt, o, g, s, usemtl, mtllib, l, comments, ...) is ignored. Faces that repeat a
// vertex (zero area) are dropped. Errors name "source:line".
TriangleMesh parseObj(const std::string& text, const std::string& source = "<input>");

// ASCII or binary STL. Binary is recognised by its size (84-byte header + 50 bytes per triangle),
// not by a leading "solid" (many binary files start with it). Vertices with identical coordinates
// are merged (numbered in order of first appearance); triangles collapsed by that are dropped.
TriangleMesh parseStl(const std::string& bytes, const std::string& source = "<input>");

// OBJ or STL, decided from the content (binary STL size rule, a leading "solid") and the
// extension of `source` (".obj", ".stl", any case).
TriangleMesh parseMesh(const std::string& bytes, const std::string& source = "<input>");

// The file name of `source` without folders and extension ("models/bunny.obj" -> "bunny"); empty
// for placeholders such as "<input>".
std::string meshShapeName(const std::string& source);

// Frame files: the JSON document (kind "frame", docs/json-schema.md), OBJ (every `l` segment and
// every face edge a beam, shared edges once; every vertex a joint) and FrameInterlock's .fpuz; the
// result document of a design; exports (meshes, .fpuz, a cut list).

// Reads a frame from JSON, OBJ or .fpuz text (by the extension of `source`: ".obj", ".fpuz",
// otherwise JSON). `jointSize` > 0 overrides the file's joint size (and the default). Validated
// (layoutFrame, validateJointLabels); throws BadInput naming `source`.
FrameDocument parseFrameText(const std::string& text, const std::string& source, double jointSize = 0);

// The result document of a successful design (kind "frame"): beams renumbered in removal order
// (part 1 = the key; each keeps `inputId`), `jointVoxels` (per joint its 27 part ids, x fastest),
// `removal` (part and direction, in order). Same result, same bytes.
std::string frameResultToJson(const FrameLayout& layout, const FrameDesignResult& result, const std::string& name = "",
                              int indent = 2);
// A frame document as JSON (with its joints and removal when it has them).
std::string frameDocumentToJson(const FrameDocument& document, int indent = 2);

// The assembly document `desia check` reads: parts = beams (ids), contacts = the voxel faces
// between different parts (axis normals); the frame kept as its geometry sections.
AssemblyDocument assemblyDocumentFromFrame(const FrameDocument& document);
// The frame of a frame assembly document (read again from its geometry sections).
FrameDocument frameFromAssemblyDocument(const AssemblyDocument& document, const std::string& source = "<input>");

// FrameInterlock's text format (original-code-notes.md section C): straight beams only; voxel
// values = part id (removal order), all voxels owned.
std::string formatFpuz(const FrameDocument& document);

// The cut list: one row per beam (part, input beam, joints, faces, body length, section, voxels at
// each end with their cells, removal direction).
std::string frameCutListCsv(const FrameDocument& document);

// A designed frame whose beams are straight along the axes and whose joint cubes sit on one grid
// of the joint voxel size, as a voxel assembly (core/frame/frame_voxels.cpp): each beam a rod of
// voxels through the centre voxels of the faces it enters, plus its voxels in its two joint
// cubes; voxel label = part id (beam id of the result document, 1 = the key). Throws BadInput
// naming the first beam (by id) that is off the grid (curved, not along an axis, or a joint not a
// whole number of voxels from the first joint), or for a frame without designed joints.
VoxelGrid frameVoxelGrid(const FrameDocument& document, const std::string& source = "<input>");
// The same as a voxel assembly document (the name kept): .puz, voxel JSON, .xmpuzzle, desia check.
AssemblyDocument frameVoxelDocument(const FrameDocument& document, const std::string& source = "<input>");

// "stl", "stl-ascii", "obj" (one closed mesh per part: its body boxes and voxel groups, each a
// closed shell), "fpuz", "csv", and the voxel assembly of frameVoxelDocument as "puz",
// "voxel-json" or "xmpuzzle". `part` 0 = all parts (meshes only). Throws BadInput for an unknown
// format, an unknown part, a frame without designed joints (fpuz, csv need them; meshes draw the
// beams and bare cubes), curved beams in .fpuz.
std::vector<uint8_t> exportFrame(const FrameDocument& document, const std::string& format, int part = 0,
                                 const std::string& source = "<input>");

// Every part's surface, ready to draw (flat normals), parts in id order; without designed joints,
// the beams and then the bare joint cubes (part id 0).
std::vector<PartSurface> framePartSurfaces(const FrameDocument& document);

// Reading a mesh assembly (issue 29): one OBJ with several objects or groups (one part each), one
// or several STL files (binary: one part; ASCII: one part per `solid`), in millimetres, metres or
// inches, and 3MF files (one part per build item); and the check report of such an assembly.

enum class LengthUnit { Millimetre, Metre, Inch };
// "mm", "m", "inch" (or "in"); throws BadInput naming the value otherwise.
LengthUnit parseLengthUnit(const std::string& name);
double millimetresPer(LengthUnit unit);

struct MeshFile {
  std::string source;  // the path, for messages and to tell OBJ from STL (with the content)
  std::string bytes;
};

// True for a path ending in .obj, .stl or .3mf (any case): `desia check` reads it as a mesh
// assembly.
bool isMeshAssemblyPath(const std::string& path);

// Every part of every file, ids 1, 2, ... in file order, coordinates in millimetres. OBJ: one part
// per `o` / `g` record that has faces (faces before the first record are a part of their own), the
// whole file when there are none. 3MF: one part per build item, its object (and components) under
// the item's transform, in the model's own unit (`unit` applies to OBJ and STL files only). Errors
// (BadInput) name the file and line (3MF: the model part, line and element), as the readers do.
std::vector<MeshPart> readMeshParts(const std::vector<MeshFile>& files, LengthUnit unit = LengthUnit::Millimetre);

// The document the check report is written for: kind "mesh" is not a document kind, so it is a
// contacts document (the parts and computed contacts) named after the first file.
AssemblyDocument meshReportDocument(const MeshAssembly& meshes);

// checkReportToJson of a mesh assembly with "kind": "mesh", and what only meshes have: "mesh" (tolerance, faces,
// contacts, triangles) and each step's direction as a label and a unit vector (directions of
// drawn models need not lie on axes).
std::string meshCheckReportToJson(const MeshAssembly& meshes, const CheckReport& report, int indent = 2);
// One check of mesh files as `desia check FILES --unit U --tolerance T` runs it: read (readMeshParts),
// validated and built (buildMeshAssembly), checked (checkMeshAssembly). The CLI and the package
// call this, so both give the same report.
struct MeshCheck {
  MeshAssembly meshes;
  CheckReport report;
};
MeshCheck checkMeshFiles(const std::vector<MeshFile>& files, LengthUnit unit, const MeshAssemblyOptions& meshOptions,
                         const CheckOptions& options);

// The parts of mesh files as the viewers draw them (part ids as readMeshParts numbers them, in
// millimetres): each triangle on its own with its flat normal.
std::vector<PartSurface> meshPartSurfaces(const std::vector<MeshFile>& files, LengthUnit unit);

// checkReportToText after a "meshes:" line (parts, triangles, planar faces, contacts, tolerance).
std::string meshCheckReportToText(const MeshAssembly& meshes, const CheckReport& report);

}  // namespace desia
