// SPDX-License-Identifier: GPL-3.0-or-later
// File exports (core/include/desia/export.h): part surfaces are closed, consistently oriented
// 2-manifolds with the right volume; STL and OBJ parse back; the .xmpuzzle is decoded here with
// our own gunzip (stored blocks, CRC-32 computed bit by bit, independent of the writer's table)
// and its pieces reproduce the labels of the reference puzzles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

using desia::testing::bitwiseCrc32;
using desia::testing::enclosedVolume;
using desia::testing::gridFromLayers;
using desia::testing::loadReference;
using desia::testing::manifoldProblem;
using desia::testing::verifyRemoval;
using Vec = std::array<double, 3>;

const std::vector<std::string> kReferencePuzzles = {
    "result_puz/Cube_4x4x4_K9.puz",           "result_puz/Cube_4x4x4_K9_01.puz", "result_puz/Cube_Hollow_4x4x4_K7",
    "result_puz/cube_5x5x5_K16.puz",          "result_puz/cartoon_dog.puz",      "result_puz/bunny_15x14x11_K80.puz",
    "input_puz/Cube_hollow_4x4x4_origin.puz", "input_puz/dog_origin.puz",
};

std::string text(const std::vector<uint8_t>& bytes) { return std::string(bytes.begin(), bytes.end()); }

// ---- mesh properties -----------------------------------------------------------------------------

double surfaceArea(const TriangleMesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec& a = mesh.vertices[t[0]];
    const Vec& b = mesh.vertices[t[1]];
    const Vec& c = mesh.vertices[t[2]];
    const Vec e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    area += std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
  }
  return area;
}

// Voxel faces of part `id` whose neighbour is not in the part, counted directly from the labels.
int64_t countBoundaryFaces(const VoxelGrid& grid, int id) {
  int64_t faces = 0;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        if (grid.label(x, y, z) != id) continue;
        const int n[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z}, {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
        for (const auto& p : n) faces += !(grid.inside(p[0], p[1], p[2]) && grid.label(p[0], p[1], p[2]) == id);
      }
    }
  }
  return faces;
}

void expectClosedSurfaceOfPart(const VoxelGrid& grid, int id, double voxelSize, const std::string& what) {
  const TriangleMesh mesh = partSurfaceMesh(grid, id, voxelSize);
  const double cube = voxelSize * voxelSize * voxelSize;
  EXPECT_EQ(manifoldProblem(mesh), "") << what << " part " << id;
  EXPECT_NEAR(enclosedVolume(mesh), static_cast<double>(grid.labelCounts()[id]) * cube, 1e-9 * cube * grid.voxelCount())
      << what << " part " << id;
  EXPECT_NEAR(surfaceArea(mesh), static_cast<double>(countBoundaryFaces(grid, id)) * voxelSize * voxelSize,
              1e-9 * voxelSize * voxelSize * grid.voxelCount())
      << what << " part " << id;
  for (const auto& v : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) {
      const int side = axis == 0 ? grid.nx() : axis == 1 ? grid.ny() : grid.nz();
      ASSERT_GE(v[axis], 0.0);
      ASSERT_LE(v[axis], side * voxelSize * (1 + 1e-12));
    }
  }
}

// ---- our own gunzip ------------------------------------------------------------------------------

uint32_t littleEndian(const std::vector<uint8_t>& bytes, size_t at, int count) {
  uint32_t value = 0;
  for (int k = 0; k < count; ++k) value |= static_cast<uint32_t>(bytes.at(at + k)) << (8 * k);
  return value;
}

struct Gunzipped {
  std::string data;
  int blocks = 0;
};

// Decodes a gzip member made of stored DEFLATE blocks; fails the test on anything else.
Gunzipped gunzipStored(const std::vector<uint8_t>& bytes) {
  Gunzipped out;
  EXPECT_GE(bytes.size(), 18u);
  EXPECT_EQ(bytes[0], 0x1f);
  EXPECT_EQ(bytes[1], 0x8b);
  EXPECT_EQ(bytes[2], 8) << "compression method deflate";
  EXPECT_EQ(bytes[3], 0) << "no optional header fields";
  EXPECT_EQ(littleEndian(bytes, 4, 4), 0u) << "no time stamp";
  size_t at = 10;
  for (bool last = false; !last;) {
    const uint8_t header = bytes.at(at++);
    last = (header & 1) != 0;
    EXPECT_EQ((header >> 1) & 3, 0) << "stored block expected";
    const uint32_t length = littleEndian(bytes, at, 2), check = littleEndian(bytes, at + 2, 2);
    EXPECT_EQ(length ^ 0xFFFFu, check) << "NLEN is the complement of LEN";
    at += 4;
    out.data.append(reinterpret_cast<const char*>(bytes.data() + at), length);
    at += length;
    ++out.blocks;
  }
  EXPECT_EQ(littleEndian(bytes, at, 4), bitwiseCrc32(out.data)) << "CRC-32";
  EXPECT_EQ(littleEndian(bytes, at + 4, 4), static_cast<uint32_t>(out.data.size())) << "ISIZE";
  EXPECT_EQ(at + 8, bytes.size()) << "nothing after the trailer";
  return out;
}

// ---- a little XML reading ------------------------------------------------------------------------

struct XmlShape {
  int x = 0, y = 0, z = 0;
  std::string name, voxels;
};

std::vector<XmlShape> shapesOf(const std::string& xml) {
  std::vector<XmlShape> shapes;
  const std::regex voxel(R"re(<voxel x="(\d+)" y="(\d+)" z="(\d+)" name="([^"]*)" type="0">([^<]*)</voxel>)re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), voxel); it != std::sregex_iterator(); ++it) {
    shapes.push_back({std::stoi((*it)[1]), std::stoi((*it)[2]), std::stoi((*it)[3]), (*it)[4], (*it)[5]});
  }
  return shapes;
}

// "part k: x y z" lines of the comment: where each cropped piece sits in the assembly grid.
std::map<int, std::array<int, 3>> offsetsOf(const std::string& xml) {
  std::map<int, std::array<int, 3>> offsets;
  const std::regex line(R"re(\npart (\d+): (\d+) (\d+) (\d+)(?=\n))re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), line); it != std::sregex_iterator(); ++it) {
    offsets[std::stoi((*it)[1])] = {std::stoi((*it)[2]), std::stoi((*it)[3]), std::stoi((*it)[4])};
  }
  return offsets;
}

// ---- tests ---------------------------------------------------------------------------------------

