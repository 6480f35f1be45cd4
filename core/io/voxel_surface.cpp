// SPDX-License-Identifier: GPL-3.0-or-later
// The closed surface of one part of a voxel assembly (the mesh behind the STL and OBJ exports).
#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "io/export_internals.h"

namespace desia {
namespace {

// Positions are kept in half-voxel units (integers) until the very end, so that the same point
// reached from different faces gets the same coordinates, and is scaled once by one rounding.
using HalfUnits = std::array<int64_t, 3>;

class PartSurfaceBuilder {
 public:
  PartSurfaceBuilder(const VoxelGrid& grid, int partId, double voxelSize)
      : grid_(grid), partId_(partId), voxelSize_(voxelSize) {}

  // Emits the boundary faces of the part's voxels (given in voxel index order) and, per voxel, in
  // the face order -x, +x, -y, +y, -z, +z: a fixed order, so the output is deterministic.
  TriangleMesh build(const std::vector<int64_t>& voxels) {
    for (const int64_t i : voxels) {
      const Int3 cell = grid_.coordinates(i);
      for (int face = 0; face < 6; ++face) {
        const int axis = face / 2, sign = face % 2 == 1 ? 1 : -1;
        if (!inPart(offset(cell, axis, sign))) addFace(cell, i, axis, sign);
      }
    }
    if (mesh_.triangles.empty()) throwBadInput("", "part " + std::to_string(partId_) + " has no voxels");
    return std::move(mesh_);
  }

 private:
  static Int3 offset(Int3 cell, int axis, int step) {
    (axis == 0 ? cell.x : axis == 1 ? cell.y : cell.z) += step;
    return cell;
  }
  static int component(const Int3& cell, int axis) { return axis == 0 ? cell.x : axis == 1 ? cell.y : cell.z; }

  bool inPart(const Int3& c) const { return grid_.inside(c.x, c.y, c.z) && grid_.label(c.x, c.y, c.z) == partId_; }

  int vertexAt(const HalfUnits& position) {
    const int index = static_cast<int>(mesh_.vertices.size());
    const double half = 0.5 * voxelSize_;
    mesh_.vertices.push_back({static_cast<double>(position[0]) * half, static_cast<double>(position[1]) * half,
                              static_cast<double>(position[2]) * half});
    return index;
  }

  // One vertex per grid corner (shared by every face of the part that meets there).
  int cornerVertex(const HalfUnits& position) {
    const int64_t key =
        position[0] / 2 + (grid_.nx() + 1) * (position[1] / 2 + int64_t{grid_.ny() + 1} * (position[2] / 2));
    const auto found = cornerVertices_.find(key);
    if (found != cornerVertices_.end()) return found->second;
    const int index = vertexAt(position);
    cornerVertices_.emplace(key, index);
    return index;
  }

  // A square face of `cell` with outward normal sign * e_axis. Its corners run counter-clockwise
  // seen from outside: with u = axis+1, v = axis+2 (cyclic), e_u x e_v = e_axis, so (0,0), (1,0),
  // (1,1), (0,1) in (u, v) for the + side and the reverse for the - side.
  //
  // Pinch edges. Where two voxels of the part touch only along an edge (the other two voxels
  // around that edge are not in the part), four faces of the part meet at the edge. Pairing the two
  // faces of the same voxel (they meet at that voxel's convex edge, in opposite directions) treats
  // the two voxels as apart, which is how parts hold together anyway: through faces (the paper's
  // requirement (i) "Connected", Section 4.1, checked as face-connectivity by validateVoxelParts).
  // To keep the two pairs from sharing an edge, each pair gets its own vertex at the
  // edge's midpoint; a face with such a midpoint is fanned from its centre, so no triangle is
  // degenerate. The copies coincide in space (the solid itself pinches there), but every edge of
  // the indexed mesh belongs to exactly two triangles, and the volume is unchanged.
  void addFace(const Int3& cell, int64_t cellIndex, int axis, int sign) {
    static constexpr int kPlusSide[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static constexpr int kMinusSide[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    const auto& square = sign > 0 ? kPlusSide : kMinusSide;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::array<HalfUnits, 4> corners;
    for (int k = 0; k < 4; ++k) {
      HalfUnits& p = corners[k];
      p[axis] = 2 * (component(cell, axis) + (sign > 0 ? 1 : 0));
      p[u] = 2 * (component(cell, u) + square[k][0]);
      p[v] = 2 * (component(cell, v) + square[k][1]);
    }
    std::vector<int> polygon;
    bool pinched = false;
    for (int k = 0; k < 4; ++k) {
      polygon.push_back(cornerVertex(corners[k]));
      const HalfUnits& a = corners[k];
      const HalfUnits& b = corners[(k + 1) % 4];
      // The edge a-b runs along one tangent axis; along the other one (`side`) it sits on the
      // face's low or high border.
      const int side = a[u] == b[u] ? u : v;
      const int sideStep = a[side] == 2 * component(cell, side) ? -1 : 1;
      const Int3 beside = offset(cell, side, sideStep);
      const Int3 diagonal = offset(beside, axis, sign);
      if (inPart(diagonal) && !inPart(beside)) {
        pinched = true;
        polygon.push_back(midpointVertex(a, b, cellIndex));
      }
    }
    if (!pinched) {
      mesh_.triangles.push_back({polygon[0], polygon[1], polygon[2]});
      mesh_.triangles.push_back({polygon[0], polygon[2], polygon[3]});
      return;
    }
    HalfUnits centre;
    for (int c = 0; c < 3; ++c) centre[c] = (corners[0][c] + corners[2][c]) / 2;
    const int centreVertex = vertexAt(centre);
    for (size_t k = 0; k < polygon.size(); ++k) {
      mesh_.triangles.push_back({centreVertex, polygon[k], polygon[(k + 1) % polygon.size()]});
    }
  }

  // The midpoint of a pinch edge, one copy per voxel at the edge (shared by that voxel's two faces).
  int midpointVertex(const HalfUnits& a, const HalfUnits& b, int64_t cellIndex) {
    HalfUnits middle;
    for (int c = 0; c < 3; ++c) middle[c] = (a[c] + b[c]) / 2;
    const auto key = std::make_pair(middle, cellIndex);
    const auto found = midpointVertices_.find(key);
    if (found != midpointVertices_.end()) return found->second;
    const int index = vertexAt(middle);
    midpointVertices_.emplace(key, index);
    return index;
  }

  const VoxelGrid& grid_;
  const int partId_;
  const double voxelSize_;
  TriangleMesh mesh_;
  // Looked up only; vertices are numbered in order of first use, never by iterating these maps.
  std::unordered_map<int64_t, int> cornerVertices_;
  std::map<std::pair<HalfUnits, int64_t>, int> midpointVertices_;
};

}  // namespace

std::vector<std::vector<int64_t>> voxelsByPart(const VoxelGrid& grid) {
  std::vector<std::vector<int64_t>> voxels(static_cast<size_t>(grid.maxLabel()) + 1);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) > 0) voxels[grid.labelAt(i)].push_back(i);
  }
  return voxels;
}

TriangleMesh surfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels, double voxelSize) {
  return PartSurfaceBuilder(grid, partId, voxelSize).build(voxels);
}

TriangleMesh partSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize) {
  std::vector<int64_t> voxels;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == partId) voxels.push_back(i);
  }
  return surfaceOfVoxels(grid, partId, voxels, voxelSize);
}

}  // namespace desia
