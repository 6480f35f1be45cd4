// SPDX-License-Identifier: GPL-3.0-or-later
// Moves of several parts for mesh assemblies off any lattice (issue 29, mesh_group_search.cpp).
// BurrTools puzzles exported as OBJ are taken off their lattice without changing how they move:
// at each of the eight corners of the assembly's bounding box directions (the vertex farthest
// along (±1, ±1, ±1)) the vertex is pushed a quarter cell into its part. That vertex is the outer
// corner of one cell that no other part's cell touches (a cell sharing it would reach farther
// along that diagonal), and the triangles around it are that cell's outer faces (the exports'
// triangles span one cell): only material of that cell, near a corner no part is in contact
// with, is cut away, and a part that overlaps the cell at a whole-cell offset still overlaps what
// is left of it. The lattice reading must refuse the dented puzzle, and the search must take it
// apart with the level the voxel kind gives the puzzle itself, every plan replayed independently
// (winding numbers, mesh_test_support.h), turned at random and in inches.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <random>
#include <sstream>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/mesh.h"
#include "mesh/mesh_group_search.h"
#include "mesh/mesh_lattice.h"
#include "mesh_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::bothTests;
using testing::exported;
using testing::meshesOf;
using testing::randomRotation;
using testing::readDocument;
using testing::replayMovesFailure;
using testing::transformedObj;

// The OBJ with the vertex farthest along each of the eight diagonals (the first in the file where
// several are as far) moved `depth` back along it, in every record that has it.
std::string dentedObj(const std::string& obj, double depth) {
  std::vector<std::string> lines;
  std::vector<std::pair<size_t, Vec3>> vertices;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      Vec3 p{};
      std::istringstream(line.substr(2)) >> p[0] >> p[1] >> p[2];
      vertices.push_back({lines.size(), p});
    }
    lines.push_back(line);
  }
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 s{corner & 1 ? -1.0 : 1.0, corner & 2 ? -1.0 : 1.0, corner & 4 ? -1.0 : 1.0};
    Vec3 farthest = vertices.front().second;
    for (const auto& vertex : vertices) {
      if (dot(vertex.second, s) > dot(farthest, s)) farthest = vertex.second;
    }
    const Vec3 dented = minus(farthest, scaled(s, depth));
    char text[128];
    std::snprintf(text, sizeof text, "v %.17g %.17g %.17g", dented[0], dented[1], dented[2]);
    for (const auto& vertex : vertices) {
      if (vertex.second == farthest) lines[vertex.first] = text;
    }
  }
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

constexpr double kDentCells = 0.25;  // the exports' cells are 1 mm

std::string dentedPuzzle(const char* name) {
  return dentedObj(exported(readDocument(std::string("tests/data/burrtools/") + name + ".puz"), "obj"), kDentCells);
}

std::vector<int> voxelLevel(const char* name) {
  const CheckReport own = checkDocument(readDocument(std::string("tests/data/burrtools/") + name + ".puz"), bothTests());
  return own.disassembly ? own.disassembly->level : std::vector<int>{};
}

// The check of the dented puzzle (`meshes`): off the lattice, the verdict, key and contacts of
// the same puzzle undented (`straight`, on its lattice), and a plan of moves of several parts
// that survives the independent replay, of the level the lattice reading gives `straight`. That is
// the voxel kind's level when the frame is the puzzle's own; turned, its first number (the fewest
// moves to the first separation) is the voxel kind's, and the later ones may differ, in both
// readings alike: they depend on which of several equally small separations is taken first, and
// that on the order of the axes found in the turned frame.
void expectPlannedOffLattice(const MeshAssembly& meshes, const MeshAssembly& straight, const char* name,
                             bool ownFrame, bool replay, const std::string& what) {
  const AssemblyDocument document = readDocument(std::string("tests/data/burrtools/") + name + ".puz");
  const CheckReport own = checkDocument(document, bothTests());
  const CheckReport onLattice = checkMeshAssembly(straight, bothTests());
  ASSERT_TRUE(onLattice.disassembly && onLattice.disassembly->complete && own.disassembly) << what;
  ASSERT_FALSE(onLattice.disassembly->level.empty() || own.disassembly->level.empty()) << what;
  EXPECT_EQ(onLattice.disassembly->level.front(), own.disassembly->level.front()) << what;
  EXPECT_FALSE(mesh::meshLattice(meshes)) << what;
  EXPECT_TRUE(mesh::meshLattice(straight)) << what;
  EXPECT_EQ(meshes.assembly.contacts.size(), straight.assembly.contacts.size()) << what;
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  EXPECT_EQ(report.result.verdict, own.result.verdict) << what;
  EXPECT_EQ(report.result.key, own.result.key) << what;
  ASSERT_TRUE(report.disassembly && report.disassembly->complete) << what;
  EXPECT_FALSE(report.disassembly->singlePartPaths) << what;
  EXPECT_EQ(report.disassembly->level, onLattice.disassembly->level) << what;
  if (ownFrame) {
    EXPECT_EQ(report.disassembly->level, own.disassembly->level) << what;
  }
  EXPECT_TRUE(report.disassembly->levelMinimal) << what;
  ASSERT_TRUE(report.shapeRemoval);
  EXPECT_EQ(report.shapeRemoval->failure, "") << what;
  EXPECT_NE(report.shapeRemoval->checked.find("on no lattice: the search for moves of several parts"), std::string::npos)
      << report.shapeRemoval->checked;
  if (replay) {
    EXPECT_EQ(replayMovesFailure(meshes, *report.disassembly), "") << what;
  }
}

