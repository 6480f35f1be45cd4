// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle meshes read from OBJ and STL files: the input shapes of the voxel puzzle designer.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/triangle_mesh.h"

namespace desia {

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

}  // namespace desia
