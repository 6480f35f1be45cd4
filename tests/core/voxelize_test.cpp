// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh readers (OBJ, STL), the closed-mesh check and solid voxelization. Meshes are built here;
// expected grids come from hand counts or from an independent point-in-mesh test (the winding
// number, summed solid angles), never from the voxelizer itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/formats.h"
#include "desia/voxel.h"

namespace desia {
namespace {

using Vec = std::array<double, 3>;

// ---- meshes ------------------------------------------------------------------------------------

// Axis-aligned box, outward-facing triangles. Corner (i, j, k) in {0,1}^3 is vertex i + 2j + 4k.
TriangleMesh boxMesh(Vec lo, Vec hi) {
  TriangleMesh mesh;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) mesh.vertices.push_back({i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]});
    }
  }
  mesh.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  return mesh;
}

// Appends `other` (optionally with every triangle reversed) to `mesh`.
void append(TriangleMesh& mesh, const TriangleMesh& other, bool reversed = false) {
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (auto t : other.triangles) {
    if (reversed) std::swap(t[1], t[2]);
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
}

// |x| + |y| + |z| <= 1: six vertices on the axes, eight faces.
TriangleMesh octahedronMesh() {
  TriangleMesh mesh;
  mesh.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int sx : {0, 1}) {
    for (int sy : {2, 3}) {
      for (int sz : {4, 5}) {
        // Outward when (x, y, z) of the octant has an even number of negative signs.
        const bool flip = ((sx == 1) + (sy == 3) + (sz == 5)) % 2 == 1;
        mesh.triangles.push_back(flip ? std::array<int, 3>{sx, sz, sy} : std::array<int, 3>{sx, sy, sz});
      }
    }
  }
  return mesh;
}

// A lumpy, tilted ball: a cube's surface divided into n x n squares per face, each lattice point
// pushed onto a bumpy sphere. Only + - * / and sqrt (exact in IEEE arithmetic on every platform, no
// libm), so the mesh is the same bit for bit natively and in WebAssembly, and irregular enough
// that no voxel centre lies on it.
TriangleMesh lumpyBallMesh(int n) {
  TriangleMesh mesh;
  std::map<std::array<int, 3>, int> ids;
  auto vertex = [&](std::array<int, 3> q) {
    auto it = ids.find(q);
    if (it != ids.end()) return it->second;
    Vec p{2.0 * q[0] / n - 1, 2.0 * q[1] / n - 1, 2.0 * q[2] / n - 1};
    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& c : p) c /= length;
    const double r = 1.0 + 0.3 * p[0] * p[1] - 0.2 * p[2] * p[2] + 0.15 * p[0] * p[1] * p[2] + 0.1 * p[1];
    // Squash z, tilt about z (cos 3/5, sin 4/5) and shift off the lattice.
    const Vec s{r * p[0], r * p[1], 0.8 * r * p[2]};
    mesh.vertices.push_back({0.6 * s[0] - 0.8 * s[1] + 0.123, 0.8 * s[0] + 0.6 * s[1] - 0.071, s[2] + 0.031});
    ids[q] = static_cast<int>(mesh.vertices.size()) - 1;
    return ids[q];
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side : {0, n}) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          std::array<std::array<int, 3>, 4> q;
          for (auto& corner : q) corner[axis] = side;
          q[0][u] = i, q[0][v] = j;
          q[1][u] = i + 1, q[1][v] = j;
          q[2][u] = i + 1, q[2][v] = j + 1;
          q[3][u] = i, q[3][v] = j + 1;
          if (side == 0) std::swap(q[1], q[3]);
          const int a = vertex(q[0]), b = vertex(q[1]), c = vertex(q[2]), d = vertex(q[3]);
          mesh.triangles.push_back({a, b, c});
          mesh.triangles.push_back({a, c, d});
        }
      }
    }
  }
  return mesh;
}

