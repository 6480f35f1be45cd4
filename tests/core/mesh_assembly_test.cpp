// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh assemblies (issue 29): results of the other kinds exported by desia's own exporters and read
// back as meshes must get the verdict, key and a complete plan their own kind gets, also rotated
// and in other units; every plan is replayed by a check of its own (parts moved in small steps,
// overlap tested by winding numbers of sampled points, not by the sweep); bad input is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <random>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/mesh.h"
#include "mesh_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::bothTests;
using testing::exported;
using testing::meshesOf;
using testing::randomRotation;
using testing::readDocument;
using testing::replayFailure;
using testing::transformedObj;

// --- Other kinds read back as meshes -------------------------------------------------------------

void expectSameAsOwnKind(const AssemblyDocument& document, const MeshAssembly& meshes, const std::string& what,
                         bool replay) {
  const CheckReport own = checkDocument(document, bothTests());
  const CheckReport mesh = checkMeshAssembly(meshes, bothTests());
  EXPECT_EQ(mesh.result.verdict, own.result.verdict) << what;
  EXPECT_EQ(mesh.result.key, own.result.key) << what;
  ASSERT_TRUE(own.disassembly && own.disassembly->complete) << what;
  ASSERT_TRUE(mesh.disassembly) << what;
  EXPECT_TRUE(mesh.disassembly->complete) << what;
  EXPECT_TRUE(checkPassed(mesh) == checkPassed(own)) << what;
  if (replay && mesh.disassembly->complete && mesh.disassembly->singlePartPaths) {
    EXPECT_EQ(replayFailure(meshes, *mesh.disassembly), "") << what;
  }
}

const char* const kVoxelExamples[] = {"Cube_4x4x4_K9",      "Cube_4x4x4_K9_01", "Cube_4x4x4_origin",
                                      "Cube_5x5x5_origin",  "Cube_Hollow_4x4x4_K7", "Cube_hollow_4x4x4_origin",
                                      "bunny_15x14x11_K80", "bunny_origin",     "cartoon_dog",
                                      "cube_5x5x5_K16",     "dog_origin"};

TEST(MeshAssembly, EveryVoxelExampleAsObjGetsItsOwnVerdictKeyAndAPlan) {
  for (const char* name : kVoxelExamples) {
    const std::string path = std::string("examples/voxel/") + name + ".puz";
    const AssemblyDocument document = readDocument(path);
    const MeshAssembly meshes = meshesOf({{std::string(name) + ".obj", exported(document, "obj")}});
    EXPECT_EQ(meshes.parts.size(), document.assembly.parts.size()) << name;
    expectSameAsOwnKind(document, meshes, name, false);
  }
}

// BurrTools puzzles, of every level: tests/core/mesh_lattice_test.cpp.

TEST(MeshAssembly, PlansOfVoxelPuzzlesSurviveAnIndependentReplay) {
  for (const char* name : {"Cube_4x4x4_K9", "Cube_Hollow_4x4x4_K7", "Cube_4x4x4_origin"}) {
    const AssemblyDocument document = readDocument(std::string("examples/voxel/") + name + ".puz");
    const MeshAssembly meshes = meshesOf({{std::string(name) + ".obj", exported(document, "obj")}});
    expectSameAsOwnKind(document, meshes, name, true);
  }
}

// The replay is a check that can fail: the key sent the wrong way, or a part sent out first along
// the way its contacts close, runs into its neighbours.
TEST(MeshAssembly, TheIndependentReplayCatchesAWrongPlan) {
  const AssemblyDocument document = readDocument("examples/voxel/Cube_4x4x4_K9.puz");
  const MeshAssembly meshes = meshesOf({{"k9.obj", exported(document, "obj")}});
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  ASSERT_TRUE(report.disassembly && report.disassembly->complete);
  DisassemblyPlan reversed = *report.disassembly;
  ASSERT_EQ(reversed.removals.front().path.size(), 1u);
  reversed.removals.front().path.front().direction = negated(reversed.removals.front().path.front().direction);
  EXPECT_NE(replayFailure(meshes, reversed), "");
  DisassemblyPlan reordered = *report.disassembly;
  std::swap(reordered.removals[0], reordered.removals[1]);  // part 2 before the key
  EXPECT_NE(replayFailure(meshes, reordered), "");
  EXPECT_NE(meshSweepObstacle(meshes, {reordered.removals[0].part}, std::vector<bool>(9, true),
                              reordered.removals[0].path.back().direction),
            "");
}