TEST(ExportFormat, NamesRoundTripAndBadNamesAreNamed) {
  for (const char* name : {"stl", "stl-ascii", "obj", "xmpuzzle", "stl-zip", "build-plate-stl"}) {
    EXPECT_STREQ(exportFormatName(parseExportFormat(name)), name);
  }
  EXPECT_EQ(parseExportFormat("stl"), ExportFormat::StlBinary);
  EXPECT_EQ(parseExportFormat("stl-ascii"), ExportFormat::StlAscii);
  try {
    parseExportFormat("STEP");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_STREQ(e.what(), "unknown export format 'STEP' (expected stl, stl-ascii, obj, xmpuzzle, stl-zip or "
                 "build-plate-stl)");
  }
}

TEST(ExportSurface, OneVoxelIsACubeOfTwelveOutwardTriangles) {
  const VoxelGrid grid = gridFromLayers({{"0 0", "0 1"}});  // voxel (1, 1, 0)
  const TriangleMesh mesh = partSurfaceMesh(grid, 1, 2.0);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(manifoldProblem(mesh), "");
  EXPECT_DOUBLE_EQ(enclosedVolume(mesh), 8.0);  // positive: outward
  for (const auto& v : mesh.vertices) {
    EXPECT_TRUE(v[0] == 2 || v[0] == 4);
    EXPECT_TRUE(v[1] == 2 || v[1] == 4);
    EXPECT_TRUE(v[2] == 0 || v[2] == 2);
  }
}

TEST(ExportSurface, FacesBetweenTwoPartsBelongToBothAndNoneInside) {
  // A 3x1x1 bar: part 1 = two voxels, part 2 = one. Part 1 has 10 faces (the one between its own
  // voxels is not a face), part 2 has 6, including the one it shares with part 1.
  const VoxelGrid grid = gridFromLayers({{"1 1 2"}});
  EXPECT_EQ(partSurfaceMesh(grid, 1).triangles.size(), 20u);
  EXPECT_EQ(partSurfaceMesh(grid, 2).triangles.size(), 12u);
  expectClosedSurfaceOfPart(grid, 1, 1.0, "bar");
  expectClosedSurfaceOfPart(grid, 2, 1.0, "bar");
}

TEST(ExportSurface, EveryPartOfEveryReferencePuzzleIsClosedWithItsVolume) {
  for (const std::string& file : kReferencePuzzles) {
    const AssemblyDocument document = loadReference(file);
    for (int id = 1; id <= document.voxels.maxLabel(); ++id) {
      expectClosedSurfaceOfPart(document.voxels, id, 1.0, file);
      expectClosedSurfaceOfPart(document.voxels, id, 0.1, file);
    }
  }
}

TEST(ExportSurface, VoxelsTouchingAlongAnEdgeStayManifold) {
  // Part 1 is a ring of 8 voxels around the vertical edge x = y = 1: in the middle layer its
  // voxels (0,0,1) and (1,1,1) touch only along that edge, and they are joined both below and
  // above, so four faces of the part meet at the edge and the corners at both ends are shared.
  const VoxelGrid ring = gridFromLayers({
      {"1 1", "0 1"},
      {"1 0", "0 1"},
      {"1 0", "1 1"},
  });
  const TriangleMesh mesh = partSurfaceMesh(ring, 1);
  EXPECT_EQ(manifoldProblem(mesh), "");
  EXPECT_DOUBLE_EQ(enclosedVolume(mesh), 8.0);
  EXPECT_DOUBLE_EQ(surfaceArea(mesh), static_cast<double>(countBoundaryFaces(ring, 1)));
  // Two copies of the edge's midpoint (one per voxel), both at (1, 1, 1.5).
  EXPECT_EQ(std::count(mesh.vertices.begin(), mesh.vertices.end(), Vec{1, 1, 1.5}), 2);
  // The same with two other parts filling the gaps, and a larger voxel.
  const VoxelGrid filled = gridFromLayers({
      {"1 1", "2 1"},
      {"1 3", "2 1"},
      {"1 3", "1 1"},
  });
  expectClosedSurfaceOfPart(filled, 1, 1.0, "ring");
  expectClosedSurfaceOfPart(filled, 2, 3.0, "ring");
  expectClosedSurfaceOfPart(filled, 3, 3.0, "ring");
}

TEST(ExportSurface, ScrambledGridsGiveClosedSurfacesForEveryLabel) {
  // Labels 0..3 drawn by a fixed linear congruential sequence: pinches along every axis, voxels
  // meeting only at corners, parts in several pieces (the surface builder does not need
  // connected parts). Every label's surface must still be closed with the right volume.
  uint32_t state = 12345;
  for (int round = 0; round < 20; ++round) {
    VoxelGrid grid(4 + round % 3, 3 + round % 4, 5);
    for (int64_t i = 0; i < grid.voxelCount(); ++i) {
      state = state * 1664525u + 1013904223u;
      grid.setLabelAt(i, static_cast<int>(state >> 30));
    }
    for (int id = 1; id <= grid.maxLabel(); ++id) {
      if (grid.labelCounts()[id] > 0) expectClosedSurfaceOfPart(grid, id, 1.0, "round " + std::to_string(round));
    }
  }
}

TEST(ExportSurface, MissingPartIsAnError) {
  const VoxelGrid grid = gridFromLayers({{"1 1 0"}});
  EXPECT_THROW(partSurfaceMesh(grid, 2), Error);
}

