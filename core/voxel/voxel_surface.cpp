// SPDX-License-Identifier: GPL-3.0-or-later
// The closed surface of one part of a voxel assembly (the mesh behind the STL and OBJ exports),
// as the part is, or inset by a clearance where it touches other parts (print-ready parts).
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "desia/error.h"
#include "desia/voxel.h"

namespace desia {
namespace {

// Positions are kept in half-lattice units (integers) until the very end, so that the same point
// reached from different faces gets the same coordinates, and is turned into a position once.
using HalfUnits = std::array<int64_t, 3>;

// The part as it is: the lattice is the voxel grid, a cell is solid when it has the part's label.
class VoxelLattice {
 public:
  VoxelLattice(const VoxelGrid& grid, int partId, double voxelSize)
      : grid_(grid), partId_(partId), voxelSize_(voxelSize) {}
  Int3 cells() const { return {grid_.nx(), grid_.ny(), grid_.nz()}; }
  bool solid(const Int3& c) const { return grid_.inside(c.x, c.y, c.z) && grid_.label(c.x, c.y, c.z) == partId_; }
  double coordinate(int /*axis*/, int64_t halfUnits) const {
    return static_cast<double>(halfUnits) * (0.5 * voxelSize_);
  }

 private:
  const VoxelGrid& grid_;
  const int partId_;
  const double voxelSize_;
};

// Cells between the face planes of a set of axis-aligned boxes (line k of an axis at lines[k]);
// a cell is solid when a box holds it.
class RectilinearLattice {
 public:
  RectilinearLattice(std::array<std::vector<double>, 3> lines, std::vector<uint8_t> solid)
      : lines_(std::move(lines)), solid_(std::move(solid)) {}
  Int3 cells() const {
    return {static_cast<int>(lines_[0].size()) - 1, static_cast<int>(lines_[1].size()) - 1,
            static_cast<int>(lines_[2].size()) - 1};
  }
  bool solid(const Int3& c) const {
    const Int3 n = cells();
    if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= n.x || c.y >= n.y || c.z >= n.z) return false;
    return solid_[static_cast<size_t>(c.x + int64_t{n.x} * (c.y + int64_t{n.y} * c.z))] != 0;
  }
  double coordinate(int axis, int64_t halfUnits) const {
    const std::vector<double>& lines = lines_[axis];
    if (halfUnits % 2 == 0) return lines[static_cast<size_t>(halfUnits / 2)];
    return 0.5 * (lines[static_cast<size_t>(halfUnits / 2)] + lines[static_cast<size_t>(halfUnits / 2 + 1)]);
  }

 private:
  const std::array<std::vector<double>, 3> lines_;
  const std::vector<uint8_t> solid_;
};

// The part inset by the clearance c where it touches another part. Every voxel is split into
// 3 x 3 x 3 cells by the planes at c and s - c (s the voxel size) along each axis, and a cell of
// the part is left out when it lies within c of another part:
// - across a face of its voxel: the face between two parts moves in by c (the inset);
// - across an edge or a corner of its voxel, when every voxel around that edge or corner is filled:
//   that is a concave edge (or corner) of the part with inset faces on both sides, whose offset
//   planes meet c further in along both axes (without it a c x c ridge would stay in the corner).
// Where an inset face meets a face against empty space in the same plane, the cells beyond the
// inset stay, so the outer face keeps its place and a step of height c joins the two. Outer faces
// never move: a cell is only taken away towards another part. The middle cell of every voxel and
// the middle cells of its faces towards the same part always stay (c < s / 2), so the inset part
// is still one face-connected solid and the lattice surface is closed as before.
class InsetLattice {
 public:
  InsetLattice(const VoxelGrid& grid, int partId, double voxelSize, double clearance)
      : grid_(grid), partId_(partId), voxelSize_(voxelSize), clearance_(clearance) {}
  Int3 cells() const { return {3 * grid_.nx(), 3 * grid_.ny(), 3 * grid_.nz()}; }
  bool solid(const Int3& c) const {
    if (c.x < 0 || c.y < 0 || c.z < 0) return false;
    const Int3 voxel{c.x / 3, c.y / 3, c.z / 3};
    if (label(voxel) != partId_) return false;
    return !withinClearanceOfAnotherPart(voxel, {sideOf(c.x), sideOf(c.y), sideOf(c.z)});
  }
  // Lattice line k lies at voxel k / 3, plus 0, c or s - c; a half unit between two lines (the
  // midpoint of a pinch edge, the centre of a fanned face) halfway between them.
  double coordinate(int /*axis*/, int64_t halfUnits) const {
    if (halfUnits % 2 == 0) return linePosition(halfUnits / 2);
    return 0.5 * (linePosition(halfUnits / 2) + linePosition(halfUnits / 2 + 1));
  }

