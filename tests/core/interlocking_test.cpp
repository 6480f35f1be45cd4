// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "desia/analysis.h"
#include "desia/document.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::idsOf;
using testing::loadReference;

struct ReferencePuzzle {
  const char* file;
  int parts;
  const char* keyDirection;
};

// Readable test names in gtest output instead of a byte dump.
void PrintTo(const ReferencePuzzle& value, std::ostream* out) { *out << value.file; }

// The original authors' published results (tests/reference/README.md): every one is interlocking
// with part 1 as key, free along one direction only.
const ReferencePuzzle kReferencePuzzles[] = {
    {"result_puz/Cube_4x4x4_K9.puz", 9, "-z"},      {"result_puz/Cube_4x4x4_K9_01.puz", 7, "+y"},
    {"result_puz/Cube_Hollow_4x4x4_K7", 7, "-z"},   {"result_puz/cube_5x5x5_K16.puz", 16, "+y"},
    {"result_puz/cartoon_dog.puz", 14, "+y"},       {"result_puz/bunny_15x14x11_K80.puz", 80, "+y"},
};

class ReferenceResults : public ::testing::TestWithParam<ReferencePuzzle> {};

TEST_P(ReferenceResults, GraphTestFindsKeyOne) {
  const AssemblyDocument document = loadReference(GetParam().file);
  ASSERT_EQ(document.assembly.partCount(), GetParam().parts);
  const InterlockingResult result = testInterlockingByGraphs(document.assembly, buildBaseBlockingGraphs(document.assembly));
  testing::ExpectInterlocking(document, result, 1, {GetParam().keyDirection});
}

TEST_P(ReferenceResults, InequalityTestAgreesWithGraphTest) {
  const AssemblyDocument document = loadReference(GetParam().file);
  const InterlockingResult result = testInterlockingByInequalities(document.assembly);
  testing::ExpectInterlocking(document, result, 1, {GetParam().keyDirection});
}

INSTANTIATE_TEST_SUITE_P(Desia, ReferenceResults, ::testing::ValuesIn(kReferencePuzzles),
                         [](const auto& info) { return testing::testNameFromPath(info.param.file); });

TEST(InputShapes, OnePartIsAVerdictNotAnError) {
  for (const char* file : {"input_puz/Cube_4x4x4_origin.puz", "input_puz/Cube_5x5x5_origin.puz",
                           "input_puz/Cube_hollow_4x4x4_origin.puz", "input_puz/bunny_origin.puz",
                           "input_puz/dog_origin.puz"}) {
    const AssemblyDocument document = loadReference(file);
    EXPECT_EQ(document.assembly.partCount(), 1) << file;
    CheckOptions options;
    options.method = CheckMethod::Both;
    const CheckReport report = checkAssembly(document, options);
    EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking) << file;
    EXPECT_NE(report.result.reason.find("at least three parts"), std::string::npos) << report.result.reason;
    ASSERT_TRUE(report.disassembly.has_value());
    EXPECT_TRUE(report.disassembly->complete);
  }
}

// Cube_4x4x4_K9_01 with one voxel of part 2 added on top of the key's column (2, 3, 1), growing
// the grid to 4x5x4: the key can no longer slide up, and nothing else can move.
AssemblyDocument keyCappedPuzzle() {
  const AssemblyDocument original = loadReference("result_puz/Cube_4x4x4_K9_01.puz");
  const VoxelGrid& g = original.voxels;
  VoxelGrid capped(g.nx(), g.ny() + 1, g.nz());
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) capped.setLabel(x, y, z, g.label(x, y, z));
  EXPECT_EQ(g.label(2, 3, 1), 1);  // the key's top voxel
  EXPECT_EQ(g.label(1, 3, 1), 2);  // part 2 beside it
  capped.setLabel(1, 4, 1, 2);
  capped.setLabel(2, 4, 1, 2);
  return documentFromVoxels(capped);
}

