// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a mesh assembly (issue 29): one OBJ with several objects or groups (one part each), one
// or several STL files (binary: one part; ASCII: one part per `solid`), in millimetres, metres or
// inches, and 3MF files (one part per build item); and the check report of such an assembly.
#pragma once

#include <string>
#include <vector>

#include "desia/check.h"
#include "desia/document.h"
#include "desia/export.h"
#include "desia/mesh_assembly.h"

namespace desia {

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