TEST(ExportStl, BinaryHeaderCountAndTrianglesParseBack) {
  const AssemblyDocument document = loadReference("result_puz/Cube_4x4x4_K9.puz");
  ExportOptions options;
  options.voxelSize = 2.5;
  const std::vector<uint8_t> bytes = exportAssembly(document, ExportFormat::StlBinary, options);
  int64_t expectedTriangles = 0, voxels = 0;
  for (int id = 1; id <= 9; ++id) {
    expectedTriangles += static_cast<int64_t>(partSurfaceMesh(document.voxels, id).triangles.size());
    voxels += document.voxels.labelCounts()[id];
  }
  ASSERT_EQ(bytes.size(), 84u + 50u * expectedTriangles);
  const std::string header = text(bytes).substr(0, 80);
  EXPECT_NE(header.rfind("solid", 0), 0u) << "a binary header must not look like ASCII STL";
  EXPECT_EQ(header.rfind("desia voxel export, all 9 parts, voxel size 2.5", 0), 0u) << header;
  EXPECT_EQ(littleEndian(bytes, 80, 4), static_cast<uint32_t>(expectedTriangles));
  // Every normal is an axis direction and agrees with the winding of its triangle.
  for (int64_t t = 0; t < expectedTriangles; ++t) {
    float values[12];
    std::memcpy(values, bytes.data() + 84 + 50 * t, sizeof values);
    EXPECT_EQ(std::fabs(values[0]) + std::fabs(values[1]) + std::fabs(values[2]), 1.0f);
    const Vec a{values[3], values[4], values[5]}, b{values[6], values[7], values[8]},
        c{values[9], values[10], values[11]};
    const Vec cross{(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                    (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    EXPECT_GT(cross[0] * values[0] + cross[1] * values[1] + cross[2] * values[2], 0.0);
    EXPECT_EQ(bytes[84 + 50 * t + 48], 0);
    EXPECT_EQ(bytes[84 + 50 * t + 49], 0);
  }
  // The core's own STL reader welds equal positions: the soup of all parts encloses all voxels.
  const TriangleMesh parsed = parseStl(text(bytes), "k9.stl");
  EXPECT_EQ(static_cast<int64_t>(parsed.triangles.size()), expectedTriangles);
  EXPECT_NEAR(enclosedVolume(parsed), voxels * 2.5 * 2.5 * 2.5, 1e-6);
}

TEST(ExportStl, OnePartAsciiAndBinaryDescribeTheSameClosedSolid) {
  const AssemblyDocument document = loadReference("result_puz/cube_5x5x5_K16.puz");
  ExportOptions options;
  options.part = 11;
  const std::string ascii = text(exportAssembly(document, ExportFormat::StlAscii, options));
  EXPECT_EQ(ascii.rfind("solid part11\nfacet normal ", 0), 0u);
  EXPECT_EQ(ascii.substr(ascii.size() - 16), "endsolid part11\n");
  const TriangleMesh fromAscii = parseStl(ascii, "p11.stl");
  const TriangleMesh fromBinary = parseStl(text(exportAssembly(document, ExportFormat::StlBinary, options)), "p11.stl");
  EXPECT_EQ(fromAscii.vertices, fromBinary.vertices);
  EXPECT_EQ(fromAscii.triangles, fromBinary.triangles);
  EXPECT_EQ(fromAscii.triangles.size(), partSurfaceMesh(document.voxels, 11).triangles.size());
  // STL has no vertex indices: readers weld equal positions, and part 11 has pinch edges (two of
  // its voxels touch only along an edge), where the welded mesh has four triangles on one edge.
  // The surface is still closed: every welded edge is used as often in each direction.
  std::map<std::pair<int, int>, int> balance;
  int pinchEdges = 0;
  for (const auto& t : fromAscii.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      balance[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  }
  for (const auto& [edge, difference] : balance) EXPECT_EQ(difference, 0) << edge.first << "-" << edge.second;
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : fromAscii.triangles) {
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  for (const auto& [edge, count] : uses) pinchEdges += count == 4;
  EXPECT_GE(pinchEdges, 1) << "part 11 was chosen for its pinch edge";
  EXPECT_NO_THROW(checkClosedMesh(fromAscii, "p11.stl"));
  EXPECT_DOUBLE_EQ(enclosedVolume(fromAscii), static_cast<double>(document.voxels.labelCounts()[11]));
}

// OBJ objects "o partN" as meshes with indices relative to the object (OBJ numbers are global).
std::map<int, TriangleMesh> parseObjObjects(const std::string& obj, std::vector<std::string>& problems) {
  std::map<int, TriangleMesh> objects;
  std::istringstream in(obj);
  int current = 0;
  int64_t firstVertex = 1, seenVertices = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "o") {
      std::string name;
      fields >> name;
      if (name.rfind("part", 0) != 0) problems.push_back("object name " + name);
      current = std::stoi(name.substr(4));
      firstVertex = seenVertices + 1;
    } else if (kind == "v") {
      Vec v;
      fields >> v[0] >> v[1] >> v[2];
      objects[current].vertices.push_back(v);
      ++seenVertices;
    } else if (kind == "f") {
      std::array<int, 3> t;
      for (int& index : t) {
        int64_t global = 0;
        fields >> global;
        if (global < firstVertex || global > seenVertices)
          problems.push_back("face refers outside its object: " + line);
        index = static_cast<int>(global - firstVertex);
      }
      std::string extra;
      if (fields >> extra) problems.push_back("face with more than 3 vertices: " + line);
      objects[current].triangles.push_back(t);
    } else if (kind != "#" && !kind.empty()) {
      problems.push_back("unexpected record: " + line);
    }
  }
  return objects;
}

TEST(ExportObj, EveryPartIsItsOwnClosedObjectWithItsVolume) {
  for (const std::string file : {"result_puz/bunny_15x14x11_K80.puz", "result_puz/Cube_Hollow_4x4x4_K7"}) {
    const AssemblyDocument document = loadReference(file);
    ExportOptions options;
    options.voxelSize = 0.5;
    const std::string obj = text(exportAssembly(document, ExportFormat::Obj, options));
    std::vector<std::string> problems;
    const std::map<int, TriangleMesh> objects = parseObjObjects(obj, problems);
    EXPECT_EQ(problems, std::vector<std::string>{});
    ASSERT_EQ(static_cast<int>(objects.size()), document.voxels.maxLabel()) << file;
    int expectedId = 1;
    for (const auto& [id, mesh] : objects) {
      EXPECT_EQ(id, expectedId++);
      EXPECT_EQ(manifoldProblem(mesh), "") << file << " part " << id;
      EXPECT_NEAR(enclosedVolume(mesh), document.voxels.labelCounts()[id] * 0.125, 1e-9) << file << " part " << id;
    }
    // The core's OBJ reader and closed-mesh check accept the whole file.
    EXPECT_NO_THROW(checkClosedMesh(parseObj(obj, "all.obj"), "all.obj"));
  }
}

// A part exported alone and voxelized again at one voxel per unit gives the part's voxels,
// cropped to its bounding box (the voxelizer puts voxel 0 at the bounding-box minimum).
void expectPartVoxelizesBack(const AssemblyDocument& document, int id, ExportFormat format) {
  const VoxelGrid& grid = document.voxels;
  ExportOptions options;
  options.part = id;
  const std::string bytes = text(exportAssembly(document, format, options));
  const TriangleMesh mesh = format == ExportFormat::Obj ? parseObj(bytes, "part.obj") : parseStl(bytes, "part.stl");
  std::array<int, 3> low{grid.nx(), grid.ny(), grid.nz()}, high{-1, -1, -1};
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != id) continue;
    const Int3 c = grid.coordinates(i);
    const std::array<int, 3> p{c.x, c.y, c.z};
    for (int a = 0; a < 3; ++a) low[a] = std::min(low[a], p[a]), high[a] = std::max(high[a], p[a]);
  }
  VoxelizeOptions voxelize;
  voxelize.resolution = std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]}) + 1;
  const VoxelGrid again = voxelizeSolid(mesh, voxelize, "part");
  ASSERT_EQ(again.nx(), high[0] - low[0] + 1);
  ASSERT_EQ(again.ny(), high[1] - low[1] + 1);
  ASSERT_EQ(again.nz(), high[2] - low[2] + 1);
  for (int z = 0; z < again.nz(); ++z) {
    for (int y = 0; y < again.ny(); ++y) {
      for (int x = 0; x < again.nx(); ++x) {
        ASSERT_EQ(again.label(x, y, z) == 1, grid.label(x + low[0], y + low[1], z + low[2]) == id)
            << "part " << id << " voxel " << x << " " << y << " " << z;
      }
    }
  }
}

