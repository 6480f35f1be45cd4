// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh assemblies on a lattice (issue 29): the 44 BurrTools puzzles of tests/data/burrtools, exported
// as meshes, also turned at random and in inches, get the voxel kind's verdict and, where the voxel
// kind has one, a complete plan of the same level; plans of parts moved together are replayed by an
// independent check (winding numbers of sampled points, mesh_test_support.h), which a wrong plan
// fails. The parts read as voxels are the puzzle's own; a model off any lattice is not read so.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/mesh.h"
#include "mesh/mesh_lattice.h"
#include "mesh_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::bothTests;
using testing::exported;
using testing::meshesOf;
using testing::projectPath;
using testing::randomRotation;
using testing::readDocument;
using testing::readFileText;
using testing::replayFailure;
using testing::replayMovesFailure;
using testing::transformedObj;

std::vector<std::string> burrToolsPuzzles() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(projectPath("tests/data/burrtools"))) {
    if (entry.path().extension() == ".puz") paths.push_back("tests/data/burrtools/" + entry.path().filename().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The mesh check agrees with the voxel kind's: verdict, key, a complete plan exactly when the
// voxel kind has one, and then its level.
void expectSameAsVoxels(const CheckReport& own, const CheckReport& mesh, const std::string& what) {
  EXPECT_EQ(mesh.result.verdict, own.result.verdict) << what;
  EXPECT_EQ(mesh.result.key, own.result.key) << what;
  ASSERT_TRUE(own.disassembly && mesh.disassembly) << what;
  EXPECT_EQ(mesh.disassembly->complete, own.disassembly->complete) << what;
  if (own.disassembly->complete && mesh.disassembly->complete && !own.disassembly->level.empty() &&
      !mesh.disassembly->level.empty()) {
    EXPECT_EQ(mesh.disassembly->level, own.disassembly->level) << what;
  }
  EXPECT_EQ(checkPassed(mesh), checkPassed(own)) << what;
}

TEST(MeshLattice, EveryBurrToolsPuzzleAsMeshesGetsTheVoxelKindsVerdictAndPlan) {
  std::mt19937 random(2929);
  int puzzles = 0, complete = 0, onLattice = 0;
  for (const std::string& path : burrToolsPuzzles()) {
    const AssemblyDocument document = readDocument(path);
    const CheckReport own = checkDocument(document, bothTests());
    const std::string obj = exported(document, "obj");
    const MeshAssembly meshes = meshesOf({{"puzzle.obj", obj}});
    const CheckReport mesh = checkMeshAssembly(meshes, bothTests());
    expectSameAsVoxels(own, mesh, path);
    ++puzzles;
    // Turned at random and written in inches: the same, from the frame the faces give.
    const MeshAssembly turned = meshesOf({{"turned.obj", transformedObj(obj, randomRotation(random), 25.4)}}, LengthUnit::Inch);
    const CheckReport turnedReport = checkMeshAssembly(turned, bothTests());
    expectSameAsVoxels(own, turnedReport, path + " turned, in inches");
    if (!mesh.disassembly->complete) continue;
    ++complete;
    onLattice += mesh.shapeRemoval->checked.find("planned by the complete voxel disassembler") != std::string::npos;
    // Plans of parts moved together are replayed turned and in inches below.
    if (mesh.disassembly->singlePartPaths) {
      EXPECT_EQ(replayFailure(meshes, *mesh.disassembly), "") << path;
    }
  }
  EXPECT_EQ(puzzles, 44);
  EXPECT_EQ(complete, 43);  // all but CubeInCage, which neither kind takes apart
  EXPECT_EQ(onLattice, 2);  // DraculasDentalDesaster and PelikanBurr, of levels 3.5.17.6.4 and 98.2.5
}

TEST(MeshLattice, PlansOfPartsMovedTogetherSurviveTheReplayTurnedAndInInches) {
  std::mt19937 random(7);
  for (const char* name : {"DraculasDentalDesaster-p0-s0", "PelikanBurr-p0-s0"}) {
    const AssemblyDocument document = readDocument(std::string("tests/data/burrtools/") + name + ".puz");
    const std::string obj = exported(document, "obj");
    const MeshAssembly turned = meshesOf({{"turned.obj", transformedObj(obj, randomRotation(random), 25.4)}}, LengthUnit::Inch);
    const CheckReport report = checkMeshAssembly(turned, bothTests());
    ASSERT_TRUE(report.disassembly && report.disassembly->complete) << name;
    EXPECT_FALSE(report.disassembly->singlePartPaths) << name;
    EXPECT_EQ(replayMovesFailure(turned, *report.disassembly), "") << name;
    ASSERT_TRUE(report.shapeRemoval);
    EXPECT_NE(report.shapeRemoval->checked.find("planned by the complete voxel disassembler"), std::string::npos);
  }
}

// The replay and the sweep are checks that can fail: PelikanBurr's first move sent the other way, or
// left out, runs parts into each other.
TEST(MeshLattice, TheReplayAndTheSweepCatchAWrongPlanOfPartsMovedTogether) {
  const AssemblyDocument document = readDocument("tests/data/burrtools/PelikanBurr-p0-s0.puz");
  const MeshAssembly meshes = meshesOf({{"pelikan.obj", exported(document, "obj")}});
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  ASSERT_TRUE(report.disassembly && report.disassembly->complete);
  EXPECT_EQ(report.disassembly->level, (std::vector<int>{98, 2, 5}));
  const std::vector<mesh::PartGeometry>& geometry = mesh::geometryOf(meshes);
  EXPECT_EQ(mesh::sweepPlan(meshes, geometry, *report.disassembly), "");
  DisassemblyPlan reversed = *report.disassembly;
  reversed.moves.front().direction = negated(reversed.moves.front().direction);
  EXPECT_NE(replayMovesFailure(meshes, reversed), "");
  EXPECT_NE(mesh::sweepPlan(meshes, geometry, reversed), "");
  DisassemblyPlan skipped = *report.disassembly;
  skipped.moves.erase(skipped.moves.begin());
  EXPECT_NE(replayMovesFailure(meshes, skipped), "");
  EXPECT_NE(mesh::sweepPlan(meshes, geometry, skipped), "");
}

// Read as voxels, each part has the volume it has in the puzzle: PelikanBurr on its 1 mm lattice
// (its exported surfaces have vertices at half cells, where voxels meet along an edge), and
// DraculasDentalDesaster on 2 mm cells (all its faces lie on even levels), turned and in inches.
TEST(MeshLattice, ThePartsReadAsVoxelsHaveThePuzzlesVolumes) {
  std::mt19937 random(11);
  for (const char* name : {"PelikanBurr-p0-s0", "DraculasDentalDesaster-p0-s0", "AlPackino-p0-s0"}) {
    const AssemblyDocument document = readDocument(std::string("tests/data/burrtools/") + name + ".puz");
    const std::vector<int64_t> voxels = document.voxels.labelCounts();
    const std::string obj = exported(document, "obj");
    for (const bool turn : {false, true}) {
      const MeshAssembly meshes = turn ? meshesOf({{"t.obj", transformedObj(obj, randomRotation(random), 25.4)}}, LengthUnit::Inch)
                                       : meshesOf({{"p.obj", obj}});
      const std::optional<mesh::MeshLattice> lattice = mesh::meshLattice(meshes);
      ASSERT_TRUE(lattice) << name;
      const double cell = lattice->pitch[0] * lattice->pitch[1] * lattice->pitch[2];
      const std::vector<int64_t> cells = lattice->grid.labelCounts();
      ASSERT_EQ(cells.size(), voxels.size()) << name;
      for (size_t label = 1; label < cells.size(); ++label) {
        EXPECT_NEAR(static_cast<double>(cells[label]) * cell, static_cast<double>(voxels[label]), 1e-6 * voxels[label])
            << name << " part " << label;
      }
    }
  }
}

std::string boxObj(const std::string& name, const Vec3& lo, const Vec3& size, int firstVertex) {
  std::string text = "o " + name + "\n";
  for (int k = 0; k < 8; ++k) {
    text += "v " + std::to_string(lo[0] + size[0] * (k & 1)) + ' ' + std::to_string(lo[1] + size[1] * ((k >> 1) & 1)) + ' ' +
            std::to_string(lo[2] + size[2] * ((k >> 2) & 1)) + "\n";
  }
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : faces) {
    text += "f " + std::to_string(firstVertex + q[0]) + ' ' + std::to_string(firstVertex + q[1]) + ' ' +
            std::to_string(firstVertex + q[2]) + ' ' + std::to_string(firstVertex + q[3]) + "\n";
  }
  return text;
}

// Boxes whose faces lie on levels of no common lattice (gaps of 10 and 3.7 mm), a part at a slant to
// the others, are not read as voxels; boxes of 10 and 15 mm are (5 mm cells).
TEST(MeshLattice, OnlyPartsOnOneLatticeAreReadAsVoxels) {
  const MeshAssembly offLattice = meshesOf({{"off.obj", boxObj("a", {0, 0, 0}, {10, 10, 10}, 1) +
                                                              boxObj("b", {3.7, 0, 10}, {10, 10, 10}, 9)}});
  EXPECT_FALSE(mesh::meshLattice(offLattice));
  std::mt19937 random(3);
  const std::string slanted = boxObj("a", {0, 0, 0}, {10, 10, 10}, 1) +
                              transformedObj(boxObj("b", {0, 0, 20}, {10, 10, 10}, 9), randomRotation(random), 1);
  EXPECT_FALSE(mesh::meshLattice(meshesOf({{"slanted.obj", slanted}})));
  const MeshAssembly onLattice = meshesOf({{"on.obj", boxObj("a", {0, 0, 0}, {10, 15, 10}, 1) +
                                                          boxObj("b", {0, 0, 10}, {15, 10, 5}, 9)}});
  const std::optional<mesh::MeshLattice> lattice = mesh::meshLattice(onLattice);
  ASSERT_TRUE(lattice);
  EXPECT_NEAR(lattice->pitch[0], 5, 1e-9);
  EXPECT_NEAR(lattice->pitch[2], 5, 1e-9);
  EXPECT_EQ(lattice->grid.labelCounts(), (std::vector<int64_t>{9, 12, 6}));  // 27 cells of 5 mm: 12 and 6 the boxes'
}

// The report of a plan with parts moved together: the level, each move with its length in mm.
TEST(MeshLattice, ReportsGiveTheLevelAndEachMovesLength) {
  const AssemblyDocument document = readDocument("tests/data/burrtools/PelikanBurr-p0-s0.puz");
  const MeshAssembly meshes = meshesOf({{"pelikan.obj", exported(document, "obj")}}, LengthUnit::Inch);
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  const std::string text = meshCheckReportToText(meshes, report);
  EXPECT_NE(text.find("disassembly: level 98.2.5, 108 moves"), std::string::npos) << text;
  EXPECT_NE(text.find("move 1: parts 4, 5  +y 25.4 mm"), std::string::npos) << text;
  const std::string json = meshCheckReportToJson(meshes, report, -1);
  EXPECT_NE(json.find(R"("length":25.4)"), std::string::npos);
  EXPECT_NE(json.find(R"("level":[98,2,5])"), std::string::npos);
}

}  // namespace
}  // namespace desia
