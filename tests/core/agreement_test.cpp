// SPDX-License-Identifier: GPL-3.0-or-later
// Property test: on voxel assemblies (orthogonal contacts) the DBG test is exact (paper Section
// 3.2), so it must agree with the inequality test on every assembly. Variants of the reference
// puzzles, made by handing single voxels to a neighbouring part, give a mix of interlocking,
// deadlocked and not-interlocking assemblies close to real designs.
#include <gtest/gtest.h>

#include <array>
#include <iostream>
#include <map>
#include <random>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

TEST(VoxelAgreement, GraphAndInequalityTestsAgreeOnPuzzleVariants) {
  std::mt19937 random(20181204);
  std::map<Verdict, int> seen;
  int checked = 0, disassemblable = 0;
  for (const char* file : {"result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_4x4x4_K9_01.puz", "result_puz/Cube_Hollow_4x4x4_K7",
                           "result_puz/cube_5x5x5_K16.puz"}) {
    const VoxelGrid original = testing::loadReference(file).voxels;
    for (int variant = 0; variant < 60; ++variant) {
      VoxelGrid grid = original;
      const int trades = 1 + static_cast<int>(random() % 3);
      int done = 0;
      for (int attempt = 0; attempt < 200 && done < trades; ++attempt) done += testing::tradeOneVoxel(grid, random) ? 1 : 0;
      const AssemblyDocument document = documentFromVoxels(grid);
      const InterlockingResult byGraphs = testInterlockingByGraphs(document.assembly, buildBaseBlockingGraphs(document.assembly));
      const InterlockingResult byInequalities = testInterlockingByInequalities(document.assembly);
      ASSERT_EQ(byGraphs.verdict, byInequalities.verdict)
          << file << " variant " << variant << "\ndbg: " << byGraphs.reason << "\nlp: " << byInequalities.reason;
      ASSERT_EQ(byGraphs.key, byInequalities.key) << file << " variant " << variant;
      if (byGraphs.verdict == Verdict::Interlocking) {
        EXPECT_EQ(testing::labelsOf(byGraphs.keyDirections), testing::labelsOf(byInequalities.keyDirections));
      }
      const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
      if (plan.complete) {
        EXPECT_EQ(testing::verifyPlan(document.voxels, document.assembly, plan), "") << file << " variant " << variant;
      }
      // Interlocking is local (Section 3.2) and does not imply a disassembly exists (Section 3.3
      // tests that separately), but only the key can move first.
      if (byGraphs.verdict == Verdict::Interlocking && !plan.removals.empty()) {
        EXPECT_EQ(plan.removals[0].part, byGraphs.key) << file << " variant " << variant;
      }
      if (byGraphs.verdict == Verdict::Deadlocked) {
        EXPECT_TRUE(plan.removals.empty()) << file << " variant " << variant;
      }
      disassemblable += plan.complete ? 1 : 0;
      ++seen[byGraphs.verdict];
      ++checked;
    }
  }
  EXPECT_EQ(checked, 240);
  // The variants must exercise every verdict, or this test proves little.
  EXPECT_GT(seen[Verdict::Interlocking], 10);
  EXPECT_GT(seen[Verdict::NotInterlocking], 10);
  EXPECT_GT(seen[Verdict::Deadlocked], 0);
  EXPECT_GT(disassemblable, 10);
  std::cout << "[          ] variants: " << seen[Verdict::Interlocking] << " interlocking, " << seen[Verdict::Deadlocked]
            << " deadlocked, " << seen[Verdict::NotInterlocking] << " not interlocking; " << disassemblable
            << " disassemblable\n";
}

}  // namespace
}  // namespace desia