TEST(ExportObj, OnePartVoxelizesBackToTheSameVoxels) {
  const AssemblyDocument document = loadReference("result_puz/cartoon_dog.puz");
  for (const int id : {1, 2, 9, 14}) expectPartVoxelizesBack(document, id, ExportFormat::Obj);
}

TEST(ExportStl, OnePartVoxelizesBackToTheSameVoxelsEvenWithPinchEdges) {
  // Part 11 of the 5x5x5 puzzle has a pinch edge (see above): STL readers weld it into an edge
  // of four triangles, which the voxelizer accepts (an even number) and fills correctly.
  const AssemblyDocument cube = loadReference("result_puz/cube_5x5x5_K16.puz");
  expectPartVoxelizesBack(cube, 11, ExportFormat::StlBinary);
  const AssemblyDocument dog = loadReference("result_puz/cartoon_dog.puz");
  for (const int id : {1, 2, 9, 14}) expectPartVoxelizesBack(dog, id, ExportFormat::StlBinary);
}

TEST(ExportGzip, StoredBlocksCrcAndLengthsDecode) {
  EXPECT_EQ(bitwiseCrc32("123456789"), 0xCBF43926u);  // the CRC-32 check value
  const std::vector<uint8_t> empty = gzipStored("");
  EXPECT_EQ(empty.size(), 10u + 5u + 8u);
  EXPECT_EQ(gunzipStored(empty).data, "");
  const std::vector<uint8_t> check = gzipStored("123456789");
  EXPECT_EQ(littleEndian(check, check.size() - 8, 4), 0xCBF43926u);
  // 200,000 bytes: three full blocks of 65,535 bytes and one of 3,395.
  std::string large(200000, '\0');
  for (size_t i = 0; i < large.size(); ++i) large[i] = static_cast<char>((i * 7919 + i / 251) & 0xFF);
  const Gunzipped decoded = gunzipStored(gzipStored(large));
  EXPECT_EQ(decoded.blocks, 4);
  EXPECT_TRUE(decoded.data == large);
}

TEST(ExportXmPuzzle, PiecesReproduceTheLabelsOfEveryReferencePuzzle) {
  for (const std::string& file : kReferencePuzzles) {
    const AssemblyDocument document = loadReference(file);
    const VoxelGrid& grid = document.voxels;
    const std::vector<uint8_t> bytes = exportAssembly(document, ExportFormat::XmPuzzle, {});
    const std::string xml = gunzipStored(bytes).data;
    EXPECT_EQ(xml, xmpuzzleXml(document)) << file;
    const std::vector<XmlShape> shapes = shapesOf(xml);
    const int parts = grid.maxLabel();
    ASSERT_EQ(static_cast<int>(shapes.size()), parts + 1) << file;
    // Shape 0, the result: every voxel of the assembly, in the full grid, index x + X*(y + Y*z).
    ASSERT_EQ(shapes[0].x, grid.nx());
    ASSERT_EQ(shapes[0].y, grid.ny());
    ASSERT_EQ(shapes[0].z, grid.nz());
    ASSERT_EQ(static_cast<int64_t>(shapes[0].voxels.size()), grid.voxelCount());
    for (int64_t i = 0; i < grid.voxelCount(); ++i) ASSERT_EQ(shapes[0].voxels[i], grid.labelAt(i) > 0 ? '#' : '_');
    // Pieces 1..N: each part cropped to its bounding box (no empty border), put back at the offset
    // the comment gives; together they rebuild every label of the grid.
    const std::map<int, std::array<int, 3>> offsets = offsetsOf(xml);
    ASSERT_EQ(static_cast<int>(offsets.size()), parts) << file;
    std::vector<int> rebuilt(grid.voxelCount(), 0);
    for (int id = 1; id <= parts; ++id) {
      const XmlShape& piece = shapes[id];
      EXPECT_EQ(piece.name, "part " + std::to_string(id));
      ASSERT_EQ(static_cast<int64_t>(piece.voxels.size()), int64_t{piece.x} * piece.y * piece.z);
      const std::array<int, 3> at = offsets.at(id);
      std::array<bool, 6> touches{};  // the box is tight: the piece reaches each of its six sides
      for (int z = 0; z < piece.z; ++z) {
        for (int y = 0; y < piece.y; ++y) {
          for (int x = 0; x < piece.x; ++x) {
            const char c = piece.voxels[x + piece.x * (y + piece.y * z)];
            ASSERT_TRUE(c == '#' || c == '_') << file << " piece " << id;
            if (c != '#') continue;
            ASSERT_TRUE(grid.inside(x + at[0], y + at[1], z + at[2]));
            int& label = rebuilt[grid.index(x + at[0], y + at[1], z + at[2])];
            ASSERT_EQ(label, 0) << "two pieces claim one voxel";
            label = id;
            touches[0] |= x == 0, touches[1] |= x == piece.x - 1, touches[2] |= y == 0;
            touches[3] |= y == piece.y - 1, touches[4] |= z == 0, touches[5] |= z == piece.z - 1;
          }
        }
      }
      EXPECT_EQ(touches, (std::array<bool, 6>{true, true, true, true, true, true})) << file << " piece " << id;
    }
    EXPECT_TRUE(rebuilt == grid.labels()) << file;
    // The problem: every piece once, shape 0 as the result, state 3 (solutions known, not counted),
    // one saved solution (ExportXmPuzzle.SavedSolution... checks its content).
    std::string problemShapes;
    for (int id = 1; id <= parts; ++id) problemShapes += "    <shape id=\"" + std::to_string(id) + "\" count=\"1\"/>\n";
    EXPECT_NE(xml.find("<problem name=\"desia\" state=\"3\" assemblies=\"1\" solutions=\"1\" time=\"0\">\n   <shapes>\n" + problemShapes +
                       "   </shapes>\n   <result id=\"0\"/>\n   <bitmap/>\n   <solutions>\n    <solution>\n     <assembly>"),
              std::string::npos)
        << file;
    EXPECT_NE(xml.find("    </solution>\n   </solutions>\n  </problem>\n </problems>\n"), std::string::npos) << file;
  }
}

