// SPDX-License-Identifier: GPL-3.0-or-later
// Print-ready voxel exports (core/io/voxel/print_export.cpp, voxel_surface.cpp's inset lattice, the ZIP
// writer): with a clearance every face of a part against another part moves in by exactly the
// clearance and the faces against empty space stay; the inset parts are closed, consistently
// oriented and lie inside their voxels, with the exact volumes worked out by hand for small cases;
// the ZIP is read back here field by field (CRC computed bit by bit) with one closed STL per part;
// the build plate has every part lying flat on z = 0 with its volume, no two boxes overlapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "test_support.h"

namespace desia {
namespace {

using desia::testing::bitwiseCrc32;
using desia::testing::enclosedVolume;
using desia::testing::gridFromLayers;
using desia::testing::loadReference;
using desia::testing::manifoldProblem;
using Vec = std::array<double, 3>;

const std::vector<std::string> kPuzzles = {
    "result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_Hollow_4x4x4_K7", "result_puz/cube_5x5x5_K16.puz",
    "result_puz/cartoon_dog.puz",   "result_puz/bunny_15x14x11_K80.puz",
};

constexpr double kVoxel = 10.0, kClearance = 0.2;

// ---- the faces of a mesh, by plane -----------------------------------------------------------------

// An axis-aligned triangle: its normal axis and sign, the plane's coordinate, and its corners.
struct FlatTriangle {
  int axis = 0, sign = 0;
  double plane = 0;
  std::array<Vec, 3> corners;
};

FlatTriangle flatTriangle(const TriangleMesh& mesh, const std::array<int, 3>& t) {
  FlatTriangle flat;
  for (int k = 0; k < 3; ++k) flat.corners[k] = mesh.vertices[t[k]];
  const Vec& a = flat.corners[0];
  const Vec& b = flat.corners[1];
  const Vec& c = flat.corners[2];
  const Vec n{(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
              (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
              (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
  for (int k = 1; k < 3; ++k) {
    if (std::fabs(n[k]) > std::fabs(n[flat.axis])) flat.axis = k;
  }
  flat.sign = n[flat.axis] > 0 ? 1 : -1;
  flat.plane = a[flat.axis];
  return flat;
}

// Is `p` (in the triangle's plane) inside the triangle or on its border?
bool containsInPlane(const FlatTriangle& t, const Vec& p) {
  const int u = (t.axis + 1) % 3, v = (t.axis + 2) % 3;
  auto side = [&](const Vec& a, const Vec& b) {
    return (b[u] - a[u]) * (p[v] - a[v]) - (b[v] - a[v]) * (p[u] - a[u]);
  };
  const double s0 = side(t.corners[0], t.corners[1]), s1 = side(t.corners[1], t.corners[2]),
               s2 = side(t.corners[2], t.corners[0]);
  const double eps = 1e-9;
  return (s0 >= -eps && s1 >= -eps && s2 >= -eps) || (s0 <= eps && s1 <= eps && s2 <= eps);
}

// The triangles of a mesh indexed by (normal axis, sign, plane in micro-units).
class FacesByPlane {
 public:
  explicit FacesByPlane(const TriangleMesh& mesh) {
    for (const auto& t : mesh.triangles) {
      const FlatTriangle flat = flatTriangle(mesh, t);
      planes_[key(flat.axis, flat.sign, flat.plane)].push_back(flat);
    }
  }
  // Does a triangle with outward normal sign * e_axis cover `p`?
  bool covers(int axis, int sign, const Vec& p) const {
    const auto found = planes_.find(key(axis, sign, p[axis]));
    if (found == planes_.end()) return false;
    return std::any_of(found->second.begin(), found->second.end(),
                       [&](const FlatTriangle& t) { return containsInPlane(t, p); });
  }

 private:
  static std::tuple<int, int, int64_t> key(int axis, int sign, double plane) {
    return {axis, sign, std::llround(plane * 1e6)};
  }
  std::map<std::tuple<int, int, int64_t>, std::vector<FlatTriangle>> planes_;
};

int labelOrEmpty(const VoxelGrid& grid, int x, int y, int z) { return grid.inside(x, y, z) ? grid.label(x, y, z) : 0; }

// ---- reading back a ZIP and binary STLs ------------------------------------------------------------

uint32_t littleEndian(const std::vector<uint8_t>& bytes, size_t at, int count) {
  uint32_t value = 0;
  for (int k = 0; k < count; ++k) value |= static_cast<uint32_t>(bytes.at(at + k)) << (8 * k);
  return value;
}

struct ZipFile {
  std::string name, data;
};

// Reads a stored ZIP from its end of central directory record, checks every central directory
// header against its local header (and the fixed date, the CRC, the sizes), and returns the files.
std::vector<ZipFile> readZip(const std::vector<uint8_t>& zip) {
  std::vector<ZipFile> files;
  EXPECT_GE(zip.size(), 22u);
  const size_t end = zip.size() - 22;
  EXPECT_EQ(littleEndian(zip, end, 4), 0x06054b50u) << "end of central directory, no archive comment";
  const uint32_t count = littleEndian(zip, end + 10, 2);
  EXPECT_EQ(littleEndian(zip, end + 8, 2), count);
  const uint32_t directorySize = littleEndian(zip, end + 12, 4), directoryOffset = littleEndian(zip, end + 16, 4);
  EXPECT_EQ(directoryOffset + directorySize, end) << "the central directory ends where the record starts";
  size_t at = directoryOffset;
  size_t expectedLocal = 0;
  for (uint32_t k = 0; k < count; ++k) {
    EXPECT_EQ(littleEndian(zip, at, 4), 0x02014b50u) << "central directory header " << k;
    const uint32_t method = littleEndian(zip, at + 10, 2), time = littleEndian(zip, at + 12, 2),
                   date = littleEndian(zip, at + 14, 2), crc = littleEndian(zip, at + 16, 4),
                   packed = littleEndian(zip, at + 20, 4), size = littleEndian(zip, at + 24, 4),
                   nameLength = littleEndian(zip, at + 28, 2), extra = littleEndian(zip, at + 30, 2),
                   comment = littleEndian(zip, at + 32, 2), local = littleEndian(zip, at + 42, 4);
    EXPECT_EQ(method, 0u) << "stored";
    EXPECT_EQ(time, 0u);
    EXPECT_EQ(date, (1u << 5) | 1u) << "1980-01-01";
    EXPECT_EQ(packed, size);
    EXPECT_EQ(extra + comment, 0u);
    EXPECT_EQ(local, expectedLocal) << "entries follow each other";
    const std::string name(zip.begin() + static_cast<long>(at + 46), zip.begin() + static_cast<long>(at + 46 + nameLength));
    // The local header repeats the same fields (from "version needed" to "extra length").
    EXPECT_EQ(littleEndian(zip, local, 4), 0x04034b50u) << name;
    for (int field = 0; field < 26; ++field) {
      EXPECT_EQ(zip.at(local + 4 + field), zip.at(at + 6 + field)) << name << " field byte " << field;
    }
    at += 46 + nameLength;
    const size_t data = local + 30 + nameLength;
    EXPECT_EQ(std::string(zip.begin() + static_cast<long>(local + 30), zip.begin() + static_cast<long>(data)), name);
    ZipFile file{name, std::string(zip.begin() + static_cast<long>(data), zip.begin() + static_cast<long>(data + size))};
    EXPECT_EQ(bitwiseCrc32(file.data), crc) << name;
    expectedLocal = data + size;
    files.push_back(std::move(file));
  }
  EXPECT_EQ(expectedLocal, directoryOffset) << "the central directory follows the last entry";
  return files;
}

// The triangles of a binary STL as they are (no merged vertices), after checking its size.
std::vector<std::array<Vec, 3>> stlTriangles(const std::string& stl) {
  EXPECT_GE(stl.size(), 84u);
  uint32_t count = 0;
  std::memcpy(&count, stl.data() + 80, 4);
  EXPECT_EQ(stl.size(), 84u + 50u * count);
  std::vector<std::array<Vec, 3>> triangles(count);
  for (uint32_t t = 0; t < count; ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      for (int axis = 0; axis < 3; ++axis) {
        float value = 0;
        std::memcpy(&value, stl.data() + 84 + 50 * t + 12 * (corner + 1) + 4 * axis, 4);
        triangles[t][corner][axis] = value;
      }
    }
  }
  return triangles;
}

double signedVolume(const std::vector<std::array<Vec, 3>>& triangles) {
  double volume = 0;
  for (const auto& [a, b, c] : triangles) {
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6;
}

template <typename Operation>
std::string errorOf(Operation&& operation) {
  try {
    operation();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput) << e.what();
    return e.what();
  }
  return "";
}

// ---- the inset surfaces ------------------------------------------------------------------------------

TEST(PrintExport, FacesAgainstOtherPartsMoveInByTheClearanceAndOuterFacesStay) {
  for (const std::string& file : kPuzzles) {
    const VoxelGrid& grid = loadReference(file).voxels;
    for (int id = 1; id <= grid.maxLabel(); ++id) {
      const TriangleMesh mesh = insetPartSurfaceMesh(grid, id, kVoxel, kClearance);
      ASSERT_EQ(manifoldProblem(mesh), "") << file << " part " << id;
      const FacesByPlane faces(mesh);
      // Every voxel face of the part: its centre is on the surface when it faces empty space; when
      // it faces another part it is not, and the centre moved in by the clearance is.
      int inner = 0;
      for (int64_t i = 0; i < grid.voxelCount(); ++i) {
        if (grid.labelAt(i) != id) continue;
        const Int3 c = grid.coordinates(i);
        const int cell[3] = {c.x, c.y, c.z};
        for (int axis = 0; axis < 3; ++axis) {
          for (int sign : {-1, 1}) {
            int n[3] = {c.x, c.y, c.z};
            n[axis] += sign;
            const int beyond = labelOrEmpty(grid, n[0], n[1], n[2]);
            if (beyond == id) continue;
            Vec centre;
            for (int k = 0; k < 3; ++k) centre[k] = (cell[k] + 0.5) * kVoxel;
            centre[axis] = (cell[axis] + (sign > 0 ? 1 : 0)) * kVoxel;
            if (beyond == 0) {
              EXPECT_TRUE(faces.covers(axis, sign, centre)) << file << " part " << id << " outer face moved";
              continue;
            }
            ++inner;
            EXPECT_FALSE(faces.covers(axis, sign, centre)) << file << " part " << id << " inner face stayed";
            Vec moved = centre;
            moved[axis] -= sign * kClearance;
            EXPECT_TRUE(faces.covers(axis, sign, moved)) << file << " part " << id << " inner face not inset";
          }
        }
      }
      EXPECT_GT(inner, 0) << file << " part " << id;
      // The inset part lies inside its voxels: just inside each triangle is a voxel of the part.
      for (const auto& t : mesh.triangles) {
        const FlatTriangle flat = flatTriangle(mesh, t);
        Vec inside{0, 0, 0};
        for (const Vec& corner : flat.corners) {
          for (int k = 0; k < 3; ++k) inside[k] += corner[k] / 3;
        }
        inside[flat.axis] -= flat.sign * 1e-6;
        const int x = static_cast<int>(std::floor(inside[0] / kVoxel)), y = static_cast<int>(std::floor(inside[1] / kVoxel)),
                  z = static_cast<int>(std::floor(inside[2] / kVoxel));
        ASSERT_EQ(labelOrEmpty(grid, x, y, z), id) << file << " part " << id << " grew out of its voxels";
      }
    }
  }
}

TEST(PrintExport, ExactVolumesOfAStepAConcaveEdgeAndAConcaveCorner) {
  struct Case {
    const char* what;
    std::vector<std::vector<std::string>> layers;
    std::vector<double> volumes;  // per part, worked out by hand for s = 10, c = 0.2
  };
  const std::vector<Case> cases = {
      // Part 1's top is inset over its first voxel (part 2 above) and stays over the second (empty
      // above): a step of height c between them. Part 1 loses a 10 x 10 x 0.2 slab, part 2 its bottom.
      {"step", {{"1 1", "2 0"}}, {2000 - 20, 1000 - 20}},
      // Part 1 is an L around part 2: both inset faces of the concave edge move in, and so does the
      // edge between them (10 x 0.2 x 0.2 more). Part 2 loses two slabs that share a corner strip.
      {"concave edge", {{"1 1", "1 2"}}, {3000 - 20 - 20 - 0.4, 10 * 9.8 * 9.8}},
      // Part 2 in a corner of part 1 (7 voxels): part 1 loses the cube [9.8, 20]^3 minus part 2's
      // voxel; part 2 shrinks by c on its three inner sides.
      {"concave corner", {{"1 1", "1 1"}, {"1 1", "1 2"}}, {7000 - (10.2 * 10.2 * 10.2 - 1000), 9.8 * 9.8 * 9.8}},
  };
  for (const Case& c : cases) {
    const VoxelGrid grid = gridFromLayers(c.layers);
    double total = 0;
    for (int id = 1; id <= 2; ++id) {
      const TriangleMesh mesh = insetPartSurfaceMesh(grid, id, kVoxel, kClearance);
      EXPECT_EQ(manifoldProblem(mesh), "") << c.what << " part " << id;
      EXPECT_NEAR(enclosedVolume(mesh), c.volumes[id - 1], 1e-8) << c.what << " part " << id;
      total += enclosedVolume(mesh);
    }
    EXPECT_LT(total, 1000.0 * grid.labelCounts()[1] + 1000.0 * grid.labelCounts()[2]) << c.what;
  }
}

TEST(PrintExport, NoClearanceIsThePlainSurfaceAndTheSameBytes) {
  const AssemblyDocument k9 = loadReference("result_puz/Cube_4x4x4_K9.puz");
  for (int id = 1; id <= 9; ++id) {
    const TriangleMesh plain = partSurfaceMesh(k9.voxels, id, kVoxel);
    const TriangleMesh inset = insetPartSurfaceMesh(k9.voxels, id, kVoxel, 0.0);
    EXPECT_EQ(inset.vertices, plain.vertices);
    EXPECT_EQ(inset.triangles, plain.triangles);
  }
  ExportOptions options;
  options.voxelSize = kVoxel;
  const std::vector<uint8_t> before = exportAssembly(k9, ExportFormat::StlBinary, options);
  options.clearance = 0.0;
  EXPECT_EQ(exportAssembly(k9, ExportFormat::StlBinary, options), before);
  options.clearance = kClearance;
  const std::vector<uint8_t> inset = exportAssembly(k9, ExportFormat::StlBinary, options);
  EXPECT_NE(inset, before);
  EXPECT_EQ(std::string(inset.begin(), inset.begin() + 61),
            "desia voxel export, all 9 parts, voxel size 10, clearance 0.2");
  // Each format's triangles are the inset surfaces', in part order.
  size_t triangles = 0;
  for (int id = 1; id <= 9; ++id) triangles += insetPartSurfaceMesh(k9.voxels, id, kVoxel, kClearance).triangles.size();
  EXPECT_EQ(stlTriangles(std::string(inset.begin(), inset.end())).size(), triangles);
}

TEST(PrintExport, ClearanceOfHalfAVoxelOrMoreIsRefusedNamingTheValue) {
  const AssemblyDocument k9 = loadReference("result_puz/Cube_4x4x4_K9.puz");
  auto exportWith = [&](ExportFormat format, double voxelSize, double clearance) {
    ExportOptions options;
    options.voxelSize = voxelSize;
    options.clearance = clearance;
    options.source = "k9.puz";
    return [&k9, format, options] { exportAssembly(k9, format, options); };
  };
  EXPECT_EQ(errorOf(exportWith(ExportFormat::StlZip, 10, 5)),
            "k9.puz: the clearance must be at least 0 and less than half the voxel size (5), got 5");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::BuildPlateStl, 1, 0.6)),
            "k9.puz: the clearance must be at least 0 and less than half the voxel size (0.5), got 0.6");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::StlBinary, 10, -0.1)),
            "k9.puz: the clearance must be at least 0 and less than half the voxel size (5), got -0.1");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::Obj, 10, std::nan(""))),
            "k9.puz: the clearance must be at least 0 and less than half the voxel size (5), got nan");
  EXPECT_EQ(errorOf(exportWith(ExportFormat::XmPuzzle, 10, 0.2)),
            "k9.puz: a BurrTools .xmpuzzle holds voxels, not meshes: the clearance applies to stl, stl-ascii, obj, "
            "stl-zip and build-plate-stl");
  EXPECT_EQ(errorOf([&] { insetPartSurfaceMesh(k9.voxels, 1, 1, 0.5); }),
            "the clearance must be at least 0 and less than half the voxel size (0.5), got 0.5");
  ExportOptions spaced;
  spaced.spacing = 3;
  spaced.source = "k9.puz";
  EXPECT_EQ(errorOf([&] { exportAssembly(k9, ExportFormat::StlZip, spaced); }),
            "k9.puz: the spacing sets the gaps of a build plate (build-plate-stl), not of stl-zip");
  spaced.spacing = -1;
  EXPECT_EQ(errorOf([&] { exportAssembly(k9, ExportFormat::BuildPlateStl, spaced); }),
            "k9.puz: the spacing must be a number from 0 to 1000000, got -1");
  EXPECT_EQ(parseExportFormat("stl-zip"), ExportFormat::StlZip);
  EXPECT_STREQ(exportFormatName(parseExportFormat("build-plate-stl")), "build-plate-stl");
}