 private:
  // -1, 0 or +1: the cell lies at the low side, the middle or the high side of its voxel.
  static int sideOf(int cell) { return cell % 3 - 1; }

  double linePosition(int64_t line) const {
    const double base = static_cast<double>(line / 3) * voxelSize_;
    switch (line % 3) {
      case 1:
        return base + clearance_;
      case 2:
        return base + (voxelSize_ - clearance_);
      default:
        return base;
    }
  }

  int label(const Int3& v) const { return grid_.inside(v.x, v.y, v.z) ? grid_.label(v.x, v.y, v.z) : 0; }

  // The voxel `voxel` + side restricted to the axes in `axes` (bit k = axis k).
  static Int3 towards(const Int3& voxel, const Int3& side, int axes) {
    return {voxel.x + ((axes & 1) ? side.x : 0), voxel.y + ((axes & 2) ? side.y : 0),
            voxel.z + ((axes & 4) ? side.z : 0)};
  }

  bool withinClearanceOfAnotherPart(const Int3& voxel, const Int3& side) const {
    const int sideAxes = (side.x != 0 ? 1 : 0) | (side.y != 0 ? 2 : 0) | (side.z != 0 ? 4 : 0);
    // Each non-empty set of the cell's side axes names one neighbour of the voxel: across a face
    // (one axis), an edge (two) or a corner (three).
    for (int axes = 1; axes < 8; ++axes) {
      if ((axes & ~sideAxes) != 0) continue;
      const int other = label(towards(voxel, side, axes));
      if (other == 0 || other == partId_) continue;
      if (closedAround(voxel, side, axes)) return true;
    }
    return false;
  }

  // Every voxel between `voxel` and its neighbour across `axes` (those across the proper non-empty
  // subsets of `axes`) is filled, by any part: no empty space reaches the edge or corner.
  bool closedAround(const Int3& voxel, const Int3& side, int axes) const {
    for (int between = (axes - 1) & axes; between > 0; between = (between - 1) & axes) {
      if (label(towards(voxel, side, between)) == 0) return false;
    }
    return true;
  }

  const VoxelGrid& grid_;
  const int partId_;
  const double voxelSize_;
  const double clearance_;
};

// The surface of the solid cells of a lattice (VoxelLattice or InsetLattice): one square per cell
// face whose neighbour is not solid.
template <typename Lattice>
class PartSurfaceBuilder {
 public:
  PartSurfaceBuilder(const Lattice& lattice, int partId) : lattice_(lattice), partId_(partId), size_(lattice.cells()) {}

  // Emits the boundary faces of a solid cell in the face order -x, +x, -y, +y, -z, +z; called for
  // the cells in a fixed order, so the output is deterministic.
  void addCell(const Int3& cell) {
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2, sign = face % 2 == 1 ? 1 : -1;
      if (!inPart(offset(cell, axis, sign))) addFace(cell, axis, sign);
    }
  }

