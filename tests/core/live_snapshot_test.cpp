// SPDX-License-Identifier: GPL-3.0-or-later
// Live design (issue 11): the designers' progress can carry a snapshot of the deepest node found so
// far. The snapshot is read from the search, never fed back: a design with snapshots gives the same
// result as one without, and the snapshots only ever get deeper.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

VoxelGrid referenceShape(const char* file) {
  return testing::loadReference(std::string("input_puz/") + file).voxels;
}

// Parts in a snapshot grid: its labels 1..bestDepth - 1 are parts placed, bestDepth the remainder.
int partsIn(const VoxelGrid& grid) { return grid.maxLabel(); }

TEST(LiveSnapshots, VoxelDesignIsTheSameWithSnapshotsAndTheyOnlyGetDeeper) {
  // The hollow cube restarts once for seed 1 (see VoxelDesign.RestartsGiveVerifiedReproduciblePuzzles):
  // the snapshot must stay the deepest node across trees.
  for (const char* file : {"Cube_4x4x4_origin.puz", "Cube_hollow_4x4x4_origin.puz"}) {
    const VoxelGrid shape = referenceShape(file);
    VoxelDesignOptions plain;
    plain.parts = 7;
    plain.seed = 1;
    plain.limits.timeLimitSeconds = 120;
    const VoxelDesignResult without = designVoxelPuzzle(shape, plain);

    VoxelDesignOptions live = plain;
    live.limits.deepestSnapshots = true;
    std::vector<int> depths;  // the snapshot's parts each time a new snapshot arrives
    const VoxelGrid* last = nullptr;
    live.limits.onProgress = [&](const DesignProgress& progress) {
      EXPECT_NE(progress.deepestGrid, nullptr);
      if (progress.deepestGrid && progress.deepestGrid.get() != last) {
        last = progress.deepestGrid.get();
        EXPECT_EQ(partsIn(*progress.deepestGrid), progress.bestDepth) << file;
        // Same voxels as the shape: a labelling of it, nothing more.
        for (int64_t i = 0; i < shape.voxelCount(); ++i)
          EXPECT_EQ(progress.deepestGrid->labelAt(i) != 0, shape.labelAt(i) != 0) << file << " voxel " << i;
        depths.push_back(progress.bestDepth);
      }
      return true;
    };
    const VoxelDesignResult with = designVoxelPuzzle(shape, live);
    ASSERT_EQ(with.status, DesignStatus::Success) << file << ": " << with.message;
    EXPECT_EQ(with.puzzle.labels(), without.puzzle.labels()) << file;
    EXPECT_EQ(with.progress.nodes, without.progress.nodes) << file;
    EXPECT_EQ(with.message, without.message) << file;
    ASSERT_FALSE(depths.empty());
    for (size_t k = 1; k < depths.size(); ++k) EXPECT_GT(depths[k], depths[k - 1]) << file;
    // The final progress holds the complete puzzle: the deepest node is the result.
    ASSERT_NE(with.progress.deepestGrid, nullptr);
    EXPECT_EQ(with.progress.deepestGrid->labels(), with.puzzle.labels()) << file;
    EXPECT_EQ(without.progress.deepestGrid, nullptr) << "snapshots are on demand only";
  }
}

AssemblyDocument loadPlateExample(const std::string& name) {
  const std::string path = "examples/plate/" + name;
  return parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
}

// Checks the snapshots of a plate or frame search: each one deeper than the one before and its
// parts distinct input indices.
template <typename Progress>
void ExpectGrowingPlacements(const std::vector<std::vector<int>>& snapshots, int parts) {
  ASSERT_FALSE(snapshots.empty());
  for (size_t k = 0; k < snapshots.size(); ++k) {
    if (k > 0) {
      EXPECT_GT(snapshots[k].size(), snapshots[k - 1].size());
    }
    std::vector<bool> seen(parts, false);
    for (int index : snapshots[k]) {
      ASSERT_GE(index, 0);
      ASSERT_LT(index, parts);
      EXPECT_FALSE(seen[index]) << "part " << index << " placed twice";
      seen[index] = true;
    }
  }
}

TEST(LiveSnapshots, PlateDesignIsTheSameWithSnapshotsAndTheyOnlyGetDeeper) {
  const AssemblyDocument table = loadPlateExample("table.json");
  const std::vector<PlateContact> contacts = computePlateContacts(table.plates, {});
  const PlateDesignResult without = designPlateJoints(table.plates, contacts, {});

  PlateDesignOptions live;
  live.limits.deepestSnapshots = true;
  std::vector<std::vector<int>> snapshots;
  live.limits.onProgress = [&](const DesignProgress& progress) {
    if (snapshots.empty() || progress.deepestPlaced != snapshots.back()) snapshots.push_back(progress.deepestPlaced);
    return true;
  };
  const PlateDesignResult with = designPlateJoints(table.plates, contacts, live);
  ASSERT_EQ(with.status, DesignStatus::Success) << with.message;
  EXPECT_EQ(with.order, without.order);
  EXPECT_EQ(with.message, without.message);
  EXPECT_EQ(with.progress.nodes, without.progress.nodes);
  // The first report comes before any plate is taken: an empty snapshot, then deeper ones.
  snapshots.erase(snapshots.begin());
  ExpectGrowingPlacements<DesignProgress>(snapshots, static_cast<int>(table.plates.size()));
  // The last snapshot is a prefix of the deepest path; the final progress holds the whole plan but the last plate.
  const std::vector<int>& final = with.progress.deepestPlaced;
  ASSERT_EQ(final.size() + 1, with.order.size());
  EXPECT_TRUE(std::equal(final.begin(), final.end(), with.order.begin()));
  EXPECT_TRUE(without.progress.deepestPlaced.empty()) << "snapshots are on demand only";
}

TEST(LiveSnapshots, FrameDesignIsTheSameWithSnapshotsAndTheyOnlyGetDeeper) {
  const std::string path = "examples/frame/scaffold_92.json";
  const FrameDocument scaffold = parseFrameText(testing::readFileText(testing::projectPath(path)), path);
  FrameDesignOptions plain;
  plain.limits.timeLimitSeconds = 120;
  const FrameDesignResult without = designFrame(scaffold.layout, plain);

  FrameDesignOptions live = plain;
  live.limits.deepestSnapshots = true;
  std::vector<std::vector<int>> snapshots;
  live.limits.onProgress = [&](const DesignProgress& progress) {
    if (!progress.deepestPlaced.empty() && (snapshots.empty() || progress.deepestPlaced != snapshots.back()))
      snapshots.push_back(progress.deepestPlaced);
    return true;
  };
  const FrameDesignResult with = designFrame(scaffold.layout, live);
  ASSERT_EQ(with.status, DesignStatus::Success) << with.message;
  EXPECT_EQ(frameResultToJson(scaffold.layout, with), frameResultToJson(scaffold.layout, without));
  ExpectGrowingPlacements<DesignProgress>(snapshots, static_cast<int>(scaffold.layout.frame.beams.size()));
  const std::vector<int>& final = with.progress.deepestPlaced;
  ASSERT_EQ(final.size() + 1, with.order.size());
  EXPECT_TRUE(std::equal(final.begin(), final.end(), with.order.begin()));
}

}  // namespace
}  // namespace desia
