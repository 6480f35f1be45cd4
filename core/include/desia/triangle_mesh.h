// SPDX-License-Identifier: GPL-3.0-or-later
// Closed triangle meshes: the solids every kind reads (shapes to voxelize, polyhedra to cut into
// plates) and writes (part meshes). Reading them from OBJ and STL is io's (desia/mesh.h).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace desia {

// Vertices, and triangles as 0-based indices into them (messages print them 1-based, as OBJ does).
struct TriangleMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
  // OBJ only: the object or group (`o` / `g` record) each triangle belongs to, an index into
  // groupNames; empty when the file has no such records (and for STL).
  std::vector<int> triangleGroup;
  std::vector<std::string> groupNames;
};

// Where a closed mesh pinches at a vertex (its triangles around the vertex form several fans that
// share no edge there, as around the corner two cubes share and nothing else), gives each fan
// after the first its own copy of the vertex, appended in order (fans in order of their first
// triangle, vertices in index order), so that every vertex's triangles form one fan: with every
// edge in two triangles, the indexed mesh is then a 2-manifold. Positions are unchanged.
void splitPinchedVertices(TriangleMesh& mesh);

// Takes the triangles of a closed mesh that have no area (twice-area at most
// tolerance::kDegenerateTriangleTwiceAreaMm2: a vertex on the opposite edge, as ear clipping
// leaves where holes line up) out by edge flips: such a triangle (a, c, b) with b on its longest
// edge ac and the triangle (c, a, d) across that edge become (c, b, d) and (b, a, d), the same
// surface, every edge still in two opposite triangles. A flip that would repeat an edge is not
// made. Returns the number of such triangles left.
int flipZeroAreaTriangles(TriangleMesh& mesh);

// Throws BadInput unless the mesh has vertices and triangles, finite coordinates, indices in
// range, no triangle repeating a vertex, and every undirected edge in an even number of triangles
// (two, or four where solids touch along an edge; the first offending edge in vertex order is
// named, 1-based).
void checkClosedMesh(const TriangleMesh& mesh, const std::string& source = "<input>");

}  // namespace desia