TEST(MeshAssembly, PlateDesignsAndFrameResultsAsObjGetTheirOwnVerdictAndAPlan) {
  for (const char* path : {"examples/plate/table.json", "examples/plate/cube.json", "examples/plate/icosahedron.json",
                           "examples/plate/bookshelf.json", "examples/frame/frame_cube_result.json",
                           "examples/frame/frame_chair_result.json", "examples/frame/flower_result.json"}) {
    const AssemblyDocument document = readDocument(path);
    const MeshAssembly meshes = meshesOf({{"exported.obj", exported(document, "obj")}});
    expectSameAsOwnKind(document, meshes, path, std::string(path).find("frame_cube") != std::string::npos ||
                                                    std::string(path).find("table") != std::string::npos);
  }
}

// Plate results with their joints cut or milled into the plates (the golden corpus's designs of the
// examples): interlocking with the designer's key, and a plan through tenons, dovetails and mitre
// slides, some along diagonals.
TEST(MeshAssembly, JointedPlateResultsAsObjGetTheirOwnVerdictKeyAndAPlan) {
  for (const char* name : {"bench_2_bays-cut-s1", "table-cut-s1", "table_divider-cut-s1", "cube-milled-s1",
                           "mitred_box-milled-s1", "bookshelf-milled-s1", "cabinet-milled-s1",
                           "chair_repaired-milled-s1"}) {
    const AssemblyDocument document = readDocument(std::string("tests/golden/cases/plate/") + name + "/result.json");
    const MeshAssembly meshes = meshesOf({{"result.obj", exported(document, "obj")}});
    expectSameAsOwnKind(document, meshes, name, std::string(name) == "table-cut-s1" || std::string(name) == "cube-milled-s1");
    EXPECT_EQ(checkMeshAssembly(meshes, bothTests()).result.verdict, Verdict::Interlocking) << name;
  }
}

TEST(MeshAssembly, RotatedAndInOtherUnitsTheVerdictKeyAndPlanStay) {
  std::mt19937 random(29);
  const struct {
    LengthUnit unit;
    double mm;
  } units[] = {{LengthUnit::Millimetre, 1}, {LengthUnit::Metre, 1000}, {LengthUnit::Inch, 25.4}};
  for (const char* path : {"examples/voxel/Cube_4x4x4_K9.puz", "examples/voxel/Cube_Hollow_4x4x4_K7.puz",
                           "examples/voxel/Cube_4x4x4_origin.puz", "examples/frame/frame_cube_result.json",
                           "tests/golden/cases/plate/cube-milled-s1/result.json",
                           "tests/golden/cases/plate/table-cut-s1/result.json"}) {
    const AssemblyDocument document = readDocument(path);
    const std::string obj = exported(document, "obj");
    for (const auto& unit : units) {
      const std::array<Vec3, 3> rotation = randomRotation(random);
      const MeshAssembly meshes = meshesOf({{"rotated.obj", transformedObj(obj, rotation, unit.mm)}}, unit.unit);
      expectSameAsOwnKind(document, meshes, std::string(path) + " in unit " + std::to_string(unit.mm),
                          std::string(path).find("K9") != std::string::npos);
    }
  }
}

TEST(MeshAssembly, PartsFromSeveralStlFilesAndFromOneAsciiStlOfSeveralSolids) {
  const AssemblyDocument document = readDocument("examples/voxel/Cube_4x4x4_K9.puz");
  std::vector<MeshFile> binaries;
  std::string solids;
  for (int part = 1; part <= document.assembly.partCount(); ++part) {
    binaries.push_back({"part" + std::to_string(part) + ".stl", exported(document, "stl", part)});
    solids += exported(document, "stl-ascii", part);
  }
  const MeshAssembly fromBinaries = meshesOf(binaries);
  ASSERT_EQ(fromBinaries.parts.size(), 9u);
  EXPECT_EQ(fromBinaries.parts[3].name, "part4");
  expectSameAsOwnKind(document, fromBinaries, "binary STL files", false);
  const MeshAssembly fromSolids = meshesOf({{"all.stl", solids}});
  ASSERT_EQ(fromSolids.parts.size(), 9u);
  expectSameAsOwnKind(document, fromSolids, "one ASCII STL, one solid per part", false);
}