// One <separation> of the saved solution: its side ("" for the root, "left" or "removed"), the
// pieces still together, the position of each piece (in the order of `pieces`) in every state,
// and where it nests.
struct Separation {
  std::string type;
  std::vector<int> pieces;
  std::vector<std::vector<std::array<int, 3>>> states;
  int parent = -1;
};

std::vector<int> numbersOf(const std::string& text) {
  std::vector<int> numbers;
  std::istringstream in(text);
  for (int n; in >> n;) numbers.push_back(n);
  return numbers;
}

// The separations in document order (pre-order), after checking that every tag is closed.
std::vector<Separation> separationTreeOf(const std::string& xml) {
  std::vector<Separation> tree;
  const std::regex token(
      R"re(<separation( type="(left|removed)")?>|<pieces count="(\d+)">([^<]*)</pieces>|<state><dx>([^<]*)</dx><dy>([^<]*)</dy><dz>([^<]*)</dz></state>|</separation>)re");
  std::vector<int> open;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), token); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    if (m.str(0).rfind("<separation", 0) == 0) {
      tree.push_back({m[2].matched ? m.str(2) : "", {}, {}, open.empty() ? -1 : open.back()});
      open.push_back(static_cast<int>(tree.size()) - 1);
    } else if (m.str(0) == "</separation>") {
      EXPECT_FALSE(open.empty());
      if (!open.empty()) open.pop_back();
    } else if (m[3].matched) {
      tree[open.back()].pieces = numbersOf(m[4]);
      EXPECT_EQ(static_cast<int>(tree[open.back()].pieces.size()), std::stoi(m[3]));
    } else {
      const std::vector<int> dx = numbersOf(m[5]), dy = numbersOf(m[6]), dz = numbersOf(m[7]);
      EXPECT_EQ(dx.size(), tree[open.back()].pieces.size());
      EXPECT_EQ(dy.size(), dx.size());
      EXPECT_EQ(dz.size(), dx.size());
      std::vector<std::array<int, 3>> positions;
      for (size_t k = 0; k < dx.size() && k < dy.size() && k < dz.size(); ++k) positions.push_back({dx[k], dy[k], dz[k]});
      tree[open.back()].states.push_back(positions);
    }
  }
  EXPECT_TRUE(open.empty());
  return tree;
}

// The moves a separation tree stands for, as BurrTools reads it: between two states one set of
// pieces moves along one axis; in the last state the removed pieces are beyond 10000. Checks
// that each side starts where its pieces were before they separated.
std::vector<GroupMove> movesOfTree(const std::vector<Separation>& tree, const std::string& file) {
  std::vector<GroupMove> moves;
  for (size_t n = 0; n < tree.size(); ++n) {
    const Separation& separation = tree[n];
    EXPECT_GE(separation.states.size(), 2u) << file;
    if (separation.parent >= 0) {
      const Separation& parent = tree[static_cast<size_t>(separation.parent)];
      const auto& before = parent.states[parent.states.size() - 2];
      for (size_t p = 0; p < separation.pieces.size(); ++p) {
        const size_t at = static_cast<size_t>(
            std::find(parent.pieces.begin(), parent.pieces.end(), separation.pieces[p]) - parent.pieces.begin());
        EXPECT_EQ(separation.states[0][p], before[at]) << file << ": a side starts where its pieces were";
      }
    }
    for (size_t k = 1; k < separation.states.size(); ++k) {
      GroupMove move;
      move.out = k + 1 == separation.states.size();
      std::array<int, 3> shift{0, 0, 0};
      for (size_t p = 0; p < separation.pieces.size(); ++p) {
        std::array<int, 3> delta;
        for (int axis = 0; axis < 3; ++axis) delta[axis] = separation.states[k][p][axis] - separation.states[k - 1][p][axis];
        if (delta == std::array<int, 3>{0, 0, 0}) continue;
        EXPECT_TRUE(move.parts.empty() || delta == shift) << file << ": pieces moved together move alike";
        shift = delta;
        move.parts.push_back(separation.pieces[p]);
        const bool gone = std::any_of(separation.states[k][p].begin(), separation.states[k][p].end(),
                                      [](int d) { return std::abs(d) > 10000; });
        EXPECT_EQ(gone, move.out) << file << ": gone in the last state only";
      }
      int axesMoved = 0;
      for (int axis = 0; axis < 3; ++axis) {
        if (shift[axis] == 0) continue;
        ++axesMoved;
        move.direction[axis] = shift[axis] > 0 ? 1 : -1;
        move.steps = move.out ? 0 : std::abs(shift[axis]);
      }
      EXPECT_EQ(axesMoved, 1) << file << " separation " << n << " state " << k;
      moves.push_back(move);
    }
  }
  return moves;
}

