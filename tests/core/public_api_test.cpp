// SPDX-License-Identifier: GPL-3.0-or-later
// The umbrella header is all a program needs: reading, checking, designing, exporting a puzzle
// through desia/desia.h alone (what a user embedding the core writes).
#include "desia/desia.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace desia {
namespace {

TEST(PublicApi, TheUmbrellaHeaderReadsChecksDesignsAndExports) {
  const AssemblyDocument shape =
      parseAssemblyText(testing::readFileText(testing::projectPath("examples/voxel/Cube_4x4x4_K9.puz")), "cube.puz");
  CheckOptions options;
  options.method = CheckMethod::Both;
  const CheckReport report = checkDocument(shape, options);
  EXPECT_TRUE(checkPassed(report));
  EXPECT_EQ(report.result.verdict, Verdict::Interlocking);

  VoxelGrid cube(3, 3, 3);
  for (int64_t i = 0; i < cube.voxelCount(); ++i) cube.setLabelAt(i, 1);
  VoxelDesignOptions design;
  design.parts = 3;
  design.seed = 1;
  const VoxelDesignResult result = designVoxelPuzzle(cube, design);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  const AssemblyDocument designed = documentFromVoxels(result.puzzle);
  EXPECT_TRUE(checkPassed(checkDocument(designed)));
  EXPECT_FALSE(exportAssembly(designed, parseExportFormat("stl")).empty());
  EXPECT_FALSE(std::string(kVersion).empty());
}

}  // namespace
}  // namespace desia