// Part 1 in an S-shaped channel through part 2: out only by three moves, +x 1, +y 1, then +x.
TEST(MeshAssembly, AThreeMovePathOutOfAnSChannel) {
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers(testing::sChannelLayers()));
  const MeshAssembly meshes = meshesOf({{"channel.obj", exported(document, "obj")}});
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  ASSERT_TRUE(report.disassembly && report.disassembly->complete);
  const Removal& first = report.disassembly->removals.front();
  EXPECT_EQ(first.part, 0);
  ASSERT_EQ(first.path.size(), 3u);
  EXPECT_EQ(first.path[0].direction, (Vec3{1, 0, 0}));
  EXPECT_NEAR(first.path[0].length, 1, 1e-9);
  EXPECT_EQ(first.path[1].direction, (Vec3{0, 1, 0}));
  EXPECT_NEAR(first.path[1].length, 1, 1e-9);
  EXPECT_EQ(first.path[2].direction, (Vec3{1, 0, 0}));
  EXPECT_EQ(replayFailure(meshes, *report.disassembly), "");
}

// Two cages, each around a voxel of its own: no part can move alone, but either cage leaves the other
// with its prisoner (a group: what the first cage's prisoner drags along +x). Then each pair is
// stuck, as in voxels.
TEST(MeshAssembly, GroupsMoveTogetherWhereNoSinglePartCan) {
  const std::vector<std::string> outer{"1 1 1 3 3 3", "1 1 1 3 3 3", "1 1 1 3 3 3"};
  const VoxelGrid grid = testing::gridFromLayers({outer, {"1 1 1 3 3 3", "1 2 1 3 4 3", "1 1 1 3 3 3"}, outer});
  const AssemblyDocument document = documentFromVoxels(grid);
  const MeshAssembly meshes = meshesOf({{"cages.obj", exported(document, "obj")}});
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  EXPECT_EQ(report.result.verdict, checkDocument(document, bothTests()).result.verdict);
  ASSERT_TRUE(report.disassembly);
  const DisassemblyPlan& plan = *report.disassembly;
  EXPECT_FALSE(plan.complete);
  EXPECT_FALSE(plan.singlePartPaths);
  ASSERT_EQ(plan.moves.size(), 1u);
  EXPECT_EQ(plan.moves[0].parts, (std::vector<int>{2, 3}));
  EXPECT_EQ(plan.moves[0].direction, (Vec3{1, 0, 0}));
  EXPECT_TRUE(plan.moves[0].out);
  EXPECT_EQ(plan.unseparated, (std::vector<std::vector<int>>{{0, 1}, {2, 3}}));
  const std::string json = meshCheckReportToJson(meshes, report, -1);
  EXPECT_NE(json.find(R"("dir":"+x")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("kind":"mesh")"), std::string::npos);
}

// --- Curved contacts -------------------------------------------------------------------------------

// A tube (outer radius 10, hole of radius 5, 10 high) and a pin through its hole (radius 5, from -5
// to 15), both prisms of `sides` sides: the pin's sides lie on the hole's.
std::string pinInHoleObj(int sides) {
  std::ostringstream out;
  const auto ring = [&](double radius, double z) {
    for (int k = 0; k < sides; ++k) {
      const double angle = 2 * M_PI * k / sides;
      out << "v " << radius * std::cos(angle) << ' ' << radius * std::sin(angle) << ' ' << z << "\n";
    }
  };
  // Tube: outer bottom 1.., outer top, inner bottom, inner top (1-based OBJ indices).
  out << "o tube\n";
  ring(10, 0), ring(10, 10), ring(5, 0), ring(5, 10);
  const auto at = [&](int ringIndex, int k) { return ringIndex * sides + (k % sides) + 1; };
  for (int k = 0; k < sides; ++k) {
    out << "f " << at(0, k) << ' ' << at(0, k + 1) << ' ' << at(1, k + 1) << ' ' << at(1, k) << "\n";  // outer wall
    out << "f " << at(2, k) << ' ' << at(3, k) << ' ' << at(3, k + 1) << ' ' << at(2, k + 1) << "\n";  // the hole
    out << "f " << at(3, k) << ' ' << at(1, k) << ' ' << at(1, k + 1) << ' ' << at(3, k + 1) << "\n";  // top
    out << "f " << at(2, k) << ' ' << at(2, k + 1) << ' ' << at(0, k + 1) << ' ' << at(0, k) << "\n";  // bottom
  }
  out << "o pin\n";
  ring(5, -5), ring(5, 15);
  for (int k = 0; k < sides; ++k) {
    out << "f " << at(4, k) << ' ' << at(4, k + 1) << ' ' << at(5, k + 1) << ' ' << at(5, k) << "\n";
  }
  for (int k = 1; k + 1 < sides; ++k) {
    out << "f " << at(5, 0) << ' ' << at(5, k) << ' ' << at(5, k + 1) << "\n";
    out << "f " << at(4, 0) << ' ' << at(4, k + 1) << ' ' << at(4, k) << "\n";
  }
  return out.str();
}

