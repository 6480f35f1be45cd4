// SPDX-License-Identifier: GPL-3.0-or-later
// Solid voxelization by exact ray parity (written for desia).
//
// A voxel belongs to the solid when its centre lies inside the closed mesh. For every row of voxel
// centres along x (one per (y, z) centre) we count the triangles the row's ray crosses: a point is
// inside a closed surface exactly when a ray from it crosses the surface an odd number of times.
//
// Exactness. Vertices are snapped to an integer lattice of 2^20 steps per voxel (1024 voxels per
// side at most, so coordinates are in [0, 2^30]); voxel centres lie on the same lattice. The snap
// uses only IEEE basic operations (subtract, multiply, round to nearest), which give the same
// result on every platform; every decision after it is integer arithmetic: 2D orientations in the
// y-z plane (|value| < 2^62, int64) and the position of a crossing along x against the centres
// (__int128). Snapping moves a vertex by at most 2^-21 voxel and keeps the connectivity, so the
// snapped mesh is still closed and its parity is exact; only a centre within about 2^-21 voxel of
// the surface can be classified differently than for the unsnapped mesh. The grid is the same bit
// for bit natively and in WebAssembly.
//
// Ties (a ray through an edge or a vertex in the y-z projection, a centre exactly on the surface)
// follow one rule, the outcome of moving the centre by infinitesimals (+e, +e^2, +e^3) along
// (x, y, z), e -> 0: a projected edge owns the points on it when the triangle lies on its +y
// side, or on its +z side for an edge parallel to y (the "top-left" rule of rasterizers, for this
// perturbation). Two triangles sharing an edge lie on opposite sides of it in projection unless
// the surface folds there, so a ray through a shared edge or vertex is counted exactly as a ray
// through a nearby generic point would be: never twice, never missed. Triangles seen edge-on
// (zero projected area) contain no perturbed point. Along x, a crossing at the centre counts as
// behind it. Net effect: a centre on the surface is inside exactly when the solid extends from it
// towards +x, +y, +z (lower faces in, upper faces out), as for half-open boxes [a, b).
//
// Cost: each triangle visits the rows whose centres fall in its projected bounding box and flips
// one voxel per crossing (flips commute, so the order of triangles does not matter); one pass
// per row then turns the flips into parity. No sorting, no per-row lists.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/tolerances.h"
#include "desia/voxel.h"