// ---- the ZIP of one STL per part --------------------------------------------------------------------

TEST(PrintExport, StlZipHoldsOneClosedStlPerPartWithItsInsetVolume) {
  for (const std::string& file : {std::string("result_puz/Cube_4x4x4_K9.puz"), std::string("result_puz/bunny_15x14x11_K80.puz")}) {
    const AssemblyDocument document = loadReference(file);
    ExportOptions options;
    options.voxelSize = kVoxel;
    options.clearance = kClearance;
    const std::vector<uint8_t> zip = exportAssembly(document, ExportFormat::StlZip, options);
    EXPECT_EQ(exportAssembly(document, ExportFormat::StlZip, options), zip) << "the same bytes again";
    const std::vector<ZipFile> files = readZip(zip);
    const int parts = document.voxels.maxLabel();
    ASSERT_EQ(static_cast<int>(files.size()), parts) << file;
    for (int id = 1; id <= parts; ++id) {
      const ZipFile& stl = files[id - 1];
      EXPECT_EQ(stl.name, std::string("part-") + (id < 10 ? "0" : "") + std::to_string(id) + ".stl");
      const std::string title =
          "desia part " + std::to_string(id) + " of " + std::to_string(parts) + ", voxel size 10, clearance 0.2";
      EXPECT_EQ(stl.data.substr(0, 80), title + std::string(80 - title.size(), ' ')) << file;
      // Closed as an STL (the core's own reader: edges in two triangles, or four where the solid
      // pinches), with the inset part's volume (float coordinates), turned to lie on z = 0 at the
      // origin (the box's low corner).
      const TriangleMesh merged = parseStl(stl.data, stl.name);
      EXPECT_NO_THROW(checkClosedMesh(merged, stl.name));
      const TriangleMesh inset = insetPartSurfaceMesh(document.voxels, id, kVoxel, kClearance);
      EXPECT_NEAR(signedVolume(stlTriangles(stl.data)), enclosedVolume(inset), 1e-6 * enclosedVolume(inset)) << stl.name;
      Vec low = merged.vertices[0];
      for (const Vec& v : merged.vertices) {
        for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], v[k]);
      }
      EXPECT_EQ(low, (Vec{0, 0, 0})) << stl.name;
      EXPECT_LT(enclosedVolume(inset), document.voxels.labelCounts()[id] * 1000.0) << stl.name;
    }
  }
  // One part: a ZIP with that part only.
  ExportOptions one;
  one.part = 3;
  const std::vector<ZipFile> single = readZip(exportAssembly(loadReference("result_puz/Cube_4x4x4_K9.puz"), ExportFormat::StlZip, one));
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].name, "part-03.stl");
}