// The boundary of a set of unit cubes (cell (x, y, z) = [x, x+1] x [y, y+1] x [z, z+1]), two
// triangles per exposed square, diagonals alternating. Vertices are shared; the set must not
// have cells touching along an edge only (that edge would belong to four triangles).
TriangleMesh cubeSetMesh(const std::vector<std::array<int, 3>>& cells) {
  std::map<std::array<int, 3>, bool> filled;
  for (const auto& c : cells) filled[c] = true;
  std::map<std::array<int, 3>, int> ids;
  TriangleMesh mesh;
  auto vertex = [&](std::array<int, 3> p) {
    auto it = ids.find(p);
    if (it != ids.end()) return it->second;
    const int id = static_cast<int>(mesh.vertices.size());
    ids[p] = id;
    mesh.vertices.push_back({double(p[0]), double(p[1]), double(p[2])});
    return id;
  };
  for (const auto& c : cells) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int side : {-1, 1}) {
        std::array<int, 3> neighbour = c;
        neighbour[axis] += side;
        if (filled.count(neighbour)) continue;
        // The square's corners, counterclockwise seen from outside.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<int, 3> base = c;
        if (side > 0) base[axis] += 1;
        std::array<std::array<int, 3>, 4> q{base, base, base, base};
        q[1][u] += 1;
        q[2][u] += 1;
        q[2][v] += 1;
        q[3][v] += 1;
        if (side < 0) std::swap(q[1], q[3]);
        const int a = vertex(q[0]), b = vertex(q[1]), cc = vertex(q[2]), d = vertex(q[3]);
        if ((c[0] + c[1] + c[2] + axis) % 2 == 0) {
          mesh.triangles.push_back({a, b, cc});
          mesh.triangles.push_back({a, cc, d});
        } else {
          mesh.triangles.push_back({a, b, d});
          mesh.triangles.push_back({b, cc, d});
        }
      }
    }
  }
  return mesh;
}

// ---- formats -----------------------------------------------------------------------------------

std::string objText(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  for (const auto& v : mesh.vertices) out << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return out.str();
}

std::string asciiStl(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(9);
  out << "solid test\n";
  for (const auto& t : mesh.triangles) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int k : t) {
      const auto& v = mesh.vertices[k];
      out << "      vertex " << float(v[0]) << " " << float(v[1]) << " " << float(v[2]) << "\n";
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
  return out.str();
}

std::string binaryStl(const TriangleMesh& mesh, const std::string& header) {
  std::string bytes(80, ' ');
  std::memcpy(bytes.data(), header.data(), std::min<size_t>(header.size(), 80));
  auto put32 = [&](uint32_t value) {
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
  };
  auto putFloat = [&](float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, 4);
    put32(bits);
  };
  put32(static_cast<uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) putFloat(0);  // normal: ignored
    for (int k : t) {
      for (double c : mesh.vertices[k]) putFloat(static_cast<float>(c));
    }
    bytes.push_back(0);
    bytes.push_back(0);
  }
  return bytes;
}

// ---- independent inside test -------------------------------------------------------------------

// Winding number of the mesh around p (summed solid angles, Van Oosterom & Strackee): +-1 inside
// an outward (inward) closed surface, 0 outside.
double windingNumber(const TriangleMesh& mesh, const Vec& p) {
  const double pi = std::acos(-1.0);
  double total = 0;
  for (const auto& t : mesh.triangles) {
    Vec a, b, c;
    for (int k = 0; k < 3; ++k) {
      a[k] = mesh.vertices[t[0]][k] - p[k];
      b[k] = mesh.vertices[t[1]][k] - p[k];
      c[k] = mesh.vertices[t[2]][k] - p[k];
    }
    auto dot = [](const Vec& u, const Vec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    auto norm = [&](const Vec& u) { return std::sqrt(dot(u, u)); };
    const Vec bc{b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
    const double la = norm(a), lb = norm(b), lc = norm(c);
    total += 2 * std::atan2(dot(a, bc), la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la);
  }
  return total / (4 * pi);
}

// Classifies every voxel centre of a grid of the given size over the mesh's bounding box
// (voxel size = longest extent / resolution) with the winding number.
std::vector<int> bruteForceLabels(const TriangleMesh& mesh, int resolution, int nx, int ny, int nz) {
  Vec lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const auto& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  }
  const double h = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / resolution;
  std::vector<int> labels;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        const double w = windingNumber(mesh, {lo[0] + (x + 0.5) * h, lo[1] + (y + 0.5) * h, lo[2] + (z + 0.5) * h});
        EXPECT_LT(std::abs(w - std::round(w)), 1e-6)
            << "centre too close to the surface: " << x << " " << y << " " << z;
        labels.push_back(std::lround(std::abs(w)) % 2);
      }
    }
  }
  return labels;
}

int64_t filledCount(const VoxelGrid& grid) {
  int64_t n = 0;
  for (int v : grid.labels()) n += v != 0;
  return n;
}

// FNV-1a over the size and the labels.
uint64_t fingerprint(const VoxelGrid& grid) {
  uint64_t hash = 1469598103934665603ull;
  auto mix = [&](int64_t value) {
    hash ^= static_cast<uint64_t>(value);
    hash *= 1099511628211ull;
  };
  mix(grid.nx());
  mix(grid.ny());
  mix(grid.nz());
  for (int v : grid.labels()) mix(v);
  return hash;
}

