// SPDX-License-Identifier: GPL-3.0-or-later
// Part-size control of the voxel designer (issue 10): bounds on every part's size, the even-size
// mode, the look-ahead that keeps the remainder splittable into the parts still to make, the
// reported size spread, and impossible bounds as bad input.
#include <gtest/gtest.h>

#include <algorithm>

#include "desia/error.h"
#include "desia/voxel.h"
#include "test_support.h"
#include "voxel/design_internals.h"

namespace desia {
namespace {

using design::Candidate;
using design::SizeWindow;

VoxelGrid cube4() { return testing::loadReference("input_puz/Cube_4x4x4_origin.puz").voxels; }

VoxelDesignOptions optionsFor(int parts, uint64_t seed) {
  VoxelDesignOptions options;
  options.parts = parts;
  options.seed = seed;
  options.limits.timeLimitSeconds = 120;
  return options;
}

std::vector<int> sizesOf(const std::vector<Candidate>& candidates) {
  std::vector<int> sizes;
  for (const Candidate& candidate : candidates) sizes.push_back(static_cast<int>(candidate.partVoxels.size()));
  return sizes;
}

void ExpectWindow(const SizeWindow& window, int min, int max) {
  EXPECT_EQ(window.min, min);
  EXPECT_EQ(window.max, max);
}

TEST(PartSizes, WindowLeavesARemainderTheLaterPartsCanShare) {
  // 64 voxels, 4 parts of at least 15: the first takes at most 64 - 3 * 15 = 19.
  ExpectWindow(design::partSizeWindow(64, 4, {15, 64}), 15, 19);
  // 7 parts of at most 10: the first takes at least 64 - 6 * 10 = 4.
  ExpectWindow(design::partSizeWindow(64, 7, {2, 10}), 4, 10);
  // The final split: both parts within [8, 11] of 20 voxels.
  ExpectWindow(design::partSizeWindow(20, 2, {8, 11}), 9, 11);
  // One part left (the remainder itself): exactly its size, when the bounds allow it.
  ExpectWindow(design::partSizeWindow(9, 1, {8, 11}), 9, 9);
  // 30 voxels cannot be 3 parts of at least 11: no size is allowed.
  EXPECT_TRUE(design::partSizeWindow(30, 3, {11, 20}).empty());
  // A heuristic window is moved into the allowed one, end by end.
  const SizeWindow clamped = design::clampInto({12, 21}, {15, 19});
  ExpectWindow(clamped, 15, 19);
  ExpectWindow(design::clampInto({16, 17}, {15, 19}), 16, 17);
}

TEST(PartSizes, EvenBoundsAreTheMeanWithinATolerance) {
  // floor(mean) - t .. ceil(mean) + t, t = max(1, floor(0.2 * mean)).
  const PartSizeBounds cube7 = evenPartBounds(64, 7);  // mean 9.14, t = 1
  EXPECT_EQ(cube7.min, 8);
  EXPECT_EQ(cube7.max, 11);
  const PartSizeBounds cube4parts = evenPartBounds(64, 4);  // mean 16, t = 3
  EXPECT_EQ(cube4parts.min, 13);
  EXPECT_EQ(cube4parts.max, 19);
  const PartSizeBounds bunny120 = evenPartBounds(966, 120);  // mean 8.05, t = 1
  EXPECT_EQ(bunny120.min, 7);
  EXPECT_EQ(bunny120.max, 10);
}

// The key's look-ahead: with parts of at least 15 voxels, a key of more than 19 voxels would leave
// fewer than 45, too few for 3 more parts of 15: a dead branch. Asked for keys of about 18 (18 to
// 22 voxels, the target and a quarter more), the designer makes such keys without the minimum and
// refuses them with it.
TEST(PartSizes, KeyLookAheadRefusesKeysThatLeaveTooLittle) {
  const VoxelGrid cube = cube4();
  VoxelDesignOptions loose = optionsFor(4, 1);
  loose.minPartSize = 2;
  loose.maxPartSize = 64;
  design::DesignContext looseContext{loose, {}, {}, 64, std::mt19937_64(1)};
  const std::vector<int> looseSizes = sizesOf(design::generateKeyCandidates(cube, looseContext, 18));
  ASSERT_FALSE(looseSizes.empty());
  EXPECT_GT(*std::max_element(looseSizes.begin(), looseSizes.end()), 19);

  VoxelDesignOptions bounded = loose;
  bounded.minPartSize = 15;
  design::DesignContext boundedContext{bounded, {}, {}, 64, std::mt19937_64(1)};
  const std::vector<int> sizes = sizesOf(design::generateKeyCandidates(cube, boundedContext, 18));
  ASSERT_FALSE(sizes.empty());
  for (int size : sizes) {
    EXPECT_GE(size, 18);  // the target: the heuristic still decides inside the window
    EXPECT_LE(size, 19);
  }
}

// P_i's look-ahead: with parts of at most 11, R_1 of `r` voxels must keep at most 4 * 11 after
// P_2, so P_2 takes at least r - 44 voxels, more than the heuristic's 8 (the target 10 less a
// quarter). Smaller parts are made without the maximum and refused with it.
TEST(PartSizes, PartLookAheadRefusesPartsThatLeaveTooMuch) {
  const VoxelGrid cube = cube4();
  VoxelDesignOptions bounded = optionsFor(6, 5);
  bounded.minPartSize = 2;
  bounded.maxPartSize = 11;
  design::DesignContext keyContext{bounded, {}, {}, 64, std::mt19937_64(5)};
  const std::vector<Candidate> keys = design::generateKeyCandidates(cube, keyContext, 10);
  ASSERT_FALSE(keys.empty());
  VoxelGrid grid = cube;
  design::applyCandidate(grid, 1, keys[0]);
  const int remainder = 64 - static_cast<int>(keys[0].partVoxels.size());
  ASSERT_GE(remainder, 53);  // the key has at most 11 voxels
  const int target = design::targetPartSize(remainder, 5);
  EXPECT_LT(target - target / 4, remainder - 44);

  VoxelDesignOptions loose = bounded;
  loose.maxPartSize = 64;
  design::DesignContext looseContext{loose, {}, {}, 64, std::mt19937_64(5)};
  const std::vector<int> looseSizes = sizesOf(design::generatePartCandidates(grid, 2, looseContext, target, 4));
  ASSERT_FALSE(looseSizes.empty());
  EXPECT_LT(*std::min_element(looseSizes.begin(), looseSizes.end()), remainder - 44);

  design::DesignContext boundedContext{bounded, {}, {}, 64, std::mt19937_64(5)};
  const std::vector<int> sizes = sizesOf(design::generatePartCandidates(grid, 2, boundedContext, target, 4));
  ASSERT_FALSE(sizes.empty());
  for (int size : sizes) {
    EXPECT_GE(size, remainder - 44);
    EXPECT_LE(size, 11);
  }
}

void ExpectSizesWithin(const VoxelDesignResult& result, int parts, int min, int max) {
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_EQ(result.puzzle.maxLabel(), parts);
  const std::vector<int64_t> counts = result.puzzle.labelCounts();
  for (int part = 1; part <= parts; ++part) {
    EXPECT_GE(counts[part], min) << "part " << part;
    EXPECT_LE(counts[part], max) << "part " << part;
  }
  const PartSizeSpread spread = partSizeSpread(result.puzzle);
  EXPECT_EQ(result.partSizes.min, spread.min);
  EXPECT_EQ(result.partSizes.max, spread.max);
  EXPECT_DOUBLE_EQ(result.partSizes.mean, spread.mean);
  EXPECT_GE(spread.min, min);
  EXPECT_LE(spread.max, max);
  // The designer verified it (interlocking with key 1, disassembly 1..N).
  EXPECT_EQ(result.verification.result.verdict, Verdict::Interlocking);
  EXPECT_EQ(result.verification.result.key, 0);
}

TEST(PartSizes, DesignsKeepEveryPartWithinTheBounds) {
  const VoxelGrid cube = cube4();
  VoxelDesignOptions bounded = optionsFor(6, 5);
  bounded.maxPartSize = 11;
  ExpectSizesWithin(designVoxelPuzzle(cube, bounded), 6, 2, 11);

  VoxelDesignOptions even = optionsFor(7, 1);
  even.evenParts = true;
  const VoxelDesignResult evenResult = designVoxelPuzzle(cube, even);
  ExpectSizesWithin(evenResult, 7, 8, 11);
  EXPECT_EQ(evenResult.seed, 1u);
  EXPECT_NEAR(evenResult.partSizes.mean, 64.0 / 7, 1e-12);

  VoxelDesignOptions tight = optionsFor(4, 2);
  tight.minPartSize = 15;
  tight.maxPartSize = 17;
  ExpectSizesWithin(designVoxelPuzzle(cube, tight), 4, 15, 17);
}

TEST(PartSizes, DefaultDesignsReportTheirSpread) {
  const VoxelDesignResult result = designVoxelPuzzle(cube4(), optionsFor(7, 3));
  ASSERT_EQ(result.status, DesignStatus::Success);
  EXPECT_EQ(result.seed, 3u);
  // The spread counted here from the puzzle's labels, independently of partSizeSpread.
  std::vector<int> sizes(8, 0);
  for (int label : result.puzzle.labels()) {
    ASSERT_GE(label, 1);
    ASSERT_LE(label, 7);
    ++sizes[label];
  }
  const auto [smallest, largest] = std::minmax_element(sizes.begin() + 1, sizes.end());
  EXPECT_EQ(result.partSizes.min, *smallest);
  EXPECT_EQ(result.partSizes.max, *largest);
  EXPECT_LT(*smallest, *largest);  // a default design is not even: the spread says something
  EXPECT_NEAR(result.partSizes.mean, 64.0 / 7, 1e-12);
}

TEST(PartSizes, ImpossibleBoundsAreBadInputNamingTheValues) {
  const VoxelGrid cube = cube4();
  auto message = [&](int parts, int min, int max, bool even = false) {
    VoxelDesignOptions options = optionsFor(parts, 1);
    options.minPartSize = min;
    options.maxPartSize = max;
    options.evenParts = even;
    try {
      designVoxelPuzzle(cube, options);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::BadInput);
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(7, 9, 8), "max part size 8 is less than min part size 9");
  EXPECT_EQ(message(7, 0, 5),
            "max part size 5 is too small: 7 parts of at most 5 voxels hold 35, fewer than the shape's 64 voxels");
  EXPECT_EQ(message(7, 10, 0),
            "min part size 10 is too large: 7 parts of at least 10 voxels need 70, more than the shape's 64 voxels");
  // Bounds that hold the mean always meet the even ones: here 13 to 16.
  EXPECT_EQ(message(4, 0, 16, true), "accepted");
}

}  // namespace
}  // namespace desia