TEST(ExportXmPuzzle, SavedSolutionPlacesEveryPieceAndReplaysTheDisassemblyPlan) {
  std::vector<std::string> files = kReferencePuzzles;
  // BurrTools' own puzzles, whose plans move several pieces at once (the level-98 PelikanBurr).
  for (const char* burr : {"SolidSixPieceBurrs-p0-s0.puz", "SolidSixPieceBurrs-p0-s257.puz", "PelikanBurr-p0-s0.puz"}) {
    files.push_back(std::string("tests/data/burrtools/") + burr);
  }
  for (const std::string& file : files) {
    const AssemblyDocument document = file.rfind("tests/", 0) == 0
                                          ? parseAssemblyText(testing::readFileText(testing::projectPath(file)), file)
                                          : loadReference(file);
    const VoxelGrid& grid = document.voxels;
    const int parts = grid.maxLabel();
    const std::string xml = xmpuzzleXml(document, file);
    // The assembly: x y z and transformation 0 per piece, x y z where the piece's box starts in the
    // result; putting every piece there rebuilds the labels.
    std::smatch assemblyMatch;
    ASSERT_TRUE(std::regex_search(xml, assemblyMatch, std::regex("<assembly>([^<]*)</assembly>"))) << file;
    const std::vector<int> placements = numbersOf(assemblyMatch[1]);
    ASSERT_EQ(static_cast<int>(placements.size()), 4 * parts) << file;
    const std::vector<XmlShape> shapes = shapesOf(xml);
    std::vector<int> rebuilt(grid.voxelCount(), 0);
    for (int piece = 0; piece < parts; ++piece) {
      const XmlShape& shape = shapes.at(piece + 1);
      const int* at = &placements[4 * piece];
      EXPECT_EQ(at[3], 0) << file << ": transformation 0, the piece as drawn";
      for (int z = 0; z < shape.z; ++z) {
        for (int y = 0; y < shape.y; ++y) {
          for (int x = 0; x < shape.x; ++x) {
            if (shape.voxels[x + shape.x * (y + shape.y * z)] != '#') continue;
            ASSERT_TRUE(grid.inside(x + at[0], y + at[1], z + at[2])) << file;
            rebuilt[grid.index(x + at[0], y + at[1], z + at[2])] = piece + 1;
          }
        }
      }
    }
    EXPECT_TRUE(rebuilt == grid.labels()) << file;

    // The separation tree: the root starts with every piece at its placement; its moves, as
    // BurrTools reads them, are the plan's and take the puzzle apart voxel by voxel.
    const std::vector<Separation> tree = separationTreeOf(xml);
    if (parts == 1) {
      EXPECT_TRUE(tree.empty()) << file << ": one piece, nothing to take apart";
      continue;
    }
    const DisassemblyPlan plan = planVoxelDisassembly(grid, document.assembly);
    ASSERT_TRUE(plan.complete) << file;
    ASSERT_FALSE(tree.empty()) << file;
    for (int piece = 0; piece < parts; ++piece) {
      EXPECT_EQ(tree[0].states[0][piece], (std::array<int, 3>{placements[4 * piece], placements[4 * piece + 1],
                                                              placements[4 * piece + 2]}))
          << file << ": BurrTools' states are positions, the first one the placements";
    }
    const std::vector<GroupMove> moves = movesOfTree(tree, file);
    EXPECT_EQ(moves.size(), plan.moves.size()) << file;
    EXPECT_EQ(testing::replayVoxelMoves(grid, moves, true), "") << file;
  }
}

TEST(ExportXmPuzzle, AnUnnamedPuzzleIsNamedAfterItsFile) {
  AssemblyDocument document = loadReference("result_puz/Cube_4x4x4_K9.puz");
  document.name.clear();
  ExportOptions options;
  options.source = "puzzles/Cube_4x4x4_K9.puz";
  EXPECT_EQ(shapesOf(gunzipStored(exportAssembly(document, ExportFormat::XmPuzzle, options)).data)[0].name,
            "Cube_4x4x4_K9");
  options.source = "<input>";
  EXPECT_EQ(shapesOf(gunzipStored(exportAssembly(document, ExportFormat::XmPuzzle, options)).data)[0].name,
            "assembly");
}

TEST(ExportXmPuzzle, DocumentStructureAndEscapedNames) {
  const std::string json = R"({"format": "desia-assembly", "kind": "voxel", "name": "Tom & Jerry's <\"cube\">\nv2",
    "voxel": {"size": [3, 1, 1], "labels": [1, 2, 3]}})";
  const AssemblyDocument document = parseAssemblyText(json, "names.json");
  const std::string xml = gunzipStored(exportAssembly(document, ExportFormat::XmPuzzle, {})).data;
  EXPECT_EQ(
      xml.rfind("<?xml version=\"1.0\"?>\n<puzzle version=\"2\">\n <gridType type=\"0\"/>\n <colors/>\n <shapes>\n", 0),
      0u);
  // The name escaped, its line break (a control character) turned into a space.
  const std::string escaped = "Tom &amp; Jerry&apos;s &lt;&quot;cube&quot;&gt; v2";
  EXPECT_NE(xml.find("  <voxel x=\"3\" y=\"1\" z=\"1\" name=\"" + escaped +
                     "\" type=\"0\">###</voxel>\n"
                     "  <voxel x=\"1\" y=\"1\" z=\"1\" name=\"parts 1, 2, 3\" type=\"0\">#</voxel>\n </shapes>\n"),
            std::string::npos)
      << xml;
  // Three equal parts are one shape with count 3 (BurrTools' solver would count 6 permutations
  // of three separate shapes as 6 assemblies), placed as pieces 1, 2, 3 in part order.
  EXPECT_NE(xml.find("   <shapes>\n    <shape id=\"1\" count=\"3\"/>\n   </shapes>\n"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<assembly>0 0 0 0 1 0 0 0 2 0 0 0</assembly>"), std::string::npos) << xml;
  EXPECT_NE(xml.find(" <comment>Exported by desia from " + escaped), std::string::npos) << xml;
  EXPECT_NE(xml.find("\npart 1: 0 0 0\npart 2: 1 0 0\npart 3: 2 0 0\n</comment>\n</puzzle>\n"), std::string::npos)
      << xml;
  EXPECT_EQ(xml.find("Tom & "), std::string::npos);
}

// Runs `operation` and returns the desia::Error's message (code checked), or "" if none.
template <typename Operation>
std::string errorOf(Operation&& operation, ErrorCode code = ErrorCode::BadInput) {
  try {
    operation();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    return e.what();
  }
  return "";
}

TEST(ExportErrors, BadRequestsAreNamed) {
  const AssemblyDocument k9 = loadReference("result_puz/Cube_4x4x4_K9.puz");
  auto exportWith = [&](ExportFormat format, int part, double voxelSize) {
    ExportOptions options;
    options.part = part;
    options.voxelSize = voxelSize;
    options.source = "k9.puz";
    return [&k9, format, options] { exportAssembly(k9, format, options); };
  };
  EXPECT_EQ(errorOf(exportWith(ExportFormat::StlBinary, 10, 1)),
            "k9.puz: part 10 does not exist: the assembly has parts 1 to 9 (0 = all parts)");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::Obj, -1, 1)),
            "k9.puz: part -1 does not exist: the assembly has parts 1 to 9 (0 = all parts)");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::XmPuzzle, 2, 1)),
            "k9.puz: a BurrTools .xmpuzzle holds the whole puzzle, so it cannot hold only part 2 (choose all parts, "
            "part 0)");
  for (const double size : {0.0, -1.0, 1e-7, 2e6, std::nan(""), HUGE_VAL}) {
    EXPECT_NE(errorOf(exportWith(ExportFormat::StlAscii, 0, size)).find("k9.puz: the voxel size must be a number from"),
              std::string::npos)
        << size;
  }
  // A document that is not a voxel assembly.
  const std::string contacts = R"({"format": "desia-assembly", "kind": "contacts", "parts": [{"id": 1}, {"id": 2}],
    "contacts": [{"a": 1, "b": 2, "normal": [1, 0, 0]}]})";
  ExportOptions options;
  options.source = "c.json";
  EXPECT_EQ(errorOf([&] { exportAssembly(parseAssemblyText(contacts, "c.json"), ExportFormat::Obj, options); }),
            "c.json: export needs a voxel assembly, this is a contacts document");
  // An assembly without voxels (documents built in code; parsed files always have a part).
  AssemblyDocument empty;
  EXPECT_EQ(errorOf([&] { exportAssembly(empty, ExportFormat::StlBinary, options); }),
            "c.json: the assembly is empty: it has no voxels to export");
  empty.voxels = VoxelGrid(2, 2, 2);
  EXPECT_EQ(errorOf([&] { exportAssembly(empty, ExportFormat::XmPuzzle, options); }),
            "c.json: the assembly is empty: it has no voxels to export");
  EXPECT_EQ(errorOf([&] { xmpuzzleXml(empty, "e.puz"); }), "e.puz: the assembly is empty: it has no voxels to export");
}