VoxelGrid voxelize(const TriangleMesh& mesh, int resolution, const std::string& source = "test.obj") {
  VoxelizeOptions options;
  options.resolution = resolution;
  return voxelizeSolid(mesh, options, source);
}

// The message of the desia::Error thrown by `action` (fails the test when nothing is thrown).
template <typename Action>
std::string errorOf(Action&& action, ErrorCode expectedCode = ErrorCode::BadInput) {
  try {
    action();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), expectedCode) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

// ---- voxelization ------------------------------------------------------------------------------

TEST(Voxelize, UnitCubeAtResolution4FillsEveryVoxel) {
  const VoxelGrid grid = voxelize(parseObj(objText(boxMesh({0, 0, 0}, {1, 1, 1})), "cube.obj"), 4);
  EXPECT_EQ(grid.nx(), 4);
  EXPECT_EQ(grid.ny(), 4);
  EXPECT_EQ(grid.nz(), 4);
  EXPECT_EQ(grid.labels(), std::vector<int>(64, 1));
}

TEST(Voxelize, BoxTwoByOneByOneAtResolution8Is8x4x4) {
  const VoxelGrid grid = voxelize(boxMesh({-3, 0.5, 10}, {1, 2.5, 12}), 8);
  EXPECT_EQ(grid.nx(), 8);
  EXPECT_EQ(grid.ny(), 4);
  EXPECT_EQ(grid.nz(), 4);
  EXPECT_EQ(grid.labels(), std::vector<int>(128, 1));
  // The longest side may be any axis; y up stays y up.
  const VoxelGrid tall = voxelize(boxMesh({0, 0, 0}, {1, 2, 1}), 8);
  EXPECT_EQ(tall.nx(), 4);
  EXPECT_EQ(tall.ny(), 8);
  EXPECT_EQ(tall.nz(), 4);
}

TEST(Voxelize, SidesRoundUpAndKeepAtLeastOneVoxel) {
  // 3 x 1 x 0.5 at resolution 4: voxel 0.75; y: ceil(1.33) = 2; z: ceil(0.67) = 1. The layer y = 1
  // has centres at 1.125 > 1: empty, so the shape is 4 x 1 x 1 voxels inside a 4 x 2 x 1 grid.
  const VoxelGrid grid = voxelize(boxMesh({0, 0, 0}, {3, 1, 0.5}), 4);
  EXPECT_EQ(grid.nx(), 4);
  EXPECT_EQ(grid.ny(), 2);
  EXPECT_EQ(grid.nz(), 1);
  EXPECT_EQ(grid.labels(), (std::vector<int>{1, 1, 1, 1, 0, 0, 0, 0}));
  // 0.3 x 0.1 x 0.1 at resolution 3: 0.1 / 0.3 * 3 must not round up to 2 by floating-point noise.
  const VoxelGrid thin = voxelize(boxMesh({0, 0, 0}, {0.3, 0.1, 0.1}), 3);
  EXPECT_EQ(thin.nx(), 3);
  EXPECT_EQ(thin.ny(), 1);
  EXPECT_EQ(thin.nz(), 1);
}

TEST(Voxelize, OctahedronMatchesHandCountAndBruteForce) {
  const TriangleMesh octahedron = octahedronMesh();
  checkClosedMesh(octahedron, "octahedron");
  // Resolution 8: centres at odd multiples of 1/8, inside when |a| + |b| + |c| <= 7 (a, b, c odd
  // eighths): 8 octants x 10 = 80, and no centre on the surface.
  const VoxelGrid grid = voxelize(octahedron, 8);
  EXPECT_EQ(grid.nx(), 8);
  EXPECT_EQ(filledCount(grid), 80);
  EXPECT_EQ(grid.labels(), bruteForceLabels(octahedron, 8, 8, 8, 8));
  for (int z = 0; z < 8; ++z) {
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        EXPECT_EQ(grid.label(x, y, z), grid.label(7 - x, y, z));
        EXPECT_EQ(grid.label(x, y, z), grid.label(x, 7 - y, z));
        EXPECT_EQ(grid.label(x, y, z), grid.label(x, y, 7 - z));
        EXPECT_EQ(grid.label(x, y, z), grid.label(y, z, x));
      }
    }
  }
}

