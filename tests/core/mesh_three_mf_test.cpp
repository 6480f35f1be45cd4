// SPDX-License-Identifier: GPL-3.0-or-later
// 3MF input of mesh assemblies (issue 29): files written by lib3mf (tests/data/meshes/NOTICE.md:
// deflated entries, objects of components, build items with transforms) read part by part; a
// voxel puzzle written as a 3MF in inches, each part its own object moved into place by its build
// item's transform, gets the verdict, key and plan of the same puzzle as OBJ; bad 3MF files are
// named with the file, the model part, the line and the element.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/mesh.h"
#include "desia/formats.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::projectPath;
using testing::readFileText;

const char* const kRelationships =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
  <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
)";

// A 3MF package of one model part (stored entries: desia's own ZIP writer).
std::string threeMf(const std::string& model) {
  const std::vector<uint8_t> zip = zipStored({{"_rels/.rels", kRelationships}, {"3D/3dmodel.model", model}});
  return std::string(zip.begin(), zip.end());
}

struct Extent {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

Extent extentOf(const TriangleMesh& mesh) {
  Extent e;
  for (const Vec3& v : mesh.vertices) {
    for (int i = 0; i < 3; ++i) e.lo[i] = std::min(e.lo[i], v[i]), e.hi[i] = std::max(e.hi[i], v[i]);
  }
  return e;
}

TEST(MeshThreeMf, FilesWrittenByLib3mfGiveOnePartPerBuildItemUnderItsTransforms) {
  const std::string wagon = "WagonWithWheels.3mf";
  const std::vector<MeshPart> parts = readMeshParts({{wagon, readFileText(projectPath("tests/data/meshes/" + wagon))}});
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "Wagon");   // the body and four wheels, components of one object
  EXPECT_EQ(parts[1].name, "Wheel 1");  // the spare wheel, turned upside down by its item
  // The model's objects: the body of 96 triangles, the wheel of 56 (its x from 0 to 40, z from 0 to 10).
  EXPECT_EQ(parts[0].mesh.triangles.size(), 96u + 4 * 56);
  EXPECT_EQ(parts[1].mesh.triangles.size(), 56u);
  // The spare wheel's item turns it half a turn about y and moves it: x' = 171.389 - x, z' = 10 - z.
  const Extent spare = extentOf(parts[1].mesh);
  EXPECT_NEAR(spare.lo[0], 131.389, 1e-4);
  EXPECT_NEAR(spare.hi[0], 171.389, 1e-4);
  EXPECT_NEAR(spare.lo[2], 0, 1e-4);
  EXPECT_NEAR(spare.hi[2], 10, 1e-4);
  // Two parts that do not touch: not interlocking, and each comes out.
  const MeshCheck check = checkMeshFiles({{wagon, readFileText(projectPath("tests/data/meshes/" + wagon))}},
                                         LengthUnit::Millimetre, {}, {});
  EXPECT_EQ(check.meshes.assembly.contacts.size(), 0u);
  EXPECT_EQ(check.report.result.verdict, Verdict::NotInterlocking);
  ASSERT_TRUE(check.report.disassembly);
  EXPECT_TRUE(check.report.disassembly->complete);
  const std::string group = "PartsForBoundingBox.3mf";
  const std::vector<MeshPart> grouped = readMeshParts({{group, readFileText(projectPath("tests/data/meshes/" + group))}});
  ASSERT_EQ(grouped.size(), 2u);
  EXPECT_EQ(grouped[0].name, "New Group 1");  // a pyramid (10 triangles) and a cylinder (88), turned
  EXPECT_EQ(grouped[0].mesh.triangles.size(), 98u);
  EXPECT_EQ(grouped[1].name, "Pyramid");
  EXPECT_NO_THROW(buildMeshAssembly(grouped));  // closed, outward, apart after their transforms
}

