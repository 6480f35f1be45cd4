// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a mesh assembly as voxels (issue 29): when every face of every part is square to three
// common axes and every vertex lies on one lattice of those axes, the parts are unions of its cells
// and the complete voxel disassembler (paper Section 3.3; BurrTools' moves of several parts) can
// plan them. The frame is found from the face normals, so a rotated model or one in other units
// reads the same; the test of the lattice is exact once the vertices are rounded to it.
#include "mesh/mesh_lattice.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "desia/tolerances.h"

namespace desia::mesh {
namespace {

// A grid of more cells is not read as voxels: the voxel planners' work grows with the cells.
constexpr int64_t kMostLatticeCells = int64_t{1} << 22;
// The lattice's pitch along an axis is the smallest gap between vertex levels divided by 1, 2, ...
// up to this (gaps of 1 and 1.5 units need halves).
constexpr int kMostPitchDivisions = 12;

using LatticePoint = std::array<int64_t, 3>;

bool facesAlong(const Vec3& normal, const Vec3& axis) {
  return std::abs(dot(normal, axis)) >= 1 - tolerance::kFacingCosine;
}

// Three orthonormal axes every triangle of the parts faces along (within kFacingCosine), each the
// area-weighted mean of its faces' normals, ordered and signed to lie nearest +x, +y, +z (a model
// drawn square to the world keeps its axes), the third made right-handed (so that integer normals
// keep their sign). Nothing otherwise.
std::optional<std::array<Vec3, 3>> latticeAxes(const std::vector<PartGeometry>& geometry) {
  std::vector<Vec3> found, sums;
  for (const PartGeometry& part : geometry) {
    for (const Triangle& t : part.triangles) {
      if (t.twiceArea <= 0 || norm(t.normal) == 0) continue;
      size_t k = 0;
      while (k < found.size() && !facesAlong(t.normal, found[k])) ++k;
      if (k == found.size()) {
        if (found.size() == 3) return std::nullopt;
        found.push_back(t.normal);
        sums.push_back({0, 0, 0});
      }
      const double sign = dot(t.normal, found[k]) > 0 ? 1 : -1;
      sums[k] = plus(sums[k], scaled(t.normal, sign * t.twiceArea));
    }
  }
  if (found.size() != 3) return std::nullopt;
  std::array<Vec3, 3> axes{};
  std::vector<bool> used(3, false);
  for (size_t world = 0; world < 3; ++world) {
    size_t best = 3;
    for (size_t k = 0; k < 3; ++k) {
      if (!used[k] && (best == 3 || std::abs(sums[k][world]) > std::abs(sums[best][world]))) best = k;
    }
    used[best] = true;
    axes[world] = normalized(sums[best][world] < 0 ? negated(sums[best]) : sums[best]);
  }
  // Square to each other up to rounding; whether the faces really are is the lattice's exact test.
  axes[1] = normalized(minus(axes[1], scaled(axes[0], dot(axes[1], axes[0]))));
  axes[2] = cross(axes[0], axes[1]);
  return axes;
}

// The lattice along one axis: cells of `pitch` from `start` (the faces square to the axis lie on
// their boundaries), and vertices on `subdivision` finer levels (a part's surface may have vertices
// between the faces' levels, as desia's voxel exports have where voxels meet along an edge).
struct AxisLattice {
  double start = 0;  // mm along the axis, of the lowest face
  double pitch = 0;  // mm
  int64_t cells = 0;
  int64_t subdivision = 1;
};

bool onLevels(const std::vector<double>& values, double start, double pitch, double tolerance) {
  return std::all_of(values.begin(), values.end(), [&](double value) {
    const double along = (value - start) / pitch;
    return std::abs(along - std::round(along)) * pitch <= tolerance;
  });
}

// The coarsest lattice on which every face level lies within `tolerance`: the span over a whole
// number of cells near the smallest gap between levels (or a division of it); then the fewest
// subdivisions of its cells that hold every vertex.
std::optional<AxisLattice> axisLattice(std::vector<double> faceLevels, const std::vector<double>& vertexLevels,
                                       double tolerance) {
  if (faceLevels.empty()) return std::nullopt;
  std::sort(faceLevels.begin(), faceLevels.end());
  std::vector<double> levels;
  for (double value : faceLevels) {
    if (levels.empty() || value - levels.back() > tolerance) levels.push_back(value);
  }
  const double span = faceLevels.back() - faceLevels.front();
  if (levels.size() < 2 || span <= tolerance) return std::nullopt;
  double smallestGap = span;
  for (size_t k = 1; k < levels.size(); ++k) smallestGap = std::min(smallestGap, levels[k] - levels[k - 1]);
  AxisLattice axis;
  axis.start = faceLevels.front();
  for (int division = 1; division <= kMostPitchDivisions && axis.cells == 0; ++division) {
    const double cells = std::round(span / (smallestGap / division));
    if (cells < 1 || cells > static_cast<double>(VoxelLimits::kMaxSide)) break;
    if (onLevels(faceLevels, axis.start, span / cells, tolerance)) axis.cells = static_cast<int64_t>(cells), axis.pitch = span / cells;
  }
  if (axis.cells == 0) return std::nullopt;
  for (axis.subdivision = 1; axis.subdivision <= kMostPitchDivisions; ++axis.subdivision) {
    if (onLevels(vertexLevels, axis.start, axis.pitch / static_cast<double>(axis.subdivision), tolerance)) return axis;
  }
  return std::nullopt;
}

using Point2 = std::array<int64_t, 2>;

int sign(int64_t value) { return (value > 0) - (value < 0); }

// The side of the directed line a -> b that the point q + (1/K, 1/K^2) lies on, for K larger than
// twice the grid's side in fine units (simulation of simplicity): the sign of the integer cross
// product when it is not 0, else that of the perturbation's share, -dy/K + dx/K^2. Never 0 for
// a != b: the point lies on no line through two lattice points of the grid.
int perturbedSide(const Point2& a, const Point2& b, const Point2& q) {
  const int64_t dx = b[0] - a[0], dy = b[1] - a[1];
  const int exact = sign(dx * (q[1] - a[1]) - dy * (q[0] - a[0]));
  if (exact != 0) return exact;
  return dy != 0 ? -sign(dy) : sign(dx);
}

// Fills the grid with part `label`'s cells: those of positive winding number. Along the z column
// through a point just inside cell (x, y) (its low corner moved by (1/K, 1/K^2) fine units), the
// winding number rises by one at each face entered (normal -z) and falls at each face left; the
// point lies inside exactly one triangle of a face that covers it, never on an edge, and no face
// square to x or y holds it. Vertices in fine units (`subdivision` of them per cell and axis).
// False when a triangle is not square to an axis, a face lies between cells, or a cell is
// another part's already.
bool fillPart(const std::vector<LatticePoint>& vertices, const std::vector<std::array<int, 3>>& triangles,
              const std::array<int64_t, 3>& subdivision, int label, VoxelGrid& grid) {
  LatticePoint lo{INT64_MAX, INT64_MAX, INT64_MAX}, hi{INT64_MIN, INT64_MIN, INT64_MIN};
  for (const LatticePoint& v : vertices) {
    for (size_t i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v[i]), hi[i] = std::max(hi[i], v[i]);
  }
  for (size_t i = 0; i < 3; ++i) {
    if (lo[i] % subdivision[i] != 0 || hi[i] % subdivision[i] != 0) return false;
    lo[i] /= subdivision[i], hi[i] /= subdivision[i];
  }
  const int64_t nx = hi[0] - lo[0], ny = hi[1] - lo[1], nz = hi[2] - lo[2];
  if (nx < 1 || ny < 1 || nz < 1) return false;
  std::vector<int> rise(static_cast<size_t>(nx * ny * (nz + 1)), 0);
  for (const std::array<int, 3>& t : triangles) {
    const LatticePoint &a = vertices[static_cast<size_t>(t[0])], &b = vertices[static_cast<size_t>(t[1])],
               &c = vertices[static_cast<size_t>(t[2])];
    const LatticePoint u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const LatticePoint n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const int square = (n[0] != 0) + (n[1] != 0) + (n[2] != 0);
    if (square == 0) continue;  // no area
    if (square > 1) return false;
    for (size_t i = 0; i < 3; ++i) {
      if (n[i] != 0 && a[i] % subdivision[i] != 0) return false;  // a face between cells
    }
    if (n[2] == 0) continue;  // parallel to the columns
    const int delta = n[2] < 0 ? 1 : -1;
    std::array<Point2, 3> corners{{{a[0], a[1]}, {b[0], b[1]}, {c[0], c[1]}}};
    if (n[2] < 0) std::swap(corners[1], corners[2]);  // counter-clockwise seen from +z
    const auto cellRange = [&](size_t i, int64_t* first, int64_t* last) {
      const int64_t low = std::min({a[i], b[i], c[i]}), high = std::max({a[i], b[i], c[i]});
      *first = low / subdivision[i] - lo[i];  // vertices are >= 0: division floors
      *last = (high + subdivision[i] - 1) / subdivision[i] - lo[i];
    };
    int64_t x0, x1, y0, y1;
    cellRange(0, &x0, &x1);
    cellRange(1, &y0, &y1);
    const int64_t level = a[2] / subdivision[2] - lo[2];
    for (int64_t y = y0; y < y1; ++y) {
      for (int64_t x = x0; x < x1; ++x) {
        const Point2 q{(lo[0] + x) * subdivision[0], (lo[1] + y) * subdivision[1]};
        if (perturbedSide(corners[0], corners[1], q) > 0 && perturbedSide(corners[1], corners[2], q) > 0 &&
            perturbedSide(corners[2], corners[0], q) > 0) {
          rise[static_cast<size_t>((level * ny + y) * nx + x)] += delta;
        }
      }
    }
  }
  for (int64_t y = 0; y < ny; ++y) {
    for (int64_t x = 0; x < nx; ++x) {
      int winding = 0;
      for (int64_t z = 0; z < nz; ++z) {
        winding += rise[static_cast<size_t>((z * ny + y) * nx + x)];
        if (winding <= 0) continue;
        const int gx = static_cast<int>(lo[0] + x), gy = static_cast<int>(lo[1] + y), gz = static_cast<int>(lo[2] + z);
        if (grid.label(gx, gy, gz) != 0) return false;
        grid.setLabel(gx, gy, gz, label);
      }
    }
  }
  return true;
}

}  // namespace

std::optional<MeshLattice> meshLattice(const MeshAssembly& meshes) {
  const std::vector<PartGeometry>& geometry = geometryOf(meshes);
  const auto axes = latticeAxes(geometry);
  if (!axes) return std::nullopt;
  MeshLattice lattice;
  lattice.axes = *axes;
  std::array<AxisLattice, 3> along{};
  int64_t cells = 1;
  for (size_t k = 0; k < 3; ++k) {
    std::vector<double> faceLevels, vertexLevels;
    for (const PartGeometry& part : geometry) {
      for (const Triangle& t : part.triangles) {
        if (t.twiceArea > 0 && facesAlong(t.normal, lattice.axes[k])) faceLevels.push_back(dot(t.p[0], lattice.axes[k]));
      }
    }
    for (const MeshPart& part : meshes.parts) {
      for (const Vec3& v : part.mesh.vertices) vertexLevels.push_back(dot(v, lattice.axes[k]));
    }
    const auto axis = axisLattice(std::move(faceLevels), vertexLevels, meshes.tolerance);
    if (!axis) return std::nullopt;
    along[k] = *axis;
    lattice.pitch[k] = axis->pitch;
    cells *= axis->cells;
    if (cells > kMostLatticeCells) return std::nullopt;
  }
  for (size_t k = 0; k < 3; ++k) lattice.corner = plus(lattice.corner, scaled(lattice.axes[k], along[k].start));
  lattice.grid = VoxelGrid(static_cast<int>(along[0].cells), static_cast<int>(along[1].cells), static_cast<int>(along[2].cells));
  const std::array<int64_t, 3> subdivision{along[0].subdivision, along[1].subdivision, along[2].subdivision};
  for (size_t p = 0; p < meshes.parts.size(); ++p) {
    const TriangleMesh& mesh = meshes.parts[p].mesh;
    std::vector<LatticePoint> vertices;
    for (const Vec3& v : mesh.vertices) {
      LatticePoint at{};
      for (size_t k = 0; k < 3; ++k) {
        const double fine = along[k].pitch / static_cast<double>(along[k].subdivision);
        at[k] = std::llround((dot(v, lattice.axes[k]) - along[k].start) / fine);
      }
      vertices.push_back(at);
    }
    if (!fillPart(vertices, mesh.triangles, subdivision, static_cast<int>(p + 1), lattice.grid)) return std::nullopt;
  }
  const std::vector<int64_t> counts = lattice.grid.labelCounts();
  if (counts.size() != meshes.parts.size() + 1) return std::nullopt;
  for (size_t label = 1; label < counts.size(); ++label) {
    if (counts[label] == 0) return std::nullopt;
  }
  return lattice;
}

}  // namespace desia::mesh