TEST(Voxelize, RaysThroughVerticesAndEdgesOfTheOctahedron) {
  const TriangleMesh octahedron = octahedronMesh();
  // Resolution 3: centres at -2/3, 0, 2/3. The row y = z = 0 runs through the vertices (-1,0,0)
  // and (1,0,0), where four triangles meet; rows y = 0 or z = 0 run along projected edges. The
  // result is the 3D cross: the middle voxel and its six neighbours.
  const VoxelGrid cross = voxelize(octahedron, 3);
  EXPECT_EQ(filledCount(cross), 7);
  EXPECT_EQ(cross.labels(), bruteForceLabels(octahedron, 3, 3, 3, 3));
  EXPECT_EQ(cross.label(1, 1, 1), 1);
  EXPECT_EQ(cross.label(0, 1, 1), 1);
  EXPECT_EQ(cross.label(2, 1, 1), 1);
  EXPECT_EQ(cross.label(1, 0, 1), 1);
  EXPECT_EQ(cross.label(1, 1, 2), 1);
  // Resolution 4: centres at +-1/4, +-3/4. Rows such as (y, z) = (1/4, 3/4) graze the silhouette
  // edge from (0,1,0) to (0,0,1) at x = 0; they must count 0 or 2 crossings, never 1. Only the
  // middle 2 x 2 x 2 voxels are inside.
  const VoxelGrid middle = voxelize(octahedron, 4);
  EXPECT_EQ(filledCount(middle), 8);
  EXPECT_EQ(middle.labels(), bruteForceLabels(octahedron, 4, 4, 4, 4));
  for (int z = 1; z <= 2; ++z) {
    for (int y = 1; y <= 2; ++y) {
      for (int x = 1; x <= 2; ++x) EXPECT_EQ(middle.label(x, y, z), 1);
    }
  }
}

TEST(Voxelize, LumpyBallMatchesTheWindingNumberEverywhere) {
  const TriangleMesh sphere = lumpyBallMesh(9);
  for (int resolution : {5, 12, 23}) {
    const VoxelGrid grid = voxelize(sphere, resolution);
    EXPECT_EQ(grid.labels(), bruteForceLabels(sphere, resolution, grid.nx(), grid.ny(), grid.nz())) << resolution;
  }
}

TEST(Voxelize, RowsAlongEdgesAndCentresOnFacesOfACubeStaircase) {
  // Cells x + y + z <= 3 in [0,4)^3 (20 unit cubes). At resolution 6 the voxel size is 2/3 and
  // the centres (2i+1)/3 include 1 and 3: rows run along the mesh's edges, through its vertices
  // (convex and concave) and within its faces, and some centres lie on faces. The tie rule makes
  // the solid half-open: a centre c is inside exactly when its cell floor(c) is in the set.
  std::vector<std::array<int, 3>> cells;
  for (int z = 0; z < 4; ++z) {
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 4; ++x) {
        if (x + y + z <= 3) cells.push_back({x, y, z});
      }
    }
  }
  const TriangleMesh staircase = cubeSetMesh(cells);
  checkClosedMesh(staircase, "staircase");
  for (int resolution : {2, 4, 6, 8, 12}) {
    const VoxelGrid grid = voxelize(staircase, resolution);
    ASSERT_EQ(grid.nx(), resolution);
    std::vector<int> expected;
    for (int z = 0; z < resolution; ++z) {
      for (int y = 0; y < resolution; ++y) {
        for (int x = 0; x < resolution; ++x) {
          // Centre (2i+1) * 4 / (2 * resolution), exactly: floor((2i+1) * 2 / resolution).
          const int cx = (2 * x + 1) * 2 / resolution, cy = (2 * y + 1) * 2 / resolution,
                    cz = (2 * z + 1) * 2 / resolution;
          expected.push_back(cx + cy + cz <= 3 ? 1 : 0);
        }
      }
    }
    EXPECT_EQ(grid.labels(), expected) << "resolution " << resolution;
  }
  EXPECT_EQ(filledCount(voxelize(staircase, 6)), 48);  // per axis the cells are 0 1 1 2 3 3
  EXPECT_EQ(filledCount(voxelize(staircase, 2)), 1);
}

