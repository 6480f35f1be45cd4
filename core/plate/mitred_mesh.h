// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh behind plates-from-mesh (plate.h), checked: welded, closed, manifold,
// consistently oriented, in one piece, with a volume, turned outward; and how messages name its
// points and vertices.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "desia/model.h"

namespace desia {
namespace mitred {

constexpr double kPi = 3.14159265358979323846;

// A value for messages, to 4 significant digits.
std::string number(double value);
// "(x, y, z)" to 6 significant digits.
std::string pointText(const Vec3& p);
// "vertex 7 (x, y, z)": 1-based, as the file counts.
std::string vertexText(const TriangleMesh& mesh, int v);

// How many times the closed surface winds around `point` (1 inside, 0 outside).
double windingNumber(const TriangleMesh& mesh, const Vec3& point);

// The mesh with its vertices welded, its triangles' neighbours across each edge (twins[t][e]: the
// triangle across edge e of triangle t), its size (the bounding box's diagonal), turned outward
// where it was inside out (`reoriented`). Throws BadInput naming `source` and the edge or vertex
// for a mesh that is not closed, not manifold, inconsistently oriented, in several pieces or
// without volume.
struct OrientedMesh {
  TriangleMesh mesh;
  std::vector<std::array<int, 3>> twins;
  double size = 0;
  bool reoriented = false;
};
OrientedMesh orientedMesh(const TriangleMesh& input, const std::string& source);

}  // namespace mitred
}  // namespace desia