// A round pin in a round hole touches along 24 facets: one curved contact region, noted in the text
// and the JSON; a square pin in a square hole has corners, no curved region; nor has a voxel puzzle.
TEST(MeshAssembly, ACurvedContactIsNotedAsApproximatedByItsFacets) {
  const MeshAssembly round = meshesOf({{"pin.obj", pinInHoleObj(24)}});
  ASSERT_EQ(round.parts.size(), 2u);
  EXPECT_EQ(round.assembly.contacts.size(), 24u);
  ASSERT_EQ(round.curvedContacts.size(), 1u);
  EXPECT_EQ(round.curvedContacts[0].a, 0);
  EXPECT_EQ(round.curvedContacts[0].b, 1);
  EXPECT_EQ(round.curvedContacts[0].facets, 24);
  const double side = 2 * 5 * std::sin(M_PI / 24);
  EXPECT_NEAR(round.curvedContacts[0].area, 24 * side * 10, 1e-3);  // the OBJ has 6 digits
  const CheckReport report = checkMeshAssembly(round, bothTests());
  EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking);  // the pin slides out along its axis
  ASSERT_TRUE(report.disassembly);
  EXPECT_TRUE(report.disassembly->complete);
  EXPECT_NE(meshCheckReportToText(round, report)
                .find("curved contacts, approximated by their planar facets: parts 1 and 2 (24 facets, "),
            std::string::npos);
  const std::string json = meshCheckReportToJson(round, report, -1);
  EXPECT_NE(json.find(R"("curvedContacts":[{"area":)"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("facets":24,"parts":[1,2]})"), std::string::npos) << json;
  const MeshAssembly square = meshesOf({{"square.obj", pinInHoleObj(4)}});
  EXPECT_EQ(square.assembly.contacts.size(), 4u);
  EXPECT_TRUE(square.curvedContacts.empty());
  const std::string squareText = meshCheckReportToText(square, checkMeshAssembly(square));
  EXPECT_EQ(squareText.find("curved"), std::string::npos);
  const MeshAssembly k9 = meshesOf({{"k9.obj", exported(readDocument("examples/voxel/Cube_4x4x4_K9.puz"), "obj")}});
  EXPECT_TRUE(k9.curvedContacts.empty());
}

// --- Bad input -------------------------------------------------------------------------------------

std::string cubeObj(const std::string& name, double x, double y, double z, double size, int firstVertex = 1,
                    bool dropLastFace = false, bool flipFirstFace = false) {
  std::ostringstream out;
  out << "o " << name << "\n";
  for (int k = 0; k < 8; ++k) {
    out << "v " << x + size * (k & 1) << ' ' << y + size * ((k >> 1) & 1) << ' ' << z + size * ((k >> 2) & 1) << "\n";
  }
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < (dropLastFace ? 5 : 6); ++f) {
    const int* q = faces[f];
    if (f == 0 && flipFirstFace) {
      out << "f " << firstVertex + q[0] << ' ' << firstVertex + q[1] << ' ' << firstVertex + q[2] << "\n";
      out << "f " << firstVertex + q[3] << ' ' << firstVertex + q[2] << ' ' << firstVertex + q[0] << "\n";
      continue;
    }
    out << "f " << firstVertex + q[0] << ' ' << firstVertex + q[1] << ' ' << firstVertex + q[2] << ' '
        << firstVertex + q[3] << "\n";
  }
  return out.str();
}