TEST(Voxelize, HollowBoxLeavesTheCavityEmpty) {
  TriangleMesh hollow = boxMesh({0, 0, 0}, {4, 4, 4});
  append(hollow, boxMesh({1, 1, 1}, {3, 3, 3}), /*reversed=*/true);
  const VoxelGrid grid = voxelize(hollow, 4);
  EXPECT_EQ(filledCount(grid), 56);
  for (int z = 0; z < 4; ++z) {
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 4; ++x) {
        const bool cavity = x >= 1 && x <= 2 && y >= 1 && y <= 2 && z >= 1 && z <= 2;
        EXPECT_EQ(grid.label(x, y, z), cavity ? 0 : 1) << x << " " << y << " " << z;
      }
    }
  }
  // Parity does not depend on the inner shell's orientation.
  TriangleMesh sameOrientation = boxMesh({0, 0, 0}, {4, 4, 4});
  append(sameOrientation, boxMesh({1, 1, 1}, {3, 3, 3}));
  EXPECT_EQ(voxelize(sameOrientation, 4).labels(), grid.labels());
  // A third, solid box inside the cavity: shells nest by parity (the cavity's middle voxel is
  // filled again at resolution 8, voxel 0.5: the inner box covers centres 1.75 .. 2.25).
  append(hollow, boxMesh({1.6, 1.6, 1.6}, {2.4, 2.4, 2.4}));
  const std::string message = errorOf([&] { voxelize(hollow, 8); });
  EXPECT_NE(message.find("it has 2 separate pieces (one contains voxel (0,0,0), another voxel (3,3,3))"),
            std::string::npos)
      << message;
}

TEST(Voxelize, SameMeshGivesTheSameGridBitForBit) {
  const TriangleMesh sphere = lumpyBallMesh(9);
  const VoxelGrid first = voxelize(sphere, 23);
  const VoxelGrid second = voxelize(sphere, 23);
  EXPECT_EQ(first.labels(), second.labels());
  // The same constants natively and in WebAssembly (this suite runs in both).
  EXPECT_EQ(first.nx(), 18);
  EXPECT_EQ(first.ny(), 23);
  EXPECT_EQ(first.nz(), 14);
  EXPECT_EQ(filledCount(first), 2856);
  EXPECT_EQ(fingerprint(first), 9588907132879275004ull);
}

TEST(Voxelize, VertexOrderAndTriangleOrderDoNotMatter) {
  const TriangleMesh sphere = lumpyBallMesh(6);
  TriangleMesh shuffled = sphere;
  std::reverse(shuffled.triangles.begin(), shuffled.triangles.end());
  for (auto& t : shuffled.triangles) std::swap(t[0], t[2]);  // also flips every orientation
  EXPECT_EQ(voxelize(shuffled, 16).labels(), voxelize(sphere, 16).labels());
}

// ---- limits and shape errors -------------------------------------------------------------------

TEST(VoxelizeErrors, ResolutionAndGridLimitsAreCheckedBeforeAllocating) {
  const TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(errorOf([&] { voxelize(cube, 0, "cube.obj"); }),
            "cube.obj: resolution 0 is out of range (1 to 1024 voxels along the longest side)");
  EXPECT_EQ(errorOf([&] { voxelize(cube, 1025, "cube.obj"); }, ErrorCode::TooLarge),
            "cube.obj: resolution 1025 is out of range (1 to 1024 voxels along the longest side)");
  EXPECT_EQ(errorOf([&] { voxelize(cube, 1024, "cube.obj"); }, ErrorCode::TooLarge),
            "cube.obj: resolution 1024 gives a grid of 1024 x 1024 x 1024 = 1073741824 voxels, more than the limit "
            "of 16777216; use a lower resolution");
  // A long thin box at 1024 fits: 1024 x 8 x 8.
  const VoxelGrid rod = voxelize(boxMesh({0, 0, 0}, {128, 1, 1}), 1024);
  EXPECT_EQ(rod.nx(), 1024);
  EXPECT_EQ(rod.ny(), 8);
  EXPECT_EQ(filledCount(rod), 1024 * 64);
}

TEST(VoxelizeErrors, EmptyResultAsksForAHigherResolution) {
  TriangleMesh hollow = boxMesh({0, 0, 0}, {4, 4, 4});
  append(hollow, boxMesh({0.5, 0.5, 0.5}, {3.5, 3.5, 3.5}), true);
  EXPECT_EQ(errorOf([&] { voxelize(hollow, 1, "shell.obj"); }),
            "shell.obj: no voxel centre lies inside the mesh at resolution 1 (grid 1 x 1 x 1): the resolution is too "
            "low for this shape; try a higher one");
}

TEST(VoxelizeErrors, PiecesThatFallApartAreNamed) {
  TriangleMesh two = boxMesh({0, 0, 0}, {1, 1, 1});
  append(two, boxMesh({2, 0, 0}, {3, 1, 1}));
  EXPECT_EQ(errorOf([&] { voxelize(two, 3, "two.obj"); }),
            "two.obj: at resolution 3 the voxelized shape is not face-connected: it has 2 separate pieces (one "
            "contains voxel (0,0,0), another voxel (2,0,0)); a single part needs one piece: try a higher resolution");
}

