// SPDX-License-Identifier: GPL-3.0-or-later
// How the voxel disassembly planner (Section 3.3) scales: it must not search every part again
// after every removal (issue 14, item 7), and its work budget must stop it without passing the
// parts it did not get to off as proven stuck. Work is asserted as counts, never as time.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

// These tests pin the single-part planner (its search caching and work limits); the complete
// disassembler, which takes over where it fails, is tested in group_disassembly_test.cpp.
DisassemblyPlan singlePartPlan(const VoxelGrid& grid, const Assembly& assembly, VoxelDisassemblyOptions options = {}) {
  options.groupMoves = false;
  return planVoxelDisassembly(grid, assembly, options);
}


// The worst case of the issue: part 1 is a container of cellsX x cellsY x cellsZ sealed cells
// (hollow 14^3 boxes with walls one voxel thick, joined by one voxel between neighbours), each
// holding an 8^3 part (ids 2, 3, ...) that can rattle two voxels each way but never get out; on
// the top layer lie topsPerCell single voxels per top cell (the last ids), each free to leave
// upwards. Removing the loose voxels changes nothing for the sealed parts, so a planner that
// searches every part every round does (cells + 2) searches per removed voxel.
struct SealedCells {
  VoxelGrid grid;
  int cells = 0;
  int tops = 0;
};

SealedCells sealedCells(int cellsX, int cellsY, int cellsZ, int topsPerCell) {
  SealedCells result;
  result.grid = VoxelGrid(15 * cellsX - 1, 15 * cellsY, 15 * cellsZ - 1);
  VoxelGrid& grid = result.grid;
  int label = 2;
  for (int k = 0; k < cellsZ; ++k) {
    for (int j = 0; j < cellsY; ++j) {
      for (int i = 0; i < cellsX; ++i) {
        const int ox = 15 * i, oy = 15 * j, oz = 15 * k;
        for (int z = 0; z < 14; ++z) {
          for (int y = 0; y < 14; ++y) {
            for (int x = 0; x < 14; ++x) {
              const bool wall = x == 0 || x == 13 || y == 0 || y == 13 || z == 0 || z == 13;
              const bool inner = x >= 3 && x <= 10 && y >= 3 && y <= 10 && z >= 3 && z <= 10;
              if (wall || inner) grid.setLabel(ox + x, oy + y, oz + z, wall ? 1 : label);
            }
          }
        }
        ++label;
        if (i + 1 < cellsX) grid.setLabel(ox + 14, oy + 7, oz + 7, 1);
        if (j + 1 < cellsY) grid.setLabel(ox + 7, oy + 14, oz + 7, 1);
        if (k + 1 < cellsZ) grid.setLabel(ox + 7, oy + 7, oz + 14, 1);
      }
    }
  }
  for (int k = 0; k < cellsZ; ++k) {
    for (int i = 0; i < cellsX; ++i) {
      for (int t = 0; t < topsPerCell; ++t)
        grid.setLabel(15 * i + 2 + 2 * t, grid.ny() - 1, 15 * k + 2 + 2 * (t % 5), label++);
    }
  }
  result.cells = cellsX * cellsY * cellsZ;
  result.tops = cellsX * cellsZ * topsPerCell;
  return result;
}

std::vector<int> range(int first, int count) {
  std::vector<int> values(count);
  for (int i = 0; i < count; ++i) values[i] = first + i;
  return values;
}

std::vector<int> removedParts(const DisassemblyPlan& plan) {
  std::vector<int> parts;
  for (const Removal& removal : plan.removals) parts.push_back(removal.part);
  return parts;
}

std::string pathText(const std::vector<Move>& path) {
  std::ostringstream out;
  for (const Move& move : path) {
    out << '(' << move.direction[0] << ' ' << move.direction[1] << ' ' << move.direction[2] << ")x" << move.steps
        << ' ';
  }
  return out.str();
}