// K9 as a 3MF: each part an object whose vertices are in inches and shifted by (-1, -2, -3) mm,
// its build item's transform (a translation, in inches) putting it back: the OBJ's report.
TEST(MeshThreeMf, AVoxelPuzzleAsThreeMfInInchesGetsTheVerdictKeyAndPlanOfItsObj) {
  const AssemblyDocument document = parseAssemblyText(readFileText(projectPath("examples/voxel/Cube_4x4x4_K9.puz")), "k9.puz");
  ExportSettings settings;
  const std::string obj = exportFiles(document, exportFormatNamed("obj"), settings).front();
  const std::vector<MeshPart> parts = readMeshParts({{"k9.obj", obj}});
  std::ostringstream model;
  model << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"inch\" xml:lang=\"en-US\" "
           "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n<resources>\n";
  char number[64];
  const auto inches = [&](double mm) {
    std::snprintf(number, sizeof number, "%.17g", mm / 25.4);
    return std::string(number);
  };
  for (const MeshPart& part : parts) {
    model << "<object id=\"" << part.id << "\" name=\"" << part.name << "\" type=\"model\"><mesh><vertices>\n";
    for (const Vec3& v : part.mesh.vertices) {
      model << "<vertex x=\"" << inches(v[0] - 1) << "\" y=\"" << inches(v[1] - 2) << "\" z=\"" << inches(v[2] - 3) << "\"/>\n";
    }
    model << "</vertices><triangles>\n";
    for (const auto& t : part.mesh.triangles) model << "<triangle v1=\"" << t[0] << "\" v2=\"" << t[1] << "\" v3=\"" << t[2] << "\"/>\n";
    model << "</triangles></mesh></object>\n";
  }
  model << "</resources>\n<build>\n";
  for (const MeshPart& part : parts) {
    model << "<item objectid=\"" << part.id << "\" transform=\"1 0 0 0 1 0 0 0 1 " << inches(1) << ' ' << inches(2) << ' '
          << inches(3) << "\"/>\n";
  }
  model << "</build>\n</model>\n";
  CheckOptions options;
  options.method = CheckMethod::Both;
  const MeshCheck fromObj = checkMeshFiles({{"k9.obj", obj}}, LengthUnit::Millimetre, {}, options);
  // --unit m must not apply to the 3MF: its model says inches.
  const MeshCheck fromThreeMf = checkMeshFiles({{"k9.3mf", threeMf(model.str())}}, LengthUnit::Metre, {}, options);
  ASSERT_EQ(fromThreeMf.meshes.parts.size(), 9u);
  EXPECT_EQ(fromThreeMf.meshes.parts[3].name, fromObj.meshes.parts[3].name);
  EXPECT_NEAR(fromThreeMf.meshes.diagonal, fromObj.meshes.diagonal, 1e-9);
  EXPECT_EQ(fromThreeMf.meshes.assembly.contacts.size(), fromObj.meshes.assembly.contacts.size());
  EXPECT_EQ(fromThreeMf.report.result.verdict, Verdict::Interlocking);
  EXPECT_EQ(fromThreeMf.report.result.key, fromObj.report.result.key);
  ASSERT_TRUE(fromThreeMf.report.disassembly && fromThreeMf.report.disassembly->complete);
  ASSERT_EQ(fromThreeMf.report.disassembly->removals.size(), fromObj.report.disassembly->removals.size());
  for (size_t k = 0; k < fromObj.report.disassembly->removals.size(); ++k) {
    EXPECT_EQ(fromThreeMf.report.disassembly->removals[k].part, fromObj.report.disassembly->removals[k].part) << k;
  }
}