TEST(MeshGroupSearch, DentedPuzzlesOffTheirLatticeGetTheVoxelKindsLevel) {
  std::mt19937 random(3131);
  for (const char* name : {"DraculasDentalDesaster-p0-s0", "PelikanBurr-p0-s0"}) {
    const std::string straight = exported(readDocument(std::string("tests/data/burrtools/") + name + ".puz"), "obj");
    const std::string obj = dentedObj(straight, kDentCells);
    const MeshAssembly dented = meshesOf({{"dented.obj", obj}});
    // PelikanBurr's 108 moves take 5 s to replay: turned and in inches only.
    const bool pelikan = std::string(name).rfind("Pelikan", 0) == 0;
    expectPlannedOffLattice(dented, meshesOf({{"puzzle.obj", straight}}), name, true, !pelikan, name);
    const std::array<Vec3, 3> rotation = randomRotation(random);
    const MeshAssembly turned = meshesOf({{"turned.obj", transformedObj(obj, rotation, 25.4)}}, LengthUnit::Inch);
    const MeshAssembly turnedStraight =
        meshesOf({{"turned.obj", transformedObj(straight, rotation, 25.4)}}, LengthUnit::Inch);
    expectPlannedOffLattice(turned, turnedStraight, name, false, true, std::string(name) + " turned, in inches");
  }
  EXPECT_EQ(voxelLevel("DraculasDentalDesaster-p0-s0"), (std::vector<int>{3, 5, 17, 6, 4}));
  EXPECT_EQ(voxelLevel("PelikanBurr-p0-s0"), (std::vector<int>{98, 2, 5}));
}

// Puzzles the single-part planner takes apart by bent paths, searched for moves of several parts
// all the same: the voxel kind's level, levels 2 and 3 among the numbers.
TEST(MeshGroupSearch, TheSearchAloneFindsTheVoxelLevelOfBentPuzzles) {
  std::mt19937 random(31);
  for (const char* name : {"AlPackino-p0-s0", "SolidSixPieceBurrs-p0-s257", "SolidSixPieceBurrs-p0-s266",
                           "SolidSixPieceBurrs-p0-s276"}) {
    const std::string obj = transformedObj(dentedPuzzle(name), randomRotation(random), 1);
    const MeshAssembly meshes = meshesOf({{"dented.obj", obj}});
    EXPECT_FALSE(mesh::meshLattice(meshes)) << name;
    const std::vector<mesh::PartGeometry>& geometry = mesh::geometryOf(meshes);
    const DisassemblyPlan plan = mesh::searchGroupMoves(meshes, geometry);
    ASSERT_TRUE(plan.complete) << name;
    EXPECT_EQ(plan.level, voxelLevel(name)) << name;
    EXPECT_EQ(mesh::sweepPlan(meshes, geometry, plan), "") << name;
    EXPECT_EQ(replayMovesFailure(meshes, plan), "") << name;
  }
  EXPECT_EQ(voxelLevel("AlPackino-p0-s0"), (std::vector<int>{1, 1, 1, 1, 1, 2, 1, 3, 1, 2, 1, 2}));
  EXPECT_EQ(voxelLevel("SolidSixPieceBurrs-p0-s257"), (std::vector<int>{1, 2}));
}

// CubeInCage comes apart in neither kind: off its lattice the search separates what the voxel kind
// separates and then runs out of positions (it does not stop at a bound): the parts left are
// proven stuck, the same as the voxel kind's.
TEST(MeshGroupSearch, APuzzleThatDoesNotComeApartIsProvenStuck) {
  const MeshAssembly meshes = meshesOf({{"dented.obj", dentedPuzzle("CubeInCage-p0-s0")}});
  EXPECT_FALSE(mesh::meshLattice(meshes));
  const DisassemblyPlan plan = mesh::searchGroupMoves(meshes, mesh::geometryOf(meshes));
  EXPECT_FALSE(plan.complete);
  EXPECT_FALSE(plan.searchLimitReached);
  const CheckReport own = checkDocument(readDocument("tests/data/burrtools/CubeInCage-p0-s0.puz"), bothTests());
  ASSERT_TRUE(own.disassembly);
  EXPECT_FALSE(own.disassembly->complete);
  EXPECT_EQ(plan.stuck, own.disassembly->stuck);
  EXPECT_EQ(plan.unseparated, own.disassembly->unseparated);
  const CheckReport report = checkMeshAssembly(meshes, bothTests());
  ASSERT_TRUE(report.disassembly && report.shapeRemoval);
  EXPECT_FALSE(report.disassembly->complete);
  EXPECT_FALSE(report.disassembly->searchLimitReached);
  EXPECT_NE(report.shapeRemoval->checked.find("finds no plan either"), std::string::npos);
}