TEST(ExportErrors, OversizedExportsAreRefusedBeforeBuilding) {
  // Two layers of 1024 x 1024 voxels, one part each: over 4 million faces, 8 million triangles,
  // at least 800 MB of ASCII STL, above the 512 MiB limit.
  VoxelGrid grid(1024, 1024, 2);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) grid.setLabelAt(i, 1 + grid.coordinates(i).z % 2);
  AssemblyDocument document;
  document.voxels = std::move(grid);
  ExportOptions options;
  options.source = "big.puz";
  const std::string message =
      errorOf([&] { exportAssembly(document, ExportFormat::StlAscii, options); }, ErrorCode::TooLarge);
  EXPECT_NE(message.find("big.puz: the stl-ascii file ("), std::string::npos) << message;
  EXPECT_NE(message.find("more than the export limit of 512 MiB"), std::string::npos) << message;
}

TEST(ExportBytes, SameRequestSameBytesAndVoxelSizeScalesOnlyCoordinates) {
  const AssemblyDocument dog = loadReference("result_puz/cartoon_dog.puz");
  ExportOptions unit, half;
  half.voxelSize = 0.5;
  for (const ExportFormat format :
       {ExportFormat::StlBinary, ExportFormat::StlAscii, ExportFormat::Obj, ExportFormat::XmPuzzle}) {
    EXPECT_EQ(exportAssembly(dog, format, unit), exportAssembly(dog, format, unit)) << exportFormatName(format);
  }
  EXPECT_EQ(exportAssembly(dog, ExportFormat::XmPuzzle, unit), exportAssembly(dog, ExportFormat::XmPuzzle, half));
  const TriangleMesh a = parseObj(text(exportAssembly(dog, ExportFormat::Obj, unit)), "a.obj");
  const TriangleMesh b = parseObj(text(exportAssembly(dog, ExportFormat::Obj, half)), "b.obj");
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.triangles, b.triangles);
  for (size_t v = 0; v < a.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a.vertices[v][k] * 0.5, b.vertices[v][k]);
  }
}

// ---- part surfaces for display -------------------------------------------------------------------

TEST(PartSurfaces, SameTrianglesAsTheExportAxisNormalsAndTheVolumeOfEveryPart) {
  for (const std::string& file : kReferencePuzzles) {
    const AssemblyDocument document = loadReference(file);
    const std::vector<PartSurface> surfaces = partSurfaces(document, file);
    ASSERT_EQ(surfaces.size(), static_cast<size_t>(document.voxels.maxLabel())) << file;
    for (size_t k = 0; k < surfaces.size(); ++k) {
      const PartSurface& surface = surfaces[k];
      const int id = static_cast<int>(k) + 1;
      ASSERT_EQ(surface.partId, id) << file << ": parts in increasing id";
      ASSERT_EQ(surface.positions.size(), surface.normals.size()) << file;
      ASSERT_EQ(surface.positions.size() % 9, 0u) << file;
      const size_t triangles = surface.positions.size() / 9;
      // The binary STL of this one part: its header's triangle count (bytes 80 to 83).
      ExportOptions onePart;
      onePart.part = id;
      const std::vector<uint8_t> stl = exportAssembly(document, ExportFormat::StlBinary, onePart);
      EXPECT_EQ(triangles, littleEndian(stl, 80, 4)) << file << " part " << id;
      EXPECT_EQ(triangles, partSurfaceMesh(document.voxels, id).triangles.size()) << file << " part " << id;
      double volume = 0;
      for (size_t t = 0; t < triangles; ++t) {
        const float* a = &surface.positions[9 * t];
        const float* b = a + 3;
        const float* c = a + 6;
        const float* normal = &surface.normals[9 * t];
        int nonzero = 0;
        for (int axis = 0; axis < 3; ++axis) {
          ASSERT_TRUE(normal[axis] == 0.0f || normal[axis] == 1.0f || normal[axis] == -1.0f) << file;
          nonzero += normal[axis] != 0.0f;
        }
        ASSERT_EQ(nonzero, 1) << file << " part " << id << " triangle " << t << ": a unit axis normal";
        for (int corner = 1; corner < 3; ++corner) {
          for (int axis = 0; axis < 3; ++axis) ASSERT_EQ(normal[3 * corner + axis], normal[axis]) << "flat normals";
        }
        // The normal points along (b - a) x (c - a): counter-clockwise seen from outside.
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double cross[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        ASSERT_GT(cross[0] * normal[0] + cross[1] * normal[1] + cross[2] * normal[2], 0.0) << file << " triangle " << t;
        volume += (a[0] * (static_cast<double>(b[1]) * c[2] - static_cast<double>(b[2]) * c[1]) -
                   a[1] * (static_cast<double>(b[0]) * c[2] - static_cast<double>(b[2]) * c[0]) +
                   a[2] * (static_cast<double>(b[0]) * c[1] - static_cast<double>(b[1]) * c[0])) /
                  6;
      }
      EXPECT_NEAR(volume, static_cast<double>(document.voxels.labelCounts()[id]), 1e-6) << file << " part " << id;
    }
  }
}

TEST(PartSurfaces, BadDocumentsGiveTheExportErrors) {
  const std::string contacts = R"({"format": "desia-assembly", "kind": "contacts", "parts": [{"id": 1}, {"id": 2}],
    "contacts": [{"a": 1, "b": 2, "normal": [1, 0, 0]}]})";
  EXPECT_EQ(errorOf([&] { partSurfaces(parseAssemblyText(contacts, "c.json"), "c.json"); }),
            "c.json: export needs a voxel assembly, this is a contacts document");
  AssemblyDocument empty;
  empty.voxels = VoxelGrid(2, 2, 2);
  EXPECT_EQ(errorOf([&] { partSurfaces(empty, "e.puz"); }), "e.puz: the assembly is empty: it has no voxels to export");
  // Labels 1 and 3 only: part 2 has no voxels, as the exports say.
  empty.voxels.setLabelAt(0, 1);
  empty.voxels.setLabelAt(7, 3);
  EXPECT_EQ(errorOf([&] { partSurfaces(empty, "gap.puz"); }), "gap.puz: part 2 has no voxels");
}