  TriangleMesh take() {
    if (mesh_.triangles.empty()) throwBadInput("", "part " + std::to_string(partId_) + " has no voxels");
    // Two cells of the part that share only a corner: a copy of the corner for each.
    splitPinchedVertices(mesh_);
    return std::move(mesh_);
  }

 private:
  static Int3 offset(Int3 cell, int axis, int step) {
    (axis == 0 ? cell.x : axis == 1 ? cell.y : cell.z) += step;
    return cell;
  }
  static int component(const Int3& cell, int axis) { return axis == 0 ? cell.x : axis == 1 ? cell.y : cell.z; }

  bool inPart(const Int3& c) const { return lattice_.solid(c); }

  int64_t cellIndex(const Int3& c) const { return c.x + int64_t{size_.x} * (c.y + int64_t{size_.y} * c.z); }

  int vertexAt(const HalfUnits& position) {
    const int index = static_cast<int>(mesh_.vertices.size());
    mesh_.vertices.push_back({lattice_.coordinate(0, position[0]), lattice_.coordinate(1, position[1]),
                              lattice_.coordinate(2, position[2])});
    return index;
  }

  // One vertex per lattice corner (shared by every face of the part that meets there).
  int cornerVertex(const HalfUnits& position) {
    const int64_t key =
        position[0] / 2 + (size_.x + 1) * (position[1] / 2 + int64_t{size_.y + 1} * (position[2] / 2));
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
  void addFace(const Int3& cell, int axis, int sign) {
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
        polygon.push_back(midpointVertex(a, b, cellIndex(cell)));
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
  int midpointVertex(const HalfUnits& a, const HalfUnits& b, int64_t cell) {
    HalfUnits middle;
    for (int c = 0; c < 3; ++c) middle[c] = (a[c] + b[c]) / 2;
    const auto key = std::make_pair(middle, cell);
    const auto found = midpointVertices_.find(key);
    if (found != midpointVertices_.end()) return found->second;
    const int index = vertexAt(middle);
    midpointVertices_.emplace(key, index);
    return index;
  }

  const Lattice& lattice_;
  const int partId_;
  const Int3 size_;
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
  const VoxelLattice lattice(grid, partId, voxelSize);
  PartSurfaceBuilder<VoxelLattice> builder(lattice, partId);
  for (const int64_t i : voxels) builder.addCell(grid.coordinates(i));
  return builder.take();
}

namespace {

// Are all 26 voxels around `v` in part `partId`? Then no other part and no empty space lies
// within one voxel of it: its 27 inset cells are all solid, and so are all cells next to them, so
// it adds no face (skipping it keeps the inset export's work near the part's surface).
bool surroundedByItsPart(const VoxelGrid& grid, const Int3& v, int partId) {
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = v.x + dx, y = v.y + dy, z = v.z + dz;
        if (!grid.inside(x, y, z) || grid.label(x, y, z) != partId) return false;
      }
    }
  }
  return true;
}

}  // namespace

TriangleMesh insetSurfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels,
                                  double voxelSize, double clearance) {
  if (clearance == 0) return surfaceOfVoxels(grid, partId, voxels, voxelSize);
  const InsetLattice lattice(grid, partId, voxelSize, clearance);
  PartSurfaceBuilder<InsetLattice> builder(lattice, partId);
  // Voxel by voxel in index order, each voxel's 27 cells in lattice index order.
  for (const int64_t i : voxels) {
    const Int3 v = grid.coordinates(i);
    if (surroundedByItsPart(grid, v, partId)) continue;
    for (int dz = 0; dz < 3; ++dz) {
      for (int dy = 0; dy < 3; ++dy) {
        for (int dx = 0; dx < 3; ++dx) {
          const Int3 cell{3 * v.x + dx, 3 * v.y + dy, 3 * v.z + dz};
          if (lattice.solid(cell)) builder.addCell(cell);
        }
      }
    }
  }
  return builder.take();
}