TEST(Deadlock, CappedKeyIsDeadlockedByBothTests) {
  const AssemblyDocument document = keyCappedPuzzle();
  const auto graphs = buildBaseBlockingGraphs(document.assembly);
  const InterlockingResult byGraphs = testInterlockingByGraphs(document.assembly, graphs);
  EXPECT_EQ(byGraphs.verdict, Verdict::Deadlocked) << byGraphs.reason;
  EXPECT_EQ(byGraphs.key, -1);
  EXPECT_FALSE(byGraphs.hasWitness);
  const InterlockingResult byInequalities = testInterlockingByInequalities(document.assembly);
  EXPECT_EQ(byInequalities.verdict, Verdict::Deadlocked) << byInequalities.reason;
  const CheckReport report = checkAssembly(document);
  ASSERT_TRUE(report.disassembly.has_value());
  EXPECT_FALSE(report.disassembly->complete);
  EXPECT_EQ(report.disassembly->stuck.size(), 7u);
}

TEST(NotInterlocking, PuzzleWithoutItsKeyExposesAMovableGroup) {
  // Cube_4x4x4_K9 without part 1 (ids shifted down): parts 3 and 6 (originally 4 and 7) slide
  // out together along +x.
  const AssemblyDocument original = loadReference("result_puz/Cube_4x4x4_K9.puz");
  VoxelGrid grid = original.voxels;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) grid.setLabelAt(i, std::max(0, grid.labelAt(i) - 1));
  const AssemblyDocument document = documentFromVoxels(grid);
  const InterlockingResult byGraphs = testInterlockingByGraphs(document.assembly, buildBaseBlockingGraphs(document.assembly));
  EXPECT_EQ(byGraphs.verdict, Verdict::NotInterlocking);
  ASSERT_TRUE(byGraphs.hasWitness);
  EXPECT_EQ(idsOf(document.assembly, byGraphs.witness.parts), (std::vector<int>{3, 6}));
  EXPECT_EQ(byGraphs.witness.direction, "+x");
  const InterlockingResult byInequalities = testInterlockingByInequalities(document.assembly);
  EXPECT_EQ(byInequalities.verdict, Verdict::NotInterlocking);
  EXPECT_EQ(idsOf(document.assembly, byInequalities.witness.parts), (std::vector<int>{3, 6}));
  EXPECT_EQ(byInequalities.witness.direction, "+x");
}

TEST(NotInterlocking, StackedSlabsSlideApart) {
  // Three 2x1x2 slabs stacked along y: every slab slides along x and z.
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers({{"1 1", "2 2", "3 3"}, {"1 1", "2 2", "3 3"}}));
  const InterlockingResult byGraphs = testInterlockingByGraphs(document.assembly, buildBaseBlockingGraphs(document.assembly));
  EXPECT_EQ(byGraphs.verdict, Verdict::NotInterlocking);
  ASSERT_TRUE(byGraphs.hasWitness);
  EXPECT_EQ(idsOf(document.assembly, byGraphs.witness.parts), (std::vector<int>{1}));
  // The LP sees these sliding motions only through its null-space test (all t_ij stay 0).
  const InterlockingResult byInequalities = testInterlockingByInequalities(document.assembly);
  EXPECT_EQ(byInequalities.verdict, Verdict::NotInterlocking);
  EXPECT_NE(byInequalities.reason.find("more than one part can move alone"), std::string::npos) << byInequalities.reason;
}

TEST(NotInterlocking, TwoPartsAreAVerdictWithAReason) {
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers({{"1 2"}}));
  const CheckReport report = checkAssembly(document);
  EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking);
  EXPECT_EQ(report.result.reason, "an interlocking assembly needs at least three parts; this one has 2");
}

