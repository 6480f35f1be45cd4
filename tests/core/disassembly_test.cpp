// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::loadReference;

struct BentCase {
  const char* file;
  std::vector<int> bentParts;  // parts whose removal needs a change of direction
};

// Readable test names in gtest output instead of a byte dump.
void PrintTo(const BentCase& value, std::ostream* out) { *out << value.file; }

// Bent parts per reference result, as listed in tests/reference/README.md.
const BentCase kBentCases[] = {
    {"result_puz/Cube_4x4x4_K9.puz", {3}},
    {"result_puz/Cube_4x4x4_K9_01.puz", {2}},
    {"result_puz/Cube_Hollow_4x4x4_K7", {2, 3}},
    {"result_puz/cube_5x5x5_K16.puz", {11}},
    {"result_puz/cartoon_dog.puz", {}},
    {"result_puz/bunny_15x14x11_K80.puz", {2, 3, 9, 10, 54, 79}},
};

class ReferenceDisassembly : public ::testing::TestWithParam<BentCase> {};

TEST_P(ReferenceDisassembly, RemovesPartsInIdOrderWithVerifiedPaths) {
  const AssemblyDocument document = loadReference(GetParam().file);
  const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
  ASSERT_TRUE(plan.complete);
  std::vector<int> order, bent;
  for (const Removal& removal : plan.removals) {
    order.push_back(document.assembly.parts[removal.part].id);
    if (removal.path.size() > 1) bent.push_back(order.back());
  }
  std::vector<int> idOrder(document.assembly.partCount());
  for (size_t i = 0; i < idOrder.size(); ++i) idOrder[i] = static_cast<int>(i) + 1;
  EXPECT_EQ(order, idOrder);
  EXPECT_EQ(bent, GetParam().bentParts);
  EXPECT_EQ(testing::verifyPlan(document.voxels, document.assembly, plan), "");
}

INSTANTIATE_TEST_SUITE_P(Desia, ReferenceDisassembly, ::testing::ValuesIn(kBentCases), [](const auto& info) {
  return testing::testNameFromPath(info.param.file);
});

TEST(VoxelDisassembly, BentPathOfCube4x4x4K9PartThree) {
  const AssemblyDocument document = loadReference("result_puz/Cube_4x4x4_K9.puz");
  const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
  ASSERT_TRUE(plan.complete);
  const Removal& third = plan.removals[2];
  ASSERT_EQ(third.part, 2);  // part id 3
  ASSERT_EQ(third.path.size(), 2u);
  EXPECT_EQ(third.path[0].direction, (Vec3{0, 0, 1}));
  EXPECT_EQ(third.path[0].steps, 1);
  EXPECT_EQ(third.path[1].direction, (Vec3{-1, 0, 0}));
  EXPECT_EQ(third.path[1].steps, 2);
}

TEST(VoxelDisassembly, TrappedPartLeavesPlanIncomplete) {
  // A 3x3x3 box of part 2 with a hole at the centre holding part 1, plus part 3 beside the box.
  std::vector<std::vector<std::string>> layers = {
      {"2 2 2 3", "2 2 2 0", "2 2 2 0"},
      {"2 2 2 0", "2 1 2 0", "2 2 2 0"},
      {"2 2 2 0", "2 2 2 0", "2 2 2 0"},
  };
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers(layers));
  const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
  EXPECT_FALSE(plan.complete);
  // Part 3 can leave; then parts 1 and 2 are stuck (the enclosed part can never get out).
  ASSERT_EQ(plan.removals.size(), 1u);
  EXPECT_EQ(plan.removals[0].part, 2);
  EXPECT_EQ(plan.stuck, (std::vector<int>{0, 1}));
}

TEST(VoxelDisassembly, SearchFindsAPathWithSeveralTurns) {
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers(testing::sChannelLayers()));
  const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
  ASSERT_TRUE(plan.complete);
  const Removal& first = plan.removals[0];
  ASSERT_EQ(first.part, 0);
  ASSERT_EQ(first.path.size(), 3u);
  EXPECT_EQ(first.path[0].direction, (Vec3{1, 0, 0}));
  EXPECT_EQ(first.path[0].steps, 1);
  EXPECT_EQ(first.path[1].direction, (Vec3{0, 1, 0}));
  EXPECT_EQ(first.path[1].steps, 1);
  EXPECT_EQ(first.path[2].direction, (Vec3{1, 0, 0}));
  EXPECT_EQ(first.path[2].steps, 3);
  EXPECT_EQ(testing::verifyPlan(document.voxels, document.assembly, plan), "");
}

TEST(VoxelDisassembly, WorkLimitIsReportedNotPassedOffAsStuck) {
  const AssemblyDocument document = documentFromVoxels(testing::gridFromLayers(testing::sChannelLayers()));
  VoxelDisassemblyOptions tight;
  tight.maxVoxelTests = 10;
  tight.groupMoves = false;  // the single-part planner's own limit (the complete disassembler has its own)
  const DisassemblyPlan limited = planVoxelDisassembly(document.voxels, document.assembly, tight);
  EXPECT_FALSE(limited.complete);
  EXPECT_TRUE(limited.searchLimitReached);
  const DisassemblyPlan full = planVoxelDisassembly(document.voxels, document.assembly);
  EXPECT_TRUE(full.complete);
  EXPECT_FALSE(full.searchLimitReached);
}

TEST(ContactDisassembly, RemovesLocallyFreePartsFirst) {
  // Three parts in a row along x: 1 | 2 | 3, each touching the next. Part 1 is free along -x.
  Assembly assembly;
  assembly.parts = {{1, ""}, {2, ""}, {3, ""}};
  assembly.contacts = {{0, 1, {1, 0, 0}, 1}, {1, 2, {1, 0, 0}, 1}};
  const DisassemblyPlan plan = planContactDisassembly(assembly);
  ASSERT_TRUE(plan.complete);
  ASSERT_EQ(plan.removals.size(), 3u);
  EXPECT_EQ(plan.removals[0].part, 0);
  EXPECT_EQ(plan.removals[2].path.size(), 0u);
}

}  // namespace
}  // namespace desia
