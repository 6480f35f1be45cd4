// SPDX-License-Identifier: GPL-3.0-or-later
// What the mesh kind's files share: boxes, triangles with their unit normals, and a box tree over
// the triangles of one part (built without recursion, queried with an explicit stack).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "analysis/vec3.h"
#include "desia/mesh.h"

namespace desia::mesh {

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  void add(const Vec3& p) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  void add(const Box& b) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], b.lo[i]), hi[i] = std::max(hi[i], b.hi[i]);
  }
  // The boxes share a point once each is grown by `slack` (negative: they overlap by more than -slack).
  bool overlaps(const Box& b, double slack) const {
    for (int i = 0; i < 3; ++i) {
      if (lo[i] > b.hi[i] + slack || b.lo[i] > hi[i] + slack) return false;
    }
    return true;
  }
};

// Does this box, translated by t·d for some t >= 0, meet `target` grown by `slack`? Exact for boxes:
// per axis an interval of t, intersected.
inline bool sweptBoxMeets(const Box& box, const Vec3& d, const Box& target, double slack) {
  double first = 0, last = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double low = target.lo[i] - slack - box.hi[i], high = target.hi[i] + slack - box.lo[i];
    if (d[i] == 0) {
      if (low > 0 || high < 0) return false;
      continue;
    }
    const double t0 = low / d[i], t1 = high / d[i];
    first = std::max(first, std::min(t0, t1));
    last = std::min(last, std::max(t0, t1));
  }
  return first <= last;
}

struct Triangle {
  std::array<Vec3, 3> p;
  Vec3 normal{0, 0, 0};  // unit, outward; zero for a triangle of no area
  double twiceArea = 0;
  Box box() const {
    Box b;
    for (const Vec3& q : p) b.add(q);
    return b;
  }
};

std::vector<Triangle> trianglesOf(const TriangleMesh& mesh);

// A bounding-volume hierarchy over boxes (a part's triangles): leaves of a few boxes, split at the
// median of the longest side of their centres, ties broken by index so the tree is the same everywhere.
class BoxTree {
 public:
  explicit BoxTree(const std::vector<Box>& boxes);
  const Box& bounds() const { return nodes_.front().box; }
  // Calls visit(index) for every box whose ancestors' boxes and own box pass `meets(box)`.
  // visit returns false to stop; query returns false when stopped.
  template <class Meets, class Visit>
  bool query(Meets&& meets, Visit&& visit) const {
    if (nodes_.empty()) return true;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[static_cast<size_t>(stack.back())];
      stack.pop_back();
      if (!meets(node.box)) continue;
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int index = order_[static_cast<size_t>(k)];
          if (meets(boxes_[static_cast<size_t>(index)]) && !visit(index)) return false;
        }
      } else {
        stack.push_back(node.right);
        stack.push_back(node.left);
      }
    }
    return true;
  }

 private:
  struct Node {
    Box box;
    int left = -1, right = -1;
    int first = 0, count = 0;
  };
  std::vector<Box> boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

// The triangles of every part with their boxes and trees, computed once per assembly.
struct PartGeometry {
  std::vector<Triangle> triangles;
  Box box;
  BoxTree tree;
  explicit PartGeometry(const TriangleMesh& mesh);
};

std::vector<PartGeometry> partGeometries(const std::vector<MeshPart>& parts);

// The geometry buildMeshAssembly computed; throws Internal for an assembly not built by it.
const std::vector<PartGeometry>& geometryOf(const MeshAssembly& meshes);

// Closest distance from p to the triangle (Section 5.1.5 of Ericson's Real-Time Collision
// Detection, by regions of the triangle's plane).
double pointTriangleDistance(const Vec3& p, const Triangle& t);

// Is p inside the closed mesh? Parity of the crossings of a ray from p along a fixed direction
// that no axis-aligned face contains; p must lie farther than the tolerance from the surface.
bool pointInside(const Vec3& p, const PartGeometry& part);

// Throws BadInput for a part that intersects itself or parts overlapping by more than `tolerance`
// (named, with a point where they cross).
void requireNoOverlaps(const std::vector<MeshPart>& parts, const std::vector<PartGeometry>& geometry,
                       double tolerance);

// Contacts between parts: planar faces (coplanar, edge-connected triangles) of two parts lying on
// each other with opposite normals, overlapping by more than `emptyArea` mm² (Clipper in the
// face's plane). Sets *faceCount to the number of planar faces and *curved to the curved contact
// regions (facets of two parts in contact, joined at slight angles).
std::vector<Contact> meshContacts(const std::vector<MeshPart>& parts, const std::vector<PartGeometry>& geometry,
                                  double tolerance, double emptyArea, int* faceCount, std::vector<CurvedContact>* curved);

// "(x, y, z)" for messages.
std::string pointText(const Vec3& p);

// "FILE: part ID ('NAME')", how messages name a part.
std::string partLabel(const MeshPart& part);

// Throws BadInput naming the part unless it is closed and consistently oriented (every edge used
// once in each direction) with a volume above `emptyVolume` mm³; a part drawn inside out is turned.
void requireClosedOrientedPart(MeshPart& part, double emptyVolume);

// How far the `movers` (geometry possibly moved off the assembly's) can travel along d before an
// obstacle (a part with obstacles[k]) stops them: infinity when they leave, 0 when they cannot move.
// Stops early once below `stopBelow`; *obstacle (if given) is the part that stops them.
double travelDistance(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                      const std::vector<const PartGeometry*>& movers, const std::vector<bool>& obstacles,
                      const Vec3& d, double stopBelow, int* obstacle);

// How far `mover`, placed `moverOffset` off where its geometry lies, can travel along d before
// `obstacle` (as placed) stops it: infinity when it passes, 0 when it cannot move. One pair of
// travelDistance, for callers that place parts themselves (the search for moves of several parts,
// mesh_group_search.cpp). *work (if given) grows by the triangles and triangle pairs looked at.
double pairTravelDistance(const MeshAssembly& meshes, const PartGeometry& mover, const Vec3& moverOffset,
                          const PartGeometry& obstacle, const Vec3& d, int64_t* work = nullptr);

// meshSweepObstacle on geometry computed once (the planner sweeps many times).
std::string sweepObstacle(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                          const std::vector<int>& moving, const std::vector<bool>& present, const Vec3& d);

// The plan of mesh_disassembly.cpp; where it gets stuck and the parts lie on a lattice, the complete
// voxel disassembler's (planOnLattice). *note (if given) says what the lattice gave, else "".
DisassemblyPlan planWithGeometry(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                 std::string* note = nullptr);

}  // namespace desia::mesh
