// SPDX-License-Identifier: GPL-3.0-or-later
// Every exported part is one valid solid (issue 28, item 11): every edge in exactly two triangles,
// in opposite directions; no zero-area triangle; one connected piece; Euler characteristic
// 2 - 2 genus with a sane genus; the part's own volume. For unions of boxes (frame beams), plates
// with their milled joints (the golden corpus' designs with fixed seeds) and voxel parts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "analysis/vec3.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

struct SolidFacts {
  std::string manifold;  // "" or the first edge not in exactly two opposite triangles
  int zeroArea = 0;
  int components = 0;
  int64_t euler = 0;
  double volume = 0;
  int genus() const { return static_cast<int>((2 * components - euler) / 2); }
};

SolidFacts factsOf(const TriangleMesh& mesh) {
  SolidFacts facts;
  facts.manifold = testing::manifoldProblem(mesh);
  facts.volume = testing::enclosedVolume(mesh);
  std::set<int> used;
  std::set<std::pair<int, int>> edges;
  std::vector<int> parent(mesh.triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::map<std::pair<int, int>, int> firstTriangle;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3& a = mesh.vertices[tri[0]];
    const Vec3 n = cross(minus(mesh.vertices[tri[1]], a), minus(mesh.vertices[tri[2]], a));
    if (norm(n) / 2 <= 1e-9) ++facts.zeroArea;
    for (int k = 0; k < 3; ++k) {
      used.insert(tri[k]);
      const std::pair<int, int> edge{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])};
      edges.insert(edge);
      const auto [at, fresh] = firstTriangle.emplace(edge, static_cast<int>(t));
      if (!fresh) parent[find(static_cast<int>(t))] = find(at->second);
    }
  }
  std::set<int> roots;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) roots.insert(find(static_cast<int>(t)));
  facts.components = static_cast<int>(roots.size());
  facts.euler = static_cast<int64_t>(used.size()) - static_cast<int64_t>(edges.size()) +
                static_cast<int64_t>(mesh.triangles.size());
  return facts;
}

void expectSolid(const TriangleMesh& mesh, double volume, int maxGenus, const std::string& what) {
  const SolidFacts facts = factsOf(mesh);
  EXPECT_EQ(facts.manifold, "") << what;
  EXPECT_EQ(facts.zeroArea, 0) << what;
  EXPECT_EQ(facts.components, 1) << what;
  EXPECT_EQ(facts.euler % 2, 0) << what;
  EXPECT_GE(facts.genus(), 0) << what;
  EXPECT_LE(facts.genus(), maxGenus) << what;
  EXPECT_NEAR(facts.volume, volume, 1e-9 * std::max(1.0, volume)) << what;
}

TEST(SolidExport, UnionOfOverlappingBoxesIsOneSolidOfTheUnionsVolume) {
  // A 4 x 1 x 1 bar through a 2 x 2 x 2 cube, half of it outside: 8 + 2 (outside) = 10.
  const std::vector<AxisAlignedBox> boxes{{{0, 0, 0}, {2, 2, 2}}, {{-2, 0.5, 0.5}, {2, 1.5, 1.5}}};
  const TriangleMesh mesh = surfaceOfBoxUnion(boxes, 1e-6);
  expectSolid(mesh, 10, 0, "bar through cube");
  EXPECT_EQ(factsOf(mesh).euler, 2);
  // Boxes that touch face to face: one block, no inner wall.
  expectSolid(surfaceOfBoxUnion({{{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {3, 1, 1}}}, 1e-6), 3, 0, "touching");
  // A ring of four bars: genus 1.
  const std::vector<AxisAlignedBox> ring{
      {{0, 0, 0}, {3, 1, 1}}, {{0, 2, 0}, {3, 3, 1}}, {{0, 0, 0}, {1, 3, 1}}, {{2, 0, 0}, {3, 3, 1}}};
  const TriangleMesh ringMesh = surfaceOfBoxUnion(ring, 1e-6);
  expectSolid(ringMesh, 8, 1, "ring");
  EXPECT_EQ(factsOf(ringMesh).genus(), 1);
  // Coordinates equal up to rounding are one plane (no sliver cells).
  expectSolid(surfaceOfBoxUnion({{{0, 0, 0}, {1, 1, 1}}, {{1 + 1e-12, 0, 0}, {2, 1, 1 - 1e-13}}}, 1e-6), 2, 0,
              "rounded");
  EXPECT_THROW(surfaceOfBoxUnion({}, 1e-6), Error);
}

// Volume of the union of one box and disjoint voxels (each voxel's overlap with the box counted
// once): |B| + sum |v| - sum |B n v|.
double boxAndVoxelsVolume(const AxisAlignedBox& body, const std::vector<AxisAlignedBox>& voxels) {
  auto volume = [](const AxisAlignedBox& b) { return (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]); };
  double total = volume(body);
  for (const AxisAlignedBox& v : voxels) {
    double overlap = 1;
    for (int k = 0; k < 3; ++k) overlap *= std::max(0.0, std::min(body.hi[k], v.hi[k]) - std::max(body.lo[k], v.lo[k]));
    total += volume(v) - overlap;
  }
  return total;
}

