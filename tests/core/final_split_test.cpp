// SPDX-License-Identifier: GPL-3.0-or-later
// The deep end of the construction tree (paper Section 4.1, Algorithm 1): the last splits are
// enumerated (final_split.h), and with three parts left a child whose remainder admits no last
// split is a dead branch, dropped before the search descends into it.
#include <gtest/gtest.h>

#include <random>

#include "desia/document.h"
#include "desia/voxel.h"
#include "test_support.h"
#include "voxel/candidate_checks.h"
#include "voxel/final_split.h"

namespace desia {
namespace {

// The authors' 9-part 4x4x4 cube with the labels from `first` on merged into one remainder:
// a node of the construction tree with 10 - first parts still to make.
VoxelGrid mergedFrom(int first) {
  VoxelGrid grid = testing::loadReference("result_puz/Cube_4x4x4_K9.puz").voxels;
  for (int64_t v = 0; v < grid.voxelCount(); ++v) {
    if (grid.labelAt(v) > first) grid.setLabelAt(v, first);
  }
  return grid;
}

VoxelDesignOptions nineParts() {
  VoxelDesignOptions options;
  options.parts = 9;
  options.minPartSize = 2;
  options.keyDirection = {0, 0, -1};  // the authors' key leaves along -z
  return options;
}

int64_t countLabel(const VoxelGrid& grid, int label) {
  int64_t count = 0;
  for (int v : grid.labels()) count += v == label ? 1 : 0;
  return count;
}

// Connected subsets of the 2x2x2 cube, counted by brute force over all 2^8 subsets.
int connectedSubsetsOfCube2(int maxSize) {
  int count = 0;
  for (int mask = 1; mask < 256; ++mask) {
    if (__builtin_popcount(mask) > maxSize) continue;
    VoxelGrid grid(2, 2, 2);
    for (int v = 0; v < 8; ++v) grid.setLabelAt(v, (mask >> v) & 1);
    count += design::isFaceConnected(grid, 1) ? 1 : 0;
  }
  return count;
}

TEST(FinalSplit, VisitsEveryConnectedPartOnce) {
  VoxelGrid grid(2, 2, 2);
  for (int v = 0; v < 8; ++v) grid.setLabelAt(v, 1);
  VoxelDesignOptions options = nineParts();
  design::DesignContext context{options, {}, {}, 8, std::mt19937_64(1)};
  design::FinalSplitStats stats;
  design::enumerateSplits(grid, 1, context, {1, 7}, design::FinalSplitLimits{}, false, &stats);
  EXPECT_EQ(stats.setsVisited, connectedSubsetsOfCube2(7));
  EXPECT_EQ(stats.setsVisited, 166);
  EXPECT_TRUE(stats.exhausted);
  EXPECT_EQ(stats.exactChecks, 0);  // nothing around: every part would be free alone
}

TEST(FinalSplit, SixtyFourVoxelsAreTheLimit) {
  VoxelGrid grid(4, 4, 4);
  for (int v = 0; v < 64; ++v) grid.setLabelAt(v, 1);
  VoxelDesignOptions options = nineParts();
  design::DesignContext context{options, {}, {}, 64, std::mt19937_64(1)};
  design::FinalSplitStats stats;
  design::enumerateSplits(grid, 1, context, {1, 2}, design::FinalSplitLimits{}, false, &stats);
  EXPECT_EQ(stats.setsVisited, 64 + 144);  // single voxels and face-adjacent pairs, each once
  EXPECT_TRUE(stats.exhausted);
  VoxelGrid larger(5, 5, 5);
  for (int v = 0; v < 65; ++v) larger.setLabelAt(v, 1);
  EXPECT_TRUE(design::enumerateSplits(larger, 1, context, {1, 2}, design::FinalSplitLimits{}, false, &stats).empty());
  EXPECT_FALSE(stats.exhausted);  // not enumerated: the random designs decide
}

TEST(FinalSplit, EverySplitFoundCompletesAVerifiedPuzzle) {
  const VoxelGrid node = mergedFrom(8);  // P1..P7 placed, R7 to split into P8 and R8
  const VoxelDesignOptions options = nineParts();
  design::DesignContext context{options, {}, {}, 64, std::mt19937_64(1)};
  design::FinalSplitStats stats;
  const std::vector<design::Candidate> splits =
      design::enumerateSplits(node, 8, context, {2, static_cast<int>(countLabel(node, 8)) - 2}, design::FinalSplitLimits{}, false, &stats);
  ASSERT_FALSE(splits.empty());
  EXPECT_TRUE(stats.exhausted);
  for (const design::Candidate& split : splits) {
    VoxelGrid puzzle = node;
    design::applyCandidate(puzzle, 8, split);
    const CheckReport report = checkAssembly(documentFromVoxels(puzzle));
    EXPECT_EQ(report.result.verdict, Verdict::Interlocking);
    EXPECT_EQ(report.result.key, 0);
    ASSERT_TRUE(report.disassembly && report.disassembly->complete);
  }
}

// The look-ahead with three parts left: every child it drops is a split the exact checks accept
// whose remainder has no last split at all (enumerated to the end), i.e. a dead branch.
TEST(FinalSplit, LookAheadDropsExactlyTheChildrenWithoutALastSplit) {
  const VoxelGrid node = mergedFrom(7);  // R6: three parts left
  const VoxelDesignOptions options = nineParts();
  design::DesignContext context{options, {}, {}, 64, std::mt19937_64(1)};
  design::FinalSplitLimits limits;
  limits.maxSplits = 1000;
  const int voxels = static_cast<int>(countLabel(node, 7));
  const design::SizeWindow size{2, voxels - 4};
  const std::vector<design::Candidate> all = design::enumerateSplits(node, 7, context, size, limits, false);
  const std::vector<design::Candidate> alive = design::enumerateSplits(node, 7, context, size, limits, true);
  ASSERT_FALSE(alive.empty());  // the authors' own split is among them
  ASSERT_LT(alive.size(), all.size());
  size_t k = 0, dropped = 0;
  for (const design::Candidate& child : all) {
    if (k < alive.size() && alive[k].partVoxels == child.partVoxels) {
      ++k;
      continue;
    }
    VoxelGrid next = node;
    design::applyCandidate(next, 7, child);
    ASSERT_TRUE(design::acceptsSplit(next, 7, options.keyDirection));
    design::FinalSplitStats stats;
    const int rest = static_cast<int>(countLabel(next, 8));
    EXPECT_TRUE(design::enumerateSplits(next, 8, context, {2, rest - 2}, limits, false, &stats).empty());
    EXPECT_TRUE(stats.exhausted);
    ++dropped;
  }
  EXPECT_EQ(k, alive.size());
  EXPECT_GT(dropped, 0u);
}

}  // namespace
}  // namespace desia