TEST(PrintExport, ZipWriterStoresAnyFilesAndAnEmptyArchive) {
  EXPECT_EQ(readZip(zipStored({})).size(), 0u);
  EXPECT_EQ(zipStored({}), std::vector<uint8_t>({0x50, 0x4b, 0x05, 0x06, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  const std::vector<ZipFile> files = readZip(zipStored({{"a.txt", "hello"}, {"empty", ""}, {"b/c.bin", std::string(70000, '\x7f')}}));
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].name, "a.txt");
  EXPECT_EQ(files[0].data, "hello");
  EXPECT_EQ(bitwiseCrc32("hello"), 0x3610a686u);
  EXPECT_EQ(files[1].data, "");
  EXPECT_EQ(files[2].data, std::string(70000, '\x7f'));
}

// ---- the build plate ---------------------------------------------------------------------------------

TEST(PrintExport, BuildPlatePartsLieFlatOnZeroApartWithTheirVolumes) {
  for (const std::string& file : kPuzzles) {
    const AssemblyDocument document = loadReference(file);
    const VoxelGrid& grid = document.voxels;
    const int parts = grid.maxLabel();
    ExportOptions options;
    options.voxelSize = kVoxel;
    options.clearance = kClearance;
    options.spacing = 4.0;
    const std::vector<uint8_t> bytes = exportAssembly(document, ExportFormat::BuildPlateStl, options);
    const std::vector<std::array<Vec, 3>> triangles = stlTriangles(std::string(bytes.begin(), bytes.end()));
    // The parts follow each other in id order, each with its inset surface's triangles.
    size_t next = 0;
    std::vector<std::array<Vec, 2>> boxes;
    for (int id = 1; id <= parts; ++id) {
      const TriangleMesh inset = insetPartSurfaceMesh(grid, id, kVoxel, kClearance);
      ASSERT_LE(next + inset.triangles.size(), triangles.size()) << file;
      const std::vector<std::array<Vec, 3>> part(triangles.begin() + static_cast<long>(next),
                                                 triangles.begin() + static_cast<long>(next + inset.triangles.size()));
      next += inset.triangles.size();
      // Float coordinates up to a plate's width: a relative tolerance.
      EXPECT_NEAR(signedVolume(part), enclosedVolume(inset), 1e-5 * enclosedVolume(inset))
          << file << " part " << id << ": turned, not mirrored";
      std::array<Vec, 2> box{part[0][0], part[0][0]};
      double onPlate = 0;
      for (const auto& t : part) {
        for (const Vec& v : t) {
          for (int k = 0; k < 3; ++k) box[0][k] = std::min(box[0][k], v[k]), box[1][k] = std::max(box[1][k], v[k]);
        }
        const bool flatOnZero = t[0][2] == 0 && t[1][2] == 0 && t[2][2] == 0;
        if (flatOnZero) onPlate += std::fabs((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0])) / 2;
      }
      EXPECT_EQ(box[0][2], 0.0) << file << " part " << id << " rests on z = 0";
      EXPECT_GT(onPlate, 0.0) << file << " part " << id;
      boxes.push_back(box);
    }
    EXPECT_EQ(next, triangles.size()) << file;
    // No two boxes overlap: they are at least the spacing apart along x or y.
    for (size_t a = 0; a < boxes.size(); ++a) {
      for (size_t b = a + 1; b < boxes.size(); ++b) {
        const double gapX = std::max(boxes[b][0][0] - boxes[a][1][0], boxes[a][0][0] - boxes[b][1][0]);
        const double gapY = std::max(boxes[b][0][1] - boxes[a][1][1], boxes[a][0][1] - boxes[b][1][1]);
        EXPECT_GE(std::max(gapX, gapY), 4.0 - 1e-3) << file << " parts " << a + 1 << " and " << b + 1;
      }
    }
  }
}