// The plan the planner must reproduce: every remaining part searched again in every round
// (through the single-part check), the lowest id that can leave removed.
DisassemblyPlan planBySearchingEveryPart(const VoxelGrid& grid, int partCount) {
  VoxelGrid occupancy = grid;
  std::vector<bool> removed(partCount, false);
  DisassemblyPlan plan;
  for (int remaining = partCount; remaining > 1; --remaining) {
    bool progressed = false;
    for (int part = 0; part < partCount && !progressed; ++part) {
      if (removed[part]) continue;
      std::vector<Move> path;
      bool limit = false;
      if (!findVoxelRemovalPath(occupancy, part + 1, &path, {}, &limit)) {
        plan.searchLimitReached = plan.searchLimitReached || limit;
        continue;
      }
      plan.removals.push_back({part, path});
      removed[part] = true;
      for (int64_t i = 0; i < occupancy.voxelCount(); ++i) {
        if (occupancy.labelAt(i) == part + 1) occupancy.setLabelAt(i, 0);
      }
      progressed = true;
    }
    if (!progressed) {
      for (int part = 0; part < partCount; ++part) {
        if (!removed[part]) plan.stuck.push_back(part);
      }
      return plan;
    }
  }
  for (int part = 0; part < partCount; ++part) {
    if (!removed[part]) plan.removals.push_back({part, {}});
  }
  plan.complete = true;
  return plan;
}

void ExpectSamePlan(const DisassemblyPlan& expected, const DisassemblyPlan& actual, const std::string& name) {
  EXPECT_EQ(actual.complete, expected.complete) << name;
  EXPECT_EQ(actual.searchLimitReached, expected.searchLimitReached) << name;
  EXPECT_EQ(actual.stuck, expected.stuck) << name;
  ASSERT_EQ(removedParts(actual), removedParts(expected)) << name;
  for (size_t i = 0; i < expected.removals.size(); ++i) {
    EXPECT_EQ(pathText(actual.removals[i].path), pathText(expected.removals[i].path)) << name << " removal " << i;
  }
}

TEST(VoxelDisassemblyScale, SkippingUnchangedSearchesKeepsThePlanOfSearchingEveryPart) {
  for (const char* file :
       {"result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_4x4x4_K9_01.puz", "result_puz/Cube_Hollow_4x4x4_K7",
        "result_puz/cube_5x5x5_K16.puz", "result_puz/cartoon_dog.puz", "result_puz/bunny_15x14x11_K80.puz"}) {
    const AssemblyDocument document = testing::loadReference(file);
    ExpectSamePlan(planBySearchingEveryPart(document.voxels, document.assembly.partCount()),
                   singlePartPlan(document.voxels, document.assembly), file);
  }
  const SealedCells small = sealedCells(2, 2, 2, 2);
  const AssemblyDocument document = documentFromVoxels(small.grid);
  ExpectSamePlan(planBySearchingEveryPart(small.grid, document.assembly.partCount()),
                 singlePartPlan(document.voxels, document.assembly), "sealed cells 2x2x2");
}

TEST(VoxelDisassemblyScale, SealedCellsAreSearchedOncePerPartNotOncePerRound) {
  const SealedCells puzzle = sealedCells(3, 3, 3, 3);
  const AssemblyDocument document = documentFromVoxels(puzzle.grid);
  const int parts = document.assembly.partCount();
  ASSERT_EQ(parts, 1 + puzzle.cells + puzzle.tops);  // 55
  const DisassemblyPlan plan = singlePartPlan(document.voxels, document.assembly);
  // The loose voxels leave in id order, straight up; the container and the parts sealed in it
  // are proven stuck (every search ran out of offsets, none stopped at a limit).
  EXPECT_FALSE(plan.complete);
  EXPECT_FALSE(plan.searchLimitReached);
  EXPECT_EQ(removedParts(plan), range(1 + puzzle.cells, puzzle.tops));
  for (const Removal& removal : plan.removals) EXPECT_EQ(pathText(removal.path), "(0 1 0)x1 ") << removal.part;
  EXPECT_EQ(plan.stuck, range(0, 1 + puzzle.cells));
  // Searching every part every round takes 27 rounds of 29 searches and a last round of 28: 811,
  // 15 per part. Each part is searched about once here.
  EXPECT_LE(plan.searches, 2 * parts);
  EXPECT_GE(plan.searches, parts);

  // Voxel tests grow with the puzzle, not with its square: 27 cells against 8 cost about 27/8 as
  // much (the quadratic planner: about (27/8)^2).
  const SealedCells smaller = sealedCells(2, 2, 2, 3);
  const AssemblyDocument smallerDocument = documentFromVoxels(smaller.grid);
  const DisassemblyPlan smallerPlan = singlePartPlan(smallerDocument.voxels, smallerDocument.assembly);
  EXPECT_FALSE(smallerPlan.searchLimitReached);
  EXPECT_EQ(smallerPlan.stuck, range(0, 1 + smaller.cells));
  EXPECT_LE(plan.voxelTests * smaller.cells, 3 * puzzle.cells * smallerPlan.voxelTests / 2)
      << plan.voxelTests << " voxel tests for " << puzzle.cells << " cells, " << smallerPlan.voxelTests << " for "
      << smaller.cells;
}