TEST(VoxelizeErrors, FlatAndNonFiniteMeshes) {
  TriangleMesh pillow;  // two triangles back to back: closed, but no volume
  pillow.vertices = {{0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}};
  pillow.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(errorOf([&] { voxelize(pillow, 8, "flat.obj"); }),
            "flat.obj: the mesh is flat: every vertex has z = 0.5, so it encloses no volume");
  TriangleMesh bad = boxMesh({0, 0, 0}, {1, 1, 1});
  bad.vertices[6][1] = std::nan("");
  EXPECT_EQ(errorOf([&] { voxelize(bad, 8, "nan.obj"); }),
            "nan.obj: vertex 7 has a coordinate that is not finite (nan)");
  bad.vertices[6][1] = 1e308;
  bad.vertices[0][1] = -1e308;
  EXPECT_EQ(errorOf([&] { voxelize(bad, 8, "huge.obj"); }),
            "huge.obj: the coordinates span too large a range along y to be measured in double precision");
}

// ---- closed-mesh check -------------------------------------------------------------------------

TEST(ClosedMesh, MissingTriangleNamesTheOpenEdge) {
  TriangleMesh cube = parseObj(objText(boxMesh({0, 0, 0}, {1, 1, 1})), "cube.obj");
  cube.triangles.erase(cube.triangles.begin());  // (1, 5, 7) in OBJ numbering
  EXPECT_EQ(errorOf([&] { checkClosedMesh(cube, "cube.obj"); }),
            "cube.obj: the mesh is not closed: edge between vertices 1 and 5 belongs to 1 triangle (a closed solid "
            "needs 2)");
  EXPECT_EQ(errorOf([&] { voxelize(cube, 4, "cube.obj"); }),
            "cube.obj: the mesh is not closed: edge between vertices 1 and 5 belongs to 1 triangle (a closed solid "
            "needs 2)");
}

TEST(ClosedMesh, EdgesSharedByThreeTrianglesAreOpen) {
  TriangleMesh fin = boxMesh({0, 0, 0}, {1, 1, 1});
  // A fin hanging off edge 1-2 of the cube: that edge now has three triangles.
  fin.vertices.push_back({0.5, -1, 0});
  fin.triangles.push_back({0, 1, 8});
  EXPECT_EQ(errorOf([&] { checkClosedMesh(fin, "fin.obj"); }),
            "fin.obj: the mesh is not closed: edge between vertices 1 and 2 belongs to 3 triangles (a closed solid "
            "needs 2)");
}

TEST(ClosedMesh, TwoBoxesTouchingAlongAnEdgeAreClosed) {
  // Two unit boxes sharing only the edge x = 1, y = 1 after welding: four triangles use it.
  TriangleMesh pair = boxMesh({0, 0, 0}, {1, 1, 1});
  const TriangleMesh second = boxMesh({1, 1, 0}, {2, 2, 1});
  std::vector<int> index;
  for (const auto& v : second.vertices) {
    const auto found = std::find(pair.vertices.begin(), pair.vertices.end(), v);
    index.push_back(static_cast<int>(found - pair.vertices.begin()));
    if (found == pair.vertices.end()) pair.vertices.push_back(v);
  }
  for (const auto& t : second.triangles) pair.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  ASSERT_EQ(pair.vertices.size(), 14u) << "the boxes share the two end points of one edge";
  EXPECT_NO_THROW(checkClosedMesh(pair, "pair.obj"));
}

TEST(ClosedMesh, EmptyAndMalformedMeshes) {
  EXPECT_EQ(errorOf([] { checkClosedMesh(TriangleMesh{}, "e.obj"); }), "e.obj: the mesh has no vertices");
  TriangleMesh points;
  points.vertices = {{0, 0, 0}};
  EXPECT_EQ(errorOf([&] { checkClosedMesh(points, "p.obj"); }), "p.obj: the mesh has no triangles (no faces)");
  TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
  cube.triangles[3] = {1, 8, 5};
  EXPECT_EQ(errorOf([&] { checkClosedMesh(cube, "c.obj"); }),
            "c.obj: triangle 4 refers to vertex 9, but the mesh has 8 vertices");
  cube.triangles[3] = {1, 5, 5};
  EXPECT_EQ(errorOf([&] { checkClosedMesh(cube, "c.obj"); }), "c.obj: triangle 4 uses vertex 6 twice");
}

// ---- OBJ -----------------------------------------------------------------------------------------