TEST(PrintExport, BuildPlateTurnsEachPartOntoItsLargestLayer) {
  // Part 1 is a 3 x 1 x 2 slab standing on its narrow side in the grid (x by z, one voxel deep in
  // y); part 2 a single voxel. On the plate part 1 must lie on a 3 x 2 side: 6 voxels on z = 0,
  // one voxel high.
  const VoxelGrid grid = gridFromLayers({{"1 1 1"}, {"1 1 1"}, {"2 0 0"}});
  const AssemblyDocument document = documentFromVoxels(grid);
  ExportOptions options;
  options.spacing = 0.5;
  const std::vector<uint8_t> bytes = exportAssembly(document, ExportFormat::BuildPlateStl, options);
  const std::vector<std::array<Vec, 3>> triangles = stlTriangles(std::string(bytes.begin(), bytes.end()));
  const size_t first = partSurfaceMesh(grid, 1, 1.0).triangles.size();
  double top = 0, bottomArea = 0;
  for (size_t t = 0; t < first; ++t) {
    for (const Vec& v : triangles[t]) top = std::max(top, v[2]);
    const auto& tri = triangles[t];
    if (tri[0][2] == 0 && tri[1][2] == 0 && tri[2][2] == 0) {
      bottomArea += std::fabs((tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[1][1] - tri[0][1]) * (tri[2][0] - tri[0][0])) / 2;
    }
  }
  EXPECT_EQ(top, 1.0);
  EXPECT_EQ(bottomArea, 6.0);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 57), "desia build plate, all 2 parts, voxel size 1, spacing 0.5");
}

}  // namespace
}  // namespace desia