AxisAlignedBox bounds(const OrientedBox& box) {
  AxisAlignedBox out;
  for (int k = 0; k < 3; ++k) {
    double reach = 0;
    for (int i = 0; i < 3; ++i) reach += std::abs(box.axes[i][k]) * box.halfExtents[i];
    out.lo[k] = box.centre[k] - reach;
    out.hi[k] = box.centre[k] + reach;
  }
  return out;
}

TEST(SolidExport, EveryStraightFrameBeamIsOneSolidOfBodyAndJointVoxels) {
  for (const std::string path : {"examples/frame/frame_cube_result.json", "examples/frame/frame_chair_result.json",
                                 "examples/frame/scaffold_92_result.json"}) {
    const FrameDocument frame = parseFrameText(testing::readFileText(testing::projectPath(path)), path);
    for (size_t beam = 0; beam < frame.layout.frame.beams.size(); ++beam) {
      const std::vector<OrientedBox> body = beamBodyBoxes(frame.layout, static_cast<int>(beam));
      ASSERT_EQ(body.size(), 1u) << path;
      std::vector<AxisAlignedBox> voxels;
      for (int joint : frame.layout.frame.beams[beam].joints) {
        for (int v = 0; v < kJointVoxelCount; ++v) {
          if (frame.labels[joint][v] == static_cast<int>(beam)) voxels.push_back(bounds(jointVoxelBox(frame.layout, joint, v)));
        }
      }
      const TriangleMesh mesh = beamPartMesh(frame.layout, frame.labels, static_cast<int>(beam));
      expectSolid(mesh, boxAndVoxelsVolume(bounds(body[0]), voxels), static_cast<int>(voxels.size()),
                  path + " beam " + std::to_string(frame.layout.frame.beams[beam].id));
    }
  }
}