TEST(VoxelDisassemblyScale, PlanBudgetStopsWithoutClaimingPartsStuck) {
  const SealedCells puzzle = sealedCells(3, 3, 3, 3);
  const AssemblyDocument document = documentFromVoxels(puzzle.grid);
  const int parts = document.assembly.partCount();
  VoxelDisassemblyOptions tiny;
  tiny.maxTotalVoxelTests = 1000;
  const DisassemblyPlan plan = singlePartPlan(document.voxels, document.assembly, tiny);
  // The container's search (the first) uses the budget up: nothing is removed, and every part is
  // left, the loose voxels on top too, although each could leave: the flag says "not proven".
  EXPECT_FALSE(plan.complete);
  EXPECT_TRUE(plan.searchLimitReached);
  EXPECT_TRUE(plan.removals.empty());
  EXPECT_EQ(plan.stuck, range(0, parts));
  EXPECT_EQ(plan.searches, 1);
  // The budget is checked between search steps, so it is overrun by at most one step's sweeps.
  EXPECT_LT(plan.voxelTests, 100'000);

  // Half the work of the full plan: a prefix of its removals, the rest listed but not proven.
  const DisassemblyPlan full = singlePartPlan(document.voxels, document.assembly);
  VoxelDisassemblyOptions half;
  half.maxTotalVoxelTests = full.voxelTests / 2;
  const DisassemblyPlan cut = singlePartPlan(document.voxels, document.assembly, half);
  EXPECT_FALSE(cut.complete);
  EXPECT_TRUE(cut.searchLimitReached);
  const std::vector<int> fullOrder = removedParts(full), cutOrder = removedParts(cut);
  ASSERT_LE(cutOrder.size(), fullOrder.size());
  EXPECT_EQ(cutOrder, std::vector<int>(fullOrder.begin(), fullOrder.begin() + cutOrder.size()));
  EXPECT_EQ(cut.removals.size() + cut.stuck.size(), static_cast<size_t>(parts));
}

TEST(VoxelDisassemblyScale, SinglePartCheckStaysWithinTheBudget) {
  // The designer's per-candidate check (requirement (iii), Section 4.3) searches once; the plan
  // budget bounds it as well as the per-search limit.
  const SealedCells puzzle = sealedCells(2, 2, 2, 1);
  std::vector<Move> path;
  bool limit = true;
  EXPECT_FALSE(findVoxelRemovalPath(puzzle.grid, 2, &path, {}, &limit));  // a sealed part: proven stuck
  EXPECT_FALSE(limit);
  VoxelDisassemblyOptions tiny;
  tiny.maxTotalVoxelTests = 1000;
  EXPECT_FALSE(findVoxelRemovalPath(puzzle.grid, 1, &path, tiny, &limit));  // the container: not proven
  EXPECT_TRUE(limit);
  EXPECT_TRUE(findVoxelRemovalPath(puzzle.grid, 10, &path, tiny, &limit));  // a loose voxel on top
  EXPECT_FALSE(limit);
}

}  // namespace
}  // namespace desia