std::string errorOf(const std::string& bytes) {
  try {
    readMeshParts({{"bad.3mf", bytes}});
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string modelOf(const std::string& resources, const std::string& build, const std::string& unit = "millimeter") {
  return "<model unit=\"" + unit + "\">\n<resources>\n" + resources + "</resources>\n<build>\n" + build + "</build>\n</model>\n";
}

const char* const kTetrahedron =
    "<object id=\"1\" name=\"tet\"><mesh><vertices>\n"
    "<vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"1\" y=\"0\" z=\"0\"/><vertex x=\"0\" y=\"1\" z=\"0\"/><vertex x=\"0\" y=\"0\" z=\"1\"/>\n"
    "</vertices><triangles>\n"
    "<triangle v1=\"0\" v2=\"2\" v3=\"1\"/><triangle v1=\"0\" v2=\"1\" v3=\"3\"/><triangle v1=\"0\" v2=\"3\" v3=\"2\"/><triangle v1=\"1\" v2=\"2\" v3=\"3\"/>\n"
    "</triangles></mesh></object>\n";

TEST(MeshThreeMf, BadFilesAreNamedWithTheModelPartLineAndElement) {
  EXPECT_EQ(errorOf(threeMf(modelOf(kTetrahedron, "<item objectid=\"1\"/>"))), "");
  // A mirroring item turns the triangles so that they still face out (the part stays valid).
  const std::vector<MeshPart> mirrored =
      readMeshParts({{"m.3mf", threeMf(modelOf(kTetrahedron, "<item objectid=\"1\" transform=\"-1 0 0 0 1 0 0 0 1 0 0 0\"/>", "centimeter"))}});
  EXPECT_NO_THROW(buildMeshAssembly(mirrored));
  EXPECT_EQ(extentOf(mirrored[0].mesh).lo[0], -10);  // centimetres
  EXPECT_NE(errorOf("PK\x03\x04 not really").find("bad.3mf: not a ZIP archive"), std::string::npos);
  const std::vector<uint8_t> noModel = zipStored({{"a.txt", "x"}});
  EXPECT_NE(errorOf(std::string(noModel.begin(), noModel.end())).find("bad.3mf: the ZIP has no entry '3D/3dmodel.model'"), std::string::npos);
  std::string badY = kTetrahedron;
  badY.replace(badY.find("y=\"1\""), 5, "y=\"one\"");
  EXPECT_NE(errorOf(threeMf(modelOf(badY, "<item objectid=\"1\"/>"))).find("bad.3mf: 3D/3dmodel.model:4: <vertex>: y 'one' is not a finite number"),
            std::string::npos);
  std::string badIndex = kTetrahedron;
  badIndex.replace(badIndex.find("v3=\"1\""), 6, "v3=\"4\"");
  EXPECT_NE(errorOf(threeMf(modelOf(badIndex, "<item objectid=\"1\"/>"))).find(":6: <triangle>: v3 '4' is not an index from 0 to 3"),
            std::string::npos);
  EXPECT_NE(errorOf(threeMf(modelOf(kTetrahedron, "<item objectid=\"1\"/>", "furlong"))).find(":1: <model>: unknown unit 'furlong'"),
            std::string::npos);
  EXPECT_NE(errorOf(threeMf(modelOf(kTetrahedron, "<item objectid=\"7\"/>"))).find(":10: no object with id 7"), std::string::npos);
  EXPECT_NE(errorOf(threeMf(modelOf(kTetrahedron, ""))).find("has no <item>"), std::string::npos);
  EXPECT_NE(errorOf(threeMf(modelOf(kTetrahedron, "<item objectid=\"1\" transform=\"1 0 0\"/>"))).find("is not 12 finite numbers"),
            std::string::npos);
  // Components that refer to each other: a cycle, refused rather than followed for ever.
  const std::string cycle = "<object id=\"2\"><components><component objectid=\"3\"/></components></object>\n"
                            "<object id=\"3\"><components><component objectid=\"2\"/></components></object>\n";
  EXPECT_NE(errorOf(threeMf(modelOf(cycle, "<item objectid=\"2\"/>"))).find("components nest more than 32 deep"), std::string::npos);
  // Each object placing the next twice, 30 deep: 2^30 placements of no triangle, refused early.
  std::string doubling = "<object id=\"1\" name=\"empty\"></object>\n";
  for (int id = 2; id <= 31; ++id) {
    const std::string next = std::to_string(id - 1);
    doubling += "<object id=\"" + std::to_string(id) + "\"><components><component objectid=\"" + next +
                "\"/><component objectid=\"" + next + "\"/></components></object>\n";
  }
  try {
    readMeshParts({{"doubling.3mf", threeMf(modelOf(doubling, "<item objectid=\"31\"/>"))}});
    ADD_FAILURE() << "2^30 placements were read";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::TooLarge);
    EXPECT_NE(std::string(e.what()).find("place more than 1000000 objects"), std::string::npos) << e.what();
  }
  EXPECT_NE(errorOf(threeMf("<model>\n<resources><object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"0\"")).find(":2: <vertex> is never closed"),
            std::string::npos);
  // A damaged entry: one byte of the stored model changed, so its CRC-32 no longer matches.
  std::string damaged = threeMf(modelOf(kTetrahedron, "<item objectid=\"1\"/>"));
  damaged[damaged.find("tet")] = 'T';
  EXPECT_NE(errorOf(damaged).find("bad.3mf: 3D/3dmodel.model: the entry's CRC-32 does not match"), std::string::npos);
}

}  // namespace
}  // namespace desia