// The golden corpus' plate results (designs with fixed seeds), those with milled joints.
std::vector<std::string> milledResults() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(testing::projectPath("tests/golden/cases/plate"))) {
    const std::string file = entry.path().string() + "/result.json";
    if (std::filesystem::exists(file) && entry.path().filename().string().find("milled") != std::string::npos)
      files.push_back(file);
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(SolidExport, EveryPlateWithMilledJointsIsOneSolid) {
  const std::vector<std::string> files = milledResults();
  ASSERT_GE(files.size(), 10u);
  int withAttached = 0;
  for (const std::string& file : files) {
    const AssemblyDocument document = parseAssemblyText(testing::readFileText(file), file);
    for (const Plate& plate : document.plates) {
      // The parts' volumes: the plate's prism and each attached solid's, each on its own (they
      // touch but never overlap).
      Plate body = plate;
      body.attached.clear();
      double volume = testing::enclosedVolume(plateMesh(body));
      int holes = static_cast<int>(plate.bottom.size()) - 1;
      for (const Plate& solid : plate.attached) {
        volume += testing::enclosedVolume(plateMesh(solid));
        holes += static_cast<int>(solid.bottom.size());
      }
      withAttached += plate.attached.empty() ? 0 : 1;
      const std::string what = file + " plate " + std::to_string(plate.id);
      expectSolid(plateSolidMesh(plate), volume, holes, what);
    }
  }
  EXPECT_GE(withAttached, 20);
}

// A long table's top holds a mortise per panel: a face with a thousand holes, all with the same
// few x coordinates in rows (ties for the bridges) and diamonds between them (slanted edges). The
// triangulation must still close the plate exactly: one solid, its genus the number of holes, the
// board's volume less the holes'.
TEST(SolidExport, APlateWithAThousandHolesIsOneSolid) {
  constexpr double kThickness = 20;
  constexpr int kColumns = 112, kRows = 5;
  const double length = kColumns * 30.0 + 30, width = kRows * 40.0 + 40;
  auto flat = [](double x, double y, double z) { return Vec3{x, y, z}; };
  Plate plate;
  plate.id = 1;
  std::vector<Loop> face{{flat(0, 0, 0), flat(length, 0, 0), flat(length, width, 0), flat(0, width, 0)}};
  double holesArea = 0;
  for (int i = 0; i < kColumns; ++i) {
    for (int j = 0; j < kRows; ++j) {
      const double x = 30 + 30.0 * i, y = 40 + 40.0 * j;
      // Holes run clockwise seen from +z, as a plate's holes in its files do.
      face.push_back({flat(x, y, 0), flat(x, y + 12, 0), flat(x + 10, y + 12, 0), flat(x + 10, y, 0)});
      holesArea += 120;
      if (j + 1 < kRows) {
        const double cx = x + 5, cy = y + 26;
        face.push_back({flat(cx - 4, cy, 0), flat(cx, cy + 4, 0), flat(cx + 4, cy, 0), flat(cx, cy - 4, 0)});
        holesArea += 32;
      }
    }
  }
  plate.bottom = face;
  for (Loop& loop : face) {
    for (Vec3& p : loop) p[2] = kThickness;
  }
  plate.top = face;
  const int holes = static_cast<int>(plate.bottom.size()) - 1;
  ASSERT_EQ(holes, 1008);
  const double volume = (length * width - holesArea) * kThickness;
  expectSolid(plateSolidMesh(plate), volume, holes, "a board with 1,008 holes (export)");
  const SolidFacts sweptMesh = factsOf(plateMesh(plate));
  EXPECT_EQ(sweptMesh.manifold, "");
  EXPECT_EQ(sweptMesh.genus(), holes);
  EXPECT_NEAR(sweptMesh.volume, volume, 1e-9 * volume);
}

// A unit cube whose top face holds a triangle of no area (the midpoint m of its diagonal between
// the diagonal's ends), as ear clipping leaves where holes line up: flipped away, the same solid.
TEST(SolidExport, ATriangleOfNoAreaIsFlippedAwayLeavingTheSameSolid) {
  TriangleMesh cube;
  cube.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1}};
  const int m = 8;
  cube.triangles = {{0, 2, 1}, {0, 3, 2},                      // bottom, seen from below
                    {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},  // sides
                    {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7},
                    {4, 5, 6}, {6, m, 4}, {4, m, 7}, {m, 6, 7}};  // top: {6, m, 4} has no area
  ASSERT_EQ(testing::manifoldProblem(cube), "");
  ASSERT_EQ(factsOf(cube).zeroArea, 1);
  EXPECT_EQ(flipZeroAreaTriangles(cube), 0);
  expectSolid(cube, 1.0, 0, "the cube after the flip");
  EXPECT_EQ(cube.triangles.size(), 14u);
}

TEST(SolidExport, EveryVoxelPartIsOneSolidOfItsVoxels) {
  for (const std::string name : {"result_puz/Cube_4x4x4_K9.puz", "result_puz/cube_5x5x5_K16.puz",
                                 "result_puz/cartoon_dog.puz", "result_puz/bunny_15x14x11_K80.puz"}) {
    const AssemblyDocument document = testing::loadReference(name);
    const std::vector<std::vector<int64_t>> voxels = voxelsByPart(document.voxels);
    for (size_t part = 1; part < voxels.size(); ++part) {
      const TriangleMesh mesh = surfaceOfVoxels(document.voxels, static_cast<int>(part), voxels[part], 2.0);
      expectSolid(mesh, 8.0 * static_cast<double>(voxels[part].size()), static_cast<int>(voxels[part].size()),
                  name + " part " + std::to_string(part));
    }
  }
}

}  // namespace
}  // namespace desia