TEST(ObjFormat, QuadsSlashesNegativeIndicesAndIgnoredRecords) {
  // The unit cube with quads, every face reference form, relative indices and records that do
  // not shape the solid.
  const std::string text =
      "# a cube\r\n"
      "mtllib cube.mtl\r\n"
      "o Cube\r\n"
      "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0 1.0\r\n"
      "v 0 0 1 0.5 0.5 0.5\r\nv 1 0 1\r\nv 0 1 1\r\nv 1.0e0 +1 1.  # trailing comment\r\n"
      "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\n"
      "g side\r\ns off\r\nusemtl wood\r\n"
      "f 1/1 5/2 7/1 3/2\r\n"
      "f 2/1/1 4/2/1 8/1/1 6/2/1\r\n"
      "f 1//1 2//1 6//1 5//1\r\n"
      "f -6 -2 -1 -5\r\n"  // 3 7 8 4
      "f 1 3 4 2\r\n"
      "l 1 2\r\n"
      "f 5 6 8 7";  // no final newline
  const TriangleMesh mesh = parseObj(text, "quads.obj");
  EXPECT_EQ(mesh.vertices.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.triangles[6], (std::array<int, 3>{2, 6, 7}));  // from "f -6 -2 -1 -5"
  EXPECT_EQ(mesh.vertices[7], (Vec{1, 1, 1}));
  EXPECT_EQ(voxelize(mesh, 4).labels(), std::vector<int>(64, 1));
}