namespace desia {
namespace {

using Int128 = __int128;

constexpr int64_t kSubdivisions = int64_t{1} << 20;  // lattice steps per voxel
constexpr int64_t kHalfVoxel = kSubdivisions / 2;    // centres sit at j * kSubdivisions + kHalfVoxel

struct Point {
  int64_t x, y, z;
};

// Twice the signed area of (a, b, p) projected to the y-z plane (positive: counterclockwise).
int64_t orient(const Point& a, const Point& b, int64_t py, int64_t pz) {
  return (b.y - a.y) * (pz - a.z) - (b.z - a.z) * (py - a.y);
}

// Does edge a->b of a counterclockwise triangle own the points on its line (see the tie rule)?
bool ownsBoundary(const Point& a, const Point& b) {
  const int64_t dy = b.y - a.y, dz = b.z - a.z;
  return dz < 0 || (dz == 0 && dy > 0);
}

bool insideEdge(int64_t w, const Point& a, const Point& b) { return w > 0 || (w == 0 && ownsBoundary(a, b)); }

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

Int128 floorDiv128(Int128 a, Int128 b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
Int128 ceilDiv128(Int128 a, Int128 b) { return -floorDiv128(-a, b); }

// First row index whose centre is >= lo, last whose centre is <= hi, clipped to [0, count).
void centreRange(int64_t lo, int64_t hi, int count, int64_t& first, int64_t& last) {
  first = std::max<int64_t>(0, ceilDiv(lo - kHalfVoxel, kSubdivisions));
  last = std::min<int64_t>(count - 1, floorDiv(hi - kHalfVoxel, kSubdivisions));
}

std::string sizeText(int nx, int ny, int nz) {
  return std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz);
}

std::string voxelText(const Int3& c) {
  return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ")";
}

// Face-connected pieces of the filled voxels: the first voxel (in index order) of each.
std::vector<int64_t> pieceSeeds(const VoxelGrid& grid) {
  static constexpr int kSteps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<int64_t> seeds;
  std::vector<bool> seen(static_cast<size_t>(grid.voxelCount()), false);
  std::vector<int64_t> stack;
  for (int64_t start = 0; start < grid.voxelCount(); ++start) {
    if (grid.labelAt(start) == 0 || seen[start]) continue;
    seeds.push_back(start);
    seen[start] = true;
    stack.push_back(start);
    while (!stack.empty()) {
      const Int3 c = grid.coordinates(stack.back());
      stack.pop_back();
      for (const auto& step : kSteps) {
        const int x = c.x + step[0], y = c.y + step[1], z = c.z + step[2];
        if (!grid.inside(x, y, z)) continue;
        const int64_t next = grid.index(x, y, z);
        if (seen[next] || grid.labelAt(next) == 0) continue;
        seen[next] = true;
        stack.push_back(next);
      }
    }
  }
  return seeds;
}

}  // namespace

VoxelGrid voxelizeSolid(const TriangleMesh& mesh, const VoxelizeOptions& options, const std::string& source) {
  const int resolution = options.resolution;
  if (resolution < 1 || resolution > VoxelLimits::kMaxSide) {
    throw Error(resolution < 1 ? ErrorCode::BadInput : ErrorCode::TooLarge,
                (source.empty() ? "" : source + ": ") + "resolution " + std::to_string(resolution) +
                    " is out of range (1 to " + std::to_string(VoxelLimits::kMaxSide) +
                    " voxels along the longest side)");
  }
  checkClosedMesh(mesh, source);

  // Bounding box of the vertices the triangles use.
  std::array<double, 3> lo{}, hi{};
  lo = hi = mesh.vertices[mesh.triangles[0][0]];
  for (const auto& triangle : mesh.triangles) {
    for (int v : triangle) {
      for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::min(lo[axis], mesh.vertices[v][axis]);
        hi[axis] = std::max(hi[axis], mesh.vertices[v][axis]);
      }
    }
  }
  static const char* kAxis[3] = {"x", "y", "z"};
  std::array<double, 3> extent{};
  int longest = 0;
  for (int axis = 0; axis < 3; ++axis) {
    extent[axis] = hi[axis] - lo[axis];
    if (!std::isfinite(extent[axis])) {
      throwBadInput(source, std::string("the coordinates span too large a range along ") + kAxis[axis] +
                                " to be measured in double precision");
    }
    if (extent[axis] == 0) {
      char value[64];
      std::snprintf(value, sizeof value, "%.17g", lo[axis]);
      throwBadInput(source, std::string("the mesh is flat: every vertex has ") + kAxis[axis] + " = " + value +
                                ", so it encloses no volume");
    }
    if (extent[axis] > extent[longest]) longest = axis;
  }
  const double maxExtent = extent[longest];