// ---- frame pieces: what a maker cuts, prints and glues (issue 9) -----------------------------

// The triangles of each named OBJ object as a mesh of its own.
std::map<std::string, TriangleMesh> objectsOf(const TriangleMesh& mesh) {
  std::map<std::string, TriangleMesh> objects;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    TriangleMesh& object = objects[mesh.groupNames.at(static_cast<size_t>(mesh.triangleGroup.at(t)))];
    const int first = static_cast<int>(object.vertices.size());
    for (int corner : mesh.triangles[t]) object.vertices.push_back(mesh.vertices[static_cast<size_t>(corner)]);
    object.triangles.push_back({first, first + 1, first + 2});
  }
  // Weld equal vertices so each object's closedness can be judged edge by edge.
  for (auto& [name, object] : objects) {
    std::map<std::array<double, 3>, int> index;
    TriangleMesh welded;
    for (const auto& t : object.triangles) {
      std::array<int, 3> corners{};
      for (int k = 0; k < 3; ++k) {
        const auto& v = object.vertices[static_cast<size_t>(t[k])];
        auto [it, added] = index.emplace(v, static_cast<int>(welded.vertices.size()));
        if (added) welded.vertices.push_back(v);
        corners[k] = it->second;
      }
      welded.triangles.push_back(corners);
    }
    object = welded;
  }
  return objects;
}

TEST(FramePieces, EveryBodyAndGluedJointPieceIsItsOwnClosedObjectAddingUpToTheBeam) {
  const std::string path = "examples/frame/frame_chair_result.json";
  const FrameDocument frame = parseFrameText(testing::readFileText(testing::projectPath(path)), path);
  const std::vector<uint8_t> bytes = exportFrame(frame, "pieces-obj", 0, path);
  const std::map<std::string, TriangleMesh> objects = objectsOf(parseObj(std::string(bytes.begin(), bytes.end()), path));
  size_t jointPieces = 0;
  for (const FrameBeam& beam : frame.layout.frame.beams) {
    const int internal = static_cast<int>(&beam - frame.layout.frame.beams.data());
    const std::string name = "beam" + std::to_string(beam.id);
    ASSERT_TRUE(objects.count(name)) << name;
    double pieces = enclosedVolume(objects.at(name));
    EXPECT_NO_THROW(checkClosedMesh(objects.at(name), name));
    for (int joint : beam.joints) {
      const std::string piece = name + "_joint" + std::to_string(frame.layout.frame.joints[joint].id);
      int owned = 0;
      for (int label : frame.labels[joint]) owned += label == internal ? 1 : 0;
      ASSERT_EQ(objects.count(piece), owned > 0 ? 1u : 0u) << piece;
      if (owned == 0) continue;
      ++jointPieces;
      EXPECT_NO_THROW(checkClosedMesh(objects.at(piece), piece));  // volumes below show the orientation
      const double voxel = std::pow(frame.layout.voxelSize, 3);
      EXPECT_NEAR(enclosedVolume(objects.at(piece)), owned * voxel, 1e-6 * owned * voxel) << piece;
      pieces += enclosedVolume(objects.at(piece));
    }
    // Body and glued pieces together are the beam as the assembly draws it, and no two share
    // volume: the body is the stick cut to length, from joint face to joint face (issue 28, item
    // 11; it used to reach half a section into each joint piece).
    const double whole = enclosedVolume(beamPartMesh(frame.layout, frame.labels, internal));
    EXPECT_NEAR(pieces, whole, 1e-6 * whole) << name;
    const std::vector<OrientedBox> body = beamBodyBoxes(frame.layout, internal);
    ASSERT_EQ(body.size(), 1u) << name;
    const double halfSide = std::min({body[0].halfExtents[0], body[0].halfExtents[1], body[0].halfExtents[2]});
    const double stick = beamBodyLength(frame.layout, internal) * (2 * halfSide) * (2 * halfSide);
    EXPECT_NEAR(enclosedVolume(objects.at(name)), stick, 1e-6 * stick) << name;
  }
  EXPECT_EQ(objects.size(), frame.layout.frame.beams.size() + jointPieces);
}

TEST(FramePieces, JointPiecesLieApartOnTheBuildPlate) {
  const std::string path = "examples/frame/frame_cube_result.json";
  const FrameDocument frame = parseFrameText(testing::readFileText(testing::projectPath(path)), path);
  const std::vector<uint8_t> objBytes = exportFrame(frame, "pieces-obj", 0, path);
  const std::map<std::string, TriangleMesh> objects = objectsOf(parseObj(std::string(objBytes.begin(), objBytes.end()), path));
  double jointVolume = 0;
  size_t jointPieces = 0;
  for (const auto& [name, object] : objects) {
    if (name.find("_joint") == std::string::npos) continue;
    jointVolume += enclosedVolume(object);
    ++jointPieces;
  }
  const std::vector<uint8_t> stlBytes = exportFrame(frame, "joint-pieces-stl", 0, path);
  const TriangleMesh plate = parseStl(std::string(stlBytes.begin(), stlBytes.end()), path);
  // Closed (a piece's voxels may touch along an edge only: four triangles there, as STL readers merge).
  EXPECT_NO_THROW(checkClosedMesh(plate, path));
  EXPECT_NEAR(enclosedVolume(plate), jointVolume, 1e-6 * jointVolume);
  double lowest = 1e300, highest = -1e300;
  for (const auto& v : plate.vertices) {
    lowest = std::min(lowest, v[2]);
    highest = std::max(highest, v[2]);
  }
  EXPECT_NEAR(lowest, 0.0, 1e-9);
  EXPECT_LE(highest, 3 * frame.layout.voxelSize + 1e-9);
  // Each piece in its own cell of the grid: the cells' count is at least the pieces'.
  std::set<std::pair<long, long>> cells;
  for (const auto& v : plate.vertices) {
    cells.insert({std::lround(std::floor(v[0] / (4 * frame.layout.voxelSize) + 1e-9)),
                  std::lround(std::floor(v[1] / (4 * frame.layout.voxelSize) + 1e-9))});
  }
  EXPECT_EQ(cells.size(), jointPieces);
  EXPECT_THROW(exportFrame(frame, "joint-pieces-stl", 2, path), Error);
}

}  // namespace
}  // namespace desia