namespace {

std::vector<int64_t> voxelsOfPart(const VoxelGrid& grid, int partId) {
  std::vector<int64_t> voxels;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == partId) voxels.push_back(i);
  }
  return voxels;
}

}  // namespace

namespace {

// The first line at or above `value` (within `same`): lines are sorted and apart by more than `same`.
int lineAt(const std::vector<double>& lines, double value, double same) {
  return static_cast<int>(std::lower_bound(lines.begin(), lines.end(), value - same) - lines.begin());
}

}  // namespace

TriangleMesh surfaceOfBoxUnion(const std::vector<AxisAlignedBox>& boxes, double sameCoordinate) {
  if (boxes.empty()) throwBadInput("", "a union of boxes needs at least one box");
  // The face planes along each axis, sorted; a value within `sameCoordinate` of the last plane kept
  // is that plane (the lowest value of a run stands for it, so the result does not depend on order).
  std::array<std::vector<double>, 3> lines;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values;
    for (const AxisAlignedBox& box : boxes) {
      if (!(box.hi[axis] - box.lo[axis] > sameCoordinate)) throwBadInput("", "a box of the union has no volume");
      values.push_back(box.lo[axis]);
      values.push_back(box.hi[axis]);
    }
    std::sort(values.begin(), values.end());
    for (double value : values) {
      if (lines[axis].empty() || value > lines[axis].back() + sameCoordinate) lines[axis].push_back(value);
    }
  }
  const int64_t nx = static_cast<int64_t>(lines[0].size()) - 1, ny = static_cast<int64_t>(lines[1].size()) - 1,
                nz = static_cast<int64_t>(lines[2].size()) - 1;
  constexpr int64_t kMaxCells = int64_t{1} << 24;
  if (nx * ny * nz > kMaxCells) {
    throw Error(ErrorCode::TooLarge, "a union of " + std::to_string(boxes.size()) + " boxes needs " +
                                         std::to_string(nx * ny * nz) + " cells, more than 2^24");
  }
  std::vector<uint8_t> solid(static_cast<size_t>(nx * ny * nz), 0);
  for (const AxisAlignedBox& box : boxes) {
    std::array<int, 3> from{}, to{};
    for (int axis = 0; axis < 3; ++axis) {
      from[axis] = lineAt(lines[axis], box.lo[axis], sameCoordinate);
      to[axis] = lineAt(lines[axis], box.hi[axis], sameCoordinate);
    }
    for (int z = from[2]; z < to[2]; ++z) {
      for (int y = from[1]; y < to[1]; ++y) {
        for (int x = from[0]; x < to[0]; ++x) solid[static_cast<size_t>(x + nx * (y + ny * z))] = 1;
      }
    }
  }
  const RectilinearLattice lattice(lines, solid);
  PartSurfaceBuilder<RectilinearLattice> builder(lattice, 1);
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        if (solid[static_cast<size_t>(x + nx * (y + ny * z))] != 0) builder.addCell({x, y, z});
      }
    }
  }
  return builder.take();
}

TriangleMesh partSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize) {
  return surfaceOfVoxels(grid, partId, voxelsOfPart(grid, partId), voxelSize);
}

TriangleMesh insetPartSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize, double clearance) {
  requireValidClearance(voxelSize, clearance, "");
  return insetSurfaceOfVoxels(grid, partId, voxelsOfPart(grid, partId), voxelSize, clearance);
}

void requireValidClearance(double voxelSize, double clearance, const std::string& source) {
  if (!(clearance >= 0 && clearance < voxelSize / 2)) {
    // Nine significant digits, as the exports print numbers (and -0 as 0).
    const auto text = [](double value) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.9g", value + 0.0);
      return std::string(buffer);
    };
    throwBadInput(source, "the clearance must be at least 0 and less than half the voxel size (" +
                              text(voxelSize / 2) + "), got " + text(clearance));
  }
}

}  // namespace desia