// Fig. 4 in 3D: a fixed frame C (part 1) holds A (part 2), free only along +x relative to C, and
// B (part 3), free only along +y; A and B meet at a V-shaped interface with normals n1, n2.
// Neither part nor any group can translate in one direction, so every base DBG is strongly
// connected, yet A along +x and B along +y at the same time is collision free.
Assembly figureFourAssembly() {
  Assembly assembly;
  assembly.parts = {{1, "C"}, {2, "A"}, {3, "B"}};
  const double s1 = 1.0 / std::sqrt(1.25);
  const Vec3 n1{0.5 * s1, 1.0 * s1, 0}, n2{-1.0 * s1, -0.5 * s1, 0};
  assembly.contacts = {
      {1, 0, {0, 1, 0}, 1}, {1, 0, {0, -1, 0}, 1}, {1, 0, {-1, 0, 0}, 1}, {1, 0, {0, 0, 1}, 1}, {1, 0, {0, 0, -1}, 1},
      {2, 0, {1, 0, 0}, 1}, {2, 0, {-1, 0, 0}, 1}, {2, 0, {0, -1, 0}, 1}, {2, 0, {0, 0, 1}, 1}, {2, 0, {0, 0, -1}, 1},
      {1, 2, n1, 1},        {1, 2, n2, 1},
  };
  return assembly;
}

TEST(FigureFour, GraphTestSeesDeadlockButTheLinearProgramFindsTheMotion) {
  const Assembly assembly = figureFourAssembly();
  EXPECT_FALSE(hasOnlyAxisAlignedContacts(assembly));
  const InterlockingResult byGraphs = testInterlockingByGraphs(assembly, buildBaseBlockingGraphs(assembly));
  EXPECT_EQ(byGraphs.verdict, Verdict::Deadlocked) << byGraphs.reason;

  const InterlockingResult byInequalities = testInterlockingByInequalities(assembly);
  EXPECT_EQ(byInequalities.verdict, Verdict::NotInterlocking) << byInequalities.reason;
  ASSERT_TRUE(byInequalities.hasWitness);
  EXPECT_EQ(idsOf(assembly, byInequalities.witness.parts), (std::vector<int>{2, 3}));
  EXPECT_EQ(byInequalities.witness.direction, "");  // different directions at once
  // A moves along +x and B along +y (relative to the fixed frame).
  const Vec3& a = byInequalities.witness.velocities[0];
  const Vec3& b = byInequalities.witness.velocities[1];
  EXPECT_GT(a[0], 0.99);
  EXPECT_NEAR(a[1], 0, 1e-9);
  EXPECT_GT(b[1], 0.99);
  EXPECT_NEAR(b[0], 0, 1e-9);
}

TEST(FigureFour, CheckWithBothMethodsReportsTheMotion) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Contacts;
  document.assembly = figureFourAssembly();
  CheckOptions options;
  options.method = CheckMethod::Both;
  const CheckReport report = checkAssembly(document, options);
  EXPECT_EQ(report.graphResult->verdict, Verdict::Deadlocked);
  EXPECT_EQ(report.inequalityResult->verdict, Verdict::NotInterlocking);
  EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking);
  EXPECT_NE(report.result.reason.find("different directions at once"), std::string::npos) << report.result.reason;
}

TEST(FreeMotion, PartInASlotSlidesWithZeroObjective) {
  // Part 2 sits in a slot of part 1 along x: contacts only along ±y and ±z. Eq. 2 has optimum 0;
  // the null-space test must still find the sliding motion along x.
  Assembly assembly;
  assembly.parts = {{1, ""}, {2, ""}};
  assembly.contacts = {{1, 0, {0, 1, 0}, 1}, {1, 0, {0, -1, 0}, 1}, {1, 0, {0, 0, 1}, 1}, {1, 0, {0, 0, -1}, 1}};
  const MotionSearch search = findFreeMotion(assembly, {false, true});
  ASSERT_TRUE(search.movable);
  EXPECT_NEAR(std::abs(search.velocities[1][0]), 1.0, 1e-9);
  EXPECT_NEAR(search.velocities[1][1], 0.0, 1e-9);
  EXPECT_NEAR(search.velocities[1][2], 0.0, 1e-9);
  assembly.contacts.push_back({1, 0, {1, 0, 0}, 1});
  assembly.contacts.push_back({1, 0, {-1, 0, 0}, 1});
  EXPECT_FALSE(findFreeMotion(assembly, {false, true}).movable);
}

}  // namespace
}  // namespace desia
