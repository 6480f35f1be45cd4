// SPDX-License-Identifier: GPL-3.0-or-later
// The model layer shared by every kind (paper Section 3.1): parts and planar contacts, closed
// triangle meshes, and directed graphs with their strongly connected components and cut points.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "desia/tolerances.h"

namespace desia {

// The assembly model shared by voxel, plate and frame assemblies (paper Section 3.1): rigid parts
// and planar contacts between them, each contact with its normal. Blocking relations per
// translation direction are derived from the contacts (see analysis.h).

using Vec3 = std::array<double, 3>;

struct Part {
  int id = 0;             // the id the user sees (as in the file); parts are indexed 0..n-1 internally
  std::string name;       // optional label
};

// A planar contact interface between parts `a` and `b` (internal indices). `normal` is the unit
// normal of the interface pointing from a towards b, so translating a along d with d·normal > 0
// makes a penetrate b (paper Section 3.2, n_ij). `area` weights nothing in the tests; it is kept
// for reports and for ranking in the design framework.
struct Contact {
  int a = 0;
  int b = 0;
  Vec3 normal{0, 0, 0};
  double area = 1.0;
};

struct Assembly {
  std::vector<Part> parts;
  std::vector<Contact> contacts;

  int partCount() const { return static_cast<int>(parts.size()); }
  // Internal index of the part with the given user id, or -1.
  int indexOfId(int id) const;
};

// The unit vector along `normal`, computed without overflow or underflow at any scale (it is
// divided by its largest component first), with residue components (below tolerance::kComponentNoise
// of the largest: computed geometry leaves them where a component should vanish) set to zero.
// Empty for the zero vector or a non-finite component. Every contact normal passes through this
// once, when it is read or computed from geometry.
std::optional<Vec3> cleanedNormal(const Vec3& normal);

// True when every contact normal is already what cleanedNormal makes of it (no copy needed).
bool hasCleanNormals(const Assembly& assembly);

// The assembly with every contact normal passed through cleanedNormal; contacts whose normal is
// the zero vector constrain nothing and are left out.
Assembly withCleanedNormals(const Assembly& assembly);

// True when every contact normal is parallel to a coordinate axis, the case where the DBG test is
// exact (paper Section 3.2, supplementary proof).
bool hasOnlyAxisAlignedContacts(const Assembly& assembly);

// Closed triangle meshes: the solids every kind reads (shapes to voxelize, polyhedra to cut into
// plates) and writes (part meshes). Reading them from OBJ and STL is io's (desia/mesh.h).

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

// One planar convex polygon of a solid's boundary: its points in order (counter-clockwise seen
// from outside), its outward unit normal and the solid it comes from.
struct BoundaryPolygon {
  std::vector<Vec3> points;
  Vec3 normal;
  int solid = 0;
};

// The boundary of the union of closed solids (each a closed mesh wound outward), as polygons:
// each solid's triangles less their parts inside another solid (core/model/solid_boolean.cpp: a
// BSP tree per solid; points within tolerance::kMeshWeldMm of a plane are on it). Where faces
// of two solids lie on one plane, those facing the same way are kept once (the earlier solid's)
// and those facing each other (solids touching) dropped. Polygons are split where another
// solid's plane crosses them, so they meet in T-junctions: the caller merges the polygons of each
// plane and triangulates them (solidBooleanMesh in desia/plate.h).
std::vector<BoundaryPolygon> unionBoundaryPolygons(const std::vector<TriangleMesh>& solids);

// The same for the union of `solids` less the union of `removed` (closed meshes too): the solids'
// faces outside every removed solid (a face on a removed solid's face facing the same way is cut
// away, one facing it kept), and the removed solids' faces strictly inside a solid, turned to face
// out of what is left (`solid` counts on past the solids).
std::vector<BoundaryPolygon> booleanBoundaryPolygons(const std::vector<TriangleMesh>& solids,
                                                     const std::vector<TriangleMesh>& removed);

// Throws BadInput unless the mesh has vertices and triangles, finite coordinates, indices in
// range, no triangle repeating a vertex, and every undirected edge in an even number of triangles
// (two, or four where solids touch along an edge; the first offending edge in vertex order is
// named, 1-based).
void checkClosedMesh(const TriangleMesh& mesh, const std::string& source = "<input>");

// A small directed graph on nodes 0..n-1 and its strongly connected components.

class DirectedGraph {
 public:
  explicit DirectedGraph(int nodeCount = 0) : out_(nodeCount) {}

  int nodeCount() const { return static_cast<int>(out_.size()); }
  // Adds from->to once (duplicates are ignored, so edge lists stay sets).
  void addEdge(int from, int to);
  bool hasEdge(int from, int to) const;
  // Removes every edge, keeping the nodes and the memory (for graphs rebuilt many times).
  void clearEdges() {
    for (auto& list : out_) list.clear();
  }
  const std::vector<int>& successors(int node) const { return out_[node]; }
  int edgeCount() const;

 private:
  std::vector<std::vector<int>> out_;  // sorted successor lists
};

struct StronglyConnectedComponents {
  std::vector<int> componentOf;              // node -> component index
  std::vector<std::vector<int>> components;  // each sorted ascending; ordered by smallest node
  int count() const { return static_cast<int>(components.size()); }
};

// Tarjan's algorithm [Tarjan 1972] (paper Section 3.2), iterative with an explicit stack so the
// depth of the graph never reaches the (small) WebAssembly call stack.
StronglyConnectedComponents findStronglyConnectedComponents(const DirectedGraph& graph);

// Is the graph strongly connected? For graphs of 1 to 64 nodes, by what node 0 reaches along the
// edges and against them on bit masks: no allocation and a fraction of Tarjan's cost, for tests
// that ask thousands of times. Nothing (std::nullopt) for larger graphs.
std::optional<bool> isStronglyConnectedSmall(const DirectedGraph& graph);

// For each component: does any edge leave it / enter it from another component?
struct CondensationDegrees {
  std::vector<bool> hasOutEdge;
  std::vector<bool> hasInEdge;
};
CondensationDegrees condensationDegrees(const DirectedGraph& graph,
                                        const StronglyConnectedComponents& scc);

// Cut points (articulation points) of an undirected graph.

// The nodes whose removal splits their connected component, sorted. Hopcroft and Tarjan's
// depth-first search, iterative with an explicit stack (no recursion depth grows with the graph).
// Parallel edges and self-loops are allowed.
std::vector<int> findCutPoints(int nodeCount, const std::vector<std::pair<int, int>>& edges);

}  // namespace desia