  // Grid size: `resolution` voxels along the longest side, ceil(extent / voxel size) along the
  // others. The tolerance (tolerance::kVoxelCountRounding) absorbs rounding in extent / maxExtent
  // (0.1 * 3 / 0.1 is not exactly 3); a voxel dropped by it would cover less than that fraction of
  // a voxel beyond the centres anyway.
  int size[3];
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == longest) {
      size[axis] = resolution;
    } else {
      const double voxels = extent[axis] / maxExtent * resolution;
      const double whole = std::ceil(voxels - tolerance::kVoxelCountRounding);
      size[axis] = static_cast<int>(std::clamp(whole, 1.0, static_cast<double>(resolution)));
    }
  }
  const int64_t voxelCount = static_cast<int64_t>(size[0]) * size[1] * size[2];
  if (voxelCount > VoxelLimits::kMaxVoxels) {
    throw Error(ErrorCode::TooLarge, (source.empty() ? "" : source + ": ") + "resolution " +
                                         std::to_string(resolution) + " gives a grid of " +
                                         sizeText(size[0], size[1], size[2]) + " = " + std::to_string(voxelCount) +
                                         " voxels, more than the limit of " + std::to_string(VoxelLimits::kMaxVoxels) +
                                         "; use a lower resolution");
  }

  // Snap to the lattice (see the comment at the top).
  const double scale = static_cast<double>(kSubdivisions) * resolution / maxExtent;
  if (!std::isfinite(scale)) throwBadInput(source, "the mesh is too small to voxelize (its extent underflows)");
  std::vector<Point> points(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    int64_t c[3];
    for (int axis = 0; axis < 3; ++axis) {
      // In [0, 2^30] for used vertices; unused ones may lie anywhere and are never read.
      const double t = std::nearbyint((mesh.vertices[v][axis] - lo[axis]) * scale);
      c[axis] = static_cast<int64_t>(std::clamp(t, -4.0 * (1 << 30), 4.0 * (1 << 30)));
    }
    points[v] = {c[0], c[1], c[2]};
  }

  VoxelGrid grid(size[0], size[1], size[2]);
  // Pass 1: for each crossing, flip the first voxel of the row whose centre lies beyond it.
  for (const auto& triangle : mesh.triangles) {
    Point a = points[triangle[0]], b = points[triangle[1]], c = points[triangle[2]];
    int64_t area = orient(a, b, c.y, c.z);
    if (area == 0) continue;  // seen edge-on
    if (area < 0) {
      std::swap(b, c);
      area = -area;
    }
    int64_t firstY, lastY, firstZ, lastZ;
    centreRange(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), size[1], firstY, lastY);
    centreRange(std::min({a.z, b.z, c.z}), std::max({a.z, b.z, c.z}), size[2], firstZ, lastZ);
    const Int128 denominator = static_cast<Int128>(area) * kSubdivisions;
    for (int64_t k = firstZ; k <= lastZ; ++k) {
      const int64_t pz = k * kSubdivisions + kHalfVoxel;
      for (int64_t j = firstY; j <= lastY; ++j) {
        const int64_t py = j * kSubdivisions + kHalfVoxel;
        const int64_t wa = orient(b, c, py, pz), wb = orient(c, a, py, pz), wc = orient(a, b, py, pz);
        if (!insideEdge(wa, b, c) || !insideEdge(wb, c, a) || !insideEdge(wc, a, b)) continue;
        // The crossing is at x = (wa a.x + wb b.x + wc c.x) / area; centre i is beyond it (or on
        // it) when i * kSubdivisions + kHalfVoxel >= x.
        const Int128 numerator = static_cast<Int128>(wa) * a.x + static_cast<Int128>(wb) * b.x +
                                 static_cast<Int128>(wc) * c.x - static_cast<Int128>(area) * kHalfVoxel;
        const Int128 first = std::max<Int128>(0, ceilDiv128(numerator, denominator));
        if (first >= size[0]) continue;
        const int64_t index = grid.index(static_cast<int>(first), static_cast<int>(j), static_cast<int>(k));
        grid.setLabelAt(index, grid.labelAt(index) ^ 1);
      }
    }
  }
  // Pass 2: along each row, a centre is inside when an odd number of flips lie at or before it.
  int64_t filled = 0;
  for (int k = 0; k < size[2]; ++k) {
    for (int j = 0; j < size[1]; ++j) {
      int parity = 0;
      for (int i = 0; i < size[0]; ++i) {
        parity ^= grid.label(i, j, k);
        grid.setLabel(i, j, k, parity);
        filled += parity;
      }
    }
  }

  if (filled == 0) {
    throwBadInput(source, "no voxel centre lies inside the mesh at resolution " + std::to_string(resolution) +
                              " (grid " + sizeText(size[0], size[1], size[2]) +
                              "): the resolution is too low for this shape; try a higher one");
  }
  const std::vector<int64_t> seeds = pieceSeeds(grid);
  if (seeds.size() > 1) {
    throwBadInput(source, "at resolution " + std::to_string(resolution) +
                              " the voxelized shape is not face-connected: it has " + std::to_string(seeds.size()) +
                              " separate pieces (one contains voxel " + voxelText(grid.coordinates(seeds[0])) +
                              ", another voxel " + voxelText(grid.coordinates(seeds[1])) +
                              "); a single part needs one piece: try a higher resolution");
  }
  return grid;
}

}  // namespace desia