TEST(ObjFormat, PolygonsAreFanTriangulatedAndDegenerateFacesDropped) {
  const TriangleMesh mesh = parseObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 2 0\nf 1 2 3 4 5\nf 1 1 2\n", "fan.obj");
  EXPECT_EQ(mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST(ObjFormat, FacesMayNameVerticesDefinedLater) {
  const TriangleMesh mesh = parseObj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "late.obj");
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

struct BadObj {
  const char* name;
  std::string text;
  std::string expected;
};
void PrintTo(const BadObj& value, std::ostream* out) { *out << value.name; }

class ObjErrors : public ::testing::TestWithParam<BadObj> {};

TEST_P(ObjErrors, NameFileLineAndValue) {
  EXPECT_EQ(errorOf([&] { voxelize(parseMesh(GetParam().text, "bunny.obj"), 8, "bunny.obj"); }), GetParam().expected);
}

const std::string kCube = objText(boxMesh({0, 0, 0}, {1, 1, 1}));  // 8 v lines, then 12 f lines

INSTANTIATE_TEST_SUITE_P(
    Voxelize, ObjErrors,
    ::testing::Values(
        BadObj{"index_out_of_range", kCube + "f 1 2 900\n",
               "bunny.obj:21: face index 900 out of range (mesh has 8 vertices)"},
        BadObj{"missing_vertex", "v 0 0 0\nv 1 0 0\nf 1 2 3\n",
               "bunny.obj:3: face index 3 out of range (mesh has 2 vertices)"},
        BadObj{"index_zero", kCube + "\nf 0 1 2\n",
               "bunny.obj:22: face index 0 is invalid (OBJ indices start at 1; negative ones count back from the "
               "last vertex)"},
        BadObj{"relative_before_first", "v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n",
               "bunny.obj:2: face index -2 refers to no vertex (only 1 vertices are defined before this line)"},
        BadObj{"index_not_integer", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/3\n",
               "bunny.obj:4: face index 'x' is not an integer"},
        BadObj{"index_float", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.5\n",
               "bunny.obj:4: face index '3.5' is not an integer"},
        BadObj{"face_too_short", "v 0 0 0\nv 1 0 0\nf 1 2\n",
               "bunny.obj:3: face has 2 vertices, a face needs at least 3"},
        BadObj{"coordinate_not_number", "v 0 0 0\nv 1 zero 0\n",
               "bunny.obj:2: vertex coordinate 'zero' is not a number"},
        BadObj{"coordinate_nan", "v nan 0 0\n", "bunny.obj:1: vertex coordinate 'nan' is not a number"},
        BadObj{"coordinate_overflow", "v 1e999 0 0\n", "bunny.obj:1: vertex coordinate '1e999' is not finite"},
        BadObj{"coordinate_missing", "v 0 0 0\nv 1 0\n",
               "bunny.obj:2: vertex has 2 coordinates, expected 'v x y z' (optionally followed by w)"},
        BadObj{"binary", std::string("v 0 0 0\nv 1\0 0 0\n", 16),
               "bunny.obj:2: not a text file: unexpected byte 0x00 at offset 11"},
        BadObj{"no_faces", "v 0 0 0\nvn 0 0 1\n", "bunny.obj: the mesh has no triangles (no faces)"},
        BadObj{"nothing", "# empty\n", "bunny.obj: the mesh has no vertices"},
        BadObj{"open", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
               "bunny.obj: the mesh is not closed: edge between vertices 1 and 2 belongs to 1 triangle (a closed "
               "solid needs 2)"}),
    [](const ::testing::TestParamInfo<BadObj>& info) { return info.param.name; });

// ---- STL -----------------------------------------------------------------------------------------

TEST(StlFormat, AsciiAndBinaryGiveTheSameGridAsObj) {
  const TriangleMesh octahedron = octahedronMesh();
  const VoxelGrid fromObj = voxelize(parseMesh(objText(octahedron), "o.obj"), 8);
  const TriangleMesh ascii = parseMesh(asciiStl(octahedron), "o.stl");
  const TriangleMesh binary = parseMesh(binaryStl(octahedron, "binary STL"), "o.stl");
  // Corners are merged back into 6 shared vertices.
  EXPECT_EQ(ascii.vertices.size(), 6u);
  EXPECT_EQ(binary.vertices.size(), 6u);
  EXPECT_EQ(ascii.triangles, binary.triangles);
  EXPECT_EQ(voxelize(ascii, 8).labels(), fromObj.labels());
  EXPECT_EQ(voxelize(binary, 8).labels(), fromObj.labels());
  EXPECT_EQ(filledCount(fromObj), 80);
}

TEST(StlFormat, BinaryIsRecognisedBySizeEvenWhenTheHeaderSaysSolid) {
  const TriangleMesh cube = boxMesh({0, 0, 0}, {2, 1, 1});
  const std::string bytes = binaryStl(cube, "solid cube exported by a tool that starts binary headers with solid");
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  for (const char* source : {"cube.stl", "cube", "<input>"}) {
    const TriangleMesh mesh = parseMesh(bytes, source);
    EXPECT_EQ(mesh.vertices.size(), 8u) << source;
    EXPECT_EQ(mesh.triangles.size(), 12u) << source;
  }
  EXPECT_EQ(voxelize(parseStl(bytes, "cube.stl"), 8).labels(), std::vector<int>(128, 1));
  // Upper-case keywords and a missing endsolid are accepted in ASCII.
  std::string ascii = asciiStl(cube);
  for (char& c : ascii) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  ascii.erase(ascii.find("ENDSOLID"));
  EXPECT_EQ(voxelize(parseMesh(ascii, "CUBE.STL"), 8).labels(), std::vector<int>(128, 1));
}

TEST(StlFormat, Errors) {
  const TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
  std::string cut = binaryStl(cube, "binary");
  cut.resize(cut.size() - 7);
  EXPECT_EQ(
      errorOf([&] { parseMesh(cut, "cut.stl"); }),
      "cut.stl: not a valid binary STL: its header announces 12 triangles, which take 684 bytes, but the file has "
      "677 bytes (and it does not start with 'solid' as ASCII STL does)");
  EXPECT_EQ(
      errorOf([&] { parseStl("hello", "tiny.stl"); }),
      "tiny.stl: not an STL file: it does not start with 'solid' (ASCII STL) and has 5 bytes, fewer than a binary "
      "STL's 84-byte header");
  EXPECT_EQ(
      errorOf([] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 oops\n", "a.stl"); }),
      "a.stl:5: vertex coordinate 'oops' is not a number");
  EXPECT_EQ(errorOf([] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\n", "a.stl"); }),
            "a.stl:5: the loop has 1 vertices, a facet needs at least 3");
  EXPECT_EQ(errorOf([] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "a.stl"); }),
            "a.stl:4: the file ends inside a facet (expected 'endloop' / 'endfacet')");
  EXPECT_EQ(errorOf([] { parseStl("solid x\n  facet normal 0 0 1\n  loop\n", "a.stl"); }),
            "a.stl:3: expected 'outer loop', found 'loop'");
  std::string nan = binaryStl(cube, "binary");
  const float nanValue = std::nanf("");
  std::memcpy(&nan[84 + 50 * 2 + 12 + 4], &nanValue, 4);
  EXPECT_EQ(errorOf([&] { parseMesh(nan, "nan.stl"); }),
            "nan.stl: binary STL triangle 3 has a coordinate that is not finite (nan)");
}

TEST(MeshNames, FileNameWithoutFoldersAndExtension) {
  EXPECT_EQ(meshShapeName("models/bunny.obj"), "bunny");
  EXPECT_EQ(meshShapeName("C:\\meshes\\cup.v2.stl"), "cup.v2");
  EXPECT_EQ(meshShapeName("shape"), "shape");
  EXPECT_EQ(meshShapeName("<input>"), "");
}

}  // namespace
}  // namespace desia