// The replay and the sweep are checks that can fail: the off-lattice plan of DraculasDentalDesaster
// with its first move sent the other way, or left out, runs parts into each other.
TEST(MeshGroupSearch, TheReplayAndTheSweepCatchAWrongOffLatticePlan) {
  const MeshAssembly meshes = meshesOf({{"dented.obj", dentedPuzzle("DraculasDentalDesaster-p0-s0")}});
  const std::vector<mesh::PartGeometry>& geometry = mesh::geometryOf(meshes);
  const DisassemblyPlan plan = mesh::searchGroupMoves(meshes, geometry);
  ASSERT_TRUE(plan.complete);
  ASSERT_FALSE(plan.moves.front().out);
  EXPECT_EQ(mesh::sweepPlan(meshes, geometry, plan), "");
  DisassemblyPlan reversed = plan;
  reversed.moves.front().direction = negated(reversed.moves.front().direction);
  EXPECT_NE(replayMovesFailure(meshes, reversed), "");
  EXPECT_NE(mesh::sweepPlan(meshes, geometry, reversed), "");
  DisassemblyPlan skipped = plan;
  skipped.moves.erase(skipped.moves.begin());
  EXPECT_NE(replayMovesFailure(meshes, skipped), "");
  EXPECT_NE(mesh::sweepPlan(meshes, geometry, skipped), "");
}

// The search is bounded by counts of work, and says which bound stopped it: PelikanBurr's first
// separation takes 98 moves, far beyond 500 positions; the check then calls the parts left not
// proven stuck.
TEST(MeshGroupSearch, ASearchStoppedByItsBoundSaysWhich) {
  const MeshAssembly meshes = meshesOf({{"dented.obj", dentedPuzzle("PelikanBurr-p0-s0")}});
  mesh::GroupSearchLimits limits;
  limits.positions = 500;
  const DisassemblyPlan plan = mesh::searchGroupMoves(meshes, mesh::geometryOf(meshes), limits);
  EXPECT_FALSE(plan.complete);
  EXPECT_TRUE(plan.searchLimitReached);
  EXPECT_EQ(plan.limit, "500 positions of a sub-assembly");
  EXPECT_EQ(plan.groupStates, 500);
  limits = {};
  limits.pairSweeps = 1000;
  const DisassemblyPlan fewSweeps = mesh::searchGroupMoves(meshes, mesh::geometryOf(meshes), limits);
  EXPECT_TRUE(fewSweeps.searchLimitReached);
  EXPECT_EQ(fewSweeps.limit, "1000 sweeps of pairs of parts");
}

// Part 1 in a staircase channel through part 2 (the middle layer: right, up, right, up, then out
// to the right): five moves, beyond the single-part planner's bent paths of three. Dented off its
// lattice, the search finds the five, the voxel kind's level, turned at random and in inches too.
TEST(MeshGroupSearch, AFiveMovePathOutOfAStaircaseChannelOffItsLattice) {
  const std::vector<std::string> solid(5, "2 2 2 2 2 2 2");
  const std::vector<std::string> channel{"2 2 2 2 2 2 2", "2 1 0 2 2 2 2", "2 2 0 0 2 2 2", "2 2 2 0 0 0 0",
                                         "2 2 2 2 2 2 2"};
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers({solid, channel, solid}));
  const CheckReport own = checkDocument(document, bothTests());
  ASSERT_TRUE(own.disassembly && own.disassembly->complete);
  EXPECT_EQ(own.disassembly->level, (std::vector<int>{5}));
  const std::string obj = dentedObj(exported(document, "obj"), kDentCells);
  std::mt19937 random(55);
  for (const double unitMm : {1.0, 25.4}) {
    const MeshAssembly meshes = meshesOf({{"staircase.obj", transformedObj(obj, randomRotation(random), unitMm)}},
                                         unitMm == 1.0 ? LengthUnit::Millimetre : LengthUnit::Inch);
    EXPECT_FALSE(mesh::meshLattice(meshes));
    const CheckReport report = checkMeshAssembly(meshes, bothTests());
    ASSERT_TRUE(report.disassembly && report.disassembly->complete) << unitMm;
    EXPECT_EQ(report.disassembly->level, own.disassembly->level) << unitMm;
    ASSERT_EQ(report.disassembly->moves.size(), 5u) << unitMm;
    for (size_t m = 0; m < 4; ++m) EXPECT_NEAR(report.disassembly->moves[m].length, 1, 1e-6) << unitMm;
    EXPECT_TRUE(report.disassembly->moves.back().out) << unitMm;
    EXPECT_EQ(replayMovesFailure(meshes, *report.disassembly), "") << unitMm;
  }
}

}  // namespace
}  // namespace desia