std::string errorOf(const std::vector<MeshFile>& files) {
  try {
    meshesOf(files);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    return e.what();
  }
  return "";
}

TEST(MeshAssembly, TwoStackedCubesTouchAlongOneFaceAndComeApart) {
  const MeshAssembly meshes = meshesOf({{"two.obj", cubeObj("low", 0, 0, 0, 10) + cubeObj("high", 0, 0, 10, 10, 9)}});
  ASSERT_EQ(meshes.assembly.contacts.size(), 1u);
  EXPECT_EQ(meshes.assembly.contacts[0].normal, (Vec3{0, 0, 1}));
  EXPECT_NEAR(meshes.assembly.contacts[0].area, 100, 1e-6);
  EXPECT_EQ(meshes.faceCount, 12);
  EXPECT_EQ(meshSweepObstacle(meshes, {0}, {true, true}, {0, 0, 1}), "part 2");
  EXPECT_EQ(meshSweepObstacle(meshes, {0}, {true, true}, {0, 0, -1}), "");
  EXPECT_EQ(meshSweepObstacle(meshes, {0}, {true, true}, {1, 0, 0}), "");  // sliding along the contact
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking);
  ASSERT_TRUE(report.disassembly);
  EXPECT_TRUE(report.disassembly->complete);
}

TEST(MeshAssembly, BadPartsAreNamedWithWhatIsWrong) {
  EXPECT_NE(errorOf({{"open.obj", cubeObj("box", 0, 0, 0, 10, 1, true)}}).find("part 1 ('box'): is not closed: the edge"),
            std::string::npos);
  EXPECT_NE(errorOf({{"flip.obj", cubeObj("box", 0, 0, 0, 10, 1, false, true)}}).find("is not consistently oriented"),
            std::string::npos);
  EXPECT_NE(errorOf({{"overlap.obj", cubeObj("a", 0, 0, 0, 10) + cubeObj("b", 5, 5, 5, 10, 9)}})
                .find("part 1 ('a'): overlaps part 2"),
            std::string::npos);
  // A box whose top corner is pulled through its bottom: closed and oriented, but it crosses itself.
  std::string pulled = cubeObj("pulled", 0, 0, 0, 10);
  pulled.replace(pulled.find("v 10 10 10"), 10, "v 5 5 -5");
  EXPECT_NE(errorOf({{"self.obj", pulled}}).find("part 1 ('pulled'): intersects itself"), std::string::npos);
  // Two boxes that overlap in one object are one part, their union (as a slicer takes them).
  std::string twoBoxes = cubeObj("twice", 0, 0, 0, 10) + cubeObj("x", 5, 5, 5, 10, 9);
  twoBoxes.erase(twoBoxes.find("o x\n"), 4);
  EXPECT_EQ(errorOf({{"union.obj", twoBoxes}}), "");
  EXPECT_NE(errorOf({{"nested.obj", cubeObj("outer", 0, 0, 0, 10) + cubeObj("inner", 3, 3, 3, 2, 9)}})
                .find("part 2 ('inner'): lies inside part 1"),
            std::string::npos);
  EXPECT_NE(errorOf({{"empty.stl", ""}}).find("empty.stl: the file is empty"), std::string::npos);
  EXPECT_NE(errorOf({{"short.obj", "o a\nv 0 0 0\nv 1 0\n"}}).find("short.obj:3"), std::string::npos);
  EXPECT_NE(errorOf({{"cut.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"}}).find("cut.stl:"),
            std::string::npos);
  // An ASCII STL of several solids: a fault in the second names the file's own line (13).
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  EXPECT_NE(errorOf({{"two.stl", "solid a\n" + facet + "endsolid a\nsolid b\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n"}})
                .find("two.stl:13: vertex has 2 coordinates"),
            std::string::npos);
  // Touching within the tolerance is a contact, not an overlap: 1e-6 of a 20 mm model.
  EXPECT_EQ(errorOf({{"close.obj", cubeObj("a", 0, 0, 0, 10) + cubeObj("b", 0, 0, 10 - 1e-6, 10, 9)}}), "");
  EXPECT_THROW(parseLengthUnit("furlong"), Error);
}

}  // namespace
}  // namespace desia
