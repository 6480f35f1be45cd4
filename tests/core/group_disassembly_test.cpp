// SPDX-License-Identifier: GPL-3.0-or-later
// The complete disassembler (moves of several parts, the level): judged by BurrTools' own
// solutions and levels (tests/data/burrtools, converted from BurrTools' examples), by mazes whose
// level is known by construction, by an independent brute-force search over every set of parts,
// and by replaying every plan voxel by voxel with code that does not share the planner's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "desia/formats.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

using Cell = std::array<int, 3>;

VoxelGrid loadPuz(const std::string& relative) {
  return parsePuz(testing::readFileText(testing::projectPath(relative)), relative);
}

DisassemblyPlan plan(const VoxelGrid& grid, const VoxelDisassemblyOptions& options = {}) {
  return planVoxelDisassembly(grid, assemblyFromVoxels(grid), options);
}

// Part 1, one voxel, at the start of a serpentine tunnel through part 2 (a box, the tunnel in its
// middle layer): rows along x joined by steps of two along y, with walls between the rows, so the
// only way out turns at every corner. `runs` straight runs, the last one leaving the box: the
// level is `runs` by construction.
VoxelGrid serpentineMaze(int runs) {
  const int rows = (runs + 1) / 2;
  const int nx = 6, ny = 2 * rows + 1, nz = 3;
  VoxelGrid grid(nx, ny, nz);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) grid.setLabelAt(i, 2);
  Cell at{1, 1, 1};
  std::vector<Cell> tunnel{at};
  for (int run = 0; run < runs; ++run) {
    const bool row = run % 2 == 0;
    const Cell step = row ? Cell{(run / 2) % 2 == 0 ? 1 : -1, 0, 0} : Cell{0, 1, 0};
    const bool last = run + 1 == runs;
    for (int k = 0; last ? grid.inside(at[0] + step[0], at[1] + step[1], at[2]) : k < (row ? 3 : 2); ++k) {
      at = {at[0] + step[0], at[1] + step[1], at[2]};
      tunnel.push_back(at);
    }
  }
  for (const Cell& c : tunnel) grid.setLabel(c[0], c[1], c[2], 0);
  grid.setLabel(1, 1, 1, 1);
  return grid;
}

// The grid turned by a quarter turn about `axis`, `turns` times (a rigid rotation of the puzzle).
VoxelGrid quarterTurned(const VoxelGrid& grid, int axis, int turns) {
  VoxelGrid current = grid;
  for (int t = 0; t < turns; ++t) {
    const int n[3] = {current.nx(), current.ny(), current.nz()};
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // (u, v) -> (v', u') = (n_v - 1 - v, u)
    int size[3] = {n[0], n[1], n[2]};
    std::swap(size[u], size[v]);
    VoxelGrid next(size[0], size[1], size[2]);
    for (int z = 0; z < n[2]; ++z) {
      for (int y = 0; y < n[1]; ++y) {
        for (int x = 0; x < n[0]; ++x) {
          const int c[3] = {x, y, z};
          int d[3] = {x, y, z};
          d[u] = n[v] - 1 - c[v];
          d[v] = c[u];
          next.setLabel(d[0], d[1], d[2], current.label(x, y, z));
        }
      }
    }
    current = next;
  }
  return current;
}

// The fewest moves before the first separation, by breadth-first search over the positions of
// the parts where a move is ANY set of parts (every subset, not closures) slid unit by unit along
// an axis, tested against the other parts' voxels as sets of cells. Exponential in the parts:
// for small puzzles only. Returns 0 when no separation exists within `maxDepth` moves.
int bruteForceFirstSeparation(const VoxelGrid& grid, int maxDepth) {
  const int parts = grid.maxLabel();
  const std::vector<std::vector<Cell>> cells = testing::partCells(grid);
  using Position = std::vector<Cell>;  // offset of each part; part 1 stays at the origin
  std::map<Position, int> depth;
  std::vector<Position> frontier{Position(static_cast<size_t>(parts), Cell{0, 0, 0})};
  depth[frontier[0]] = 0;
  for (int d = 0; d < maxDepth && !frontier.empty(); ++d) {
    std::vector<Position> next;
    for (const Position& position : frontier) {
      for (uint32_t set = 1; set < (1u << parts); set += 2) {  // sets without part 1, which stays (the other side moves)
        if (set == (1u << parts) - 1) continue;
        const uint32_t moving = ~set & ((1u << parts) - 1);
        std::set<Cell> still;
        int stillMin[3] = {1 << 20, 1 << 20, 1 << 20}, stillMax[3] = {-(1 << 20), -(1 << 20), -(1 << 20)};
        for (int p = 0; p < parts; ++p) {
          if (moving & (1u << p)) continue;
          for (const Cell& c : cells[static_cast<size_t>(p)]) {
            const Cell at{c[0] + position[p][0], c[1] + position[p][1], c[2] + position[p][2]};
            still.insert(at);
            for (int a = 0; a < 3; ++a) stillMin[a] = std::min(stillMin[a], at[a]), stillMax[a] = std::max(stillMax[a], at[a]);
          }
        }
        for (int axis = 0; axis < 3; ++axis) {
          for (int sign : {1, -1}) {
            for (int amount = 1;; ++amount) {
              bool hit = false, past = true;
              for (int p = 0; p < parts && !hit; ++p) {
                if (!(moving & (1u << p))) continue;
                for (const Cell& c : cells[static_cast<size_t>(p)]) {
                  Cell at{c[0] + position[p][0], c[1] + position[p][1], c[2] + position[p][2]};
                  at[axis] += sign * amount;
                  if (still.count(at)) {
                    hit = true;
                    break;
                  }
                  if (sign > 0 ? at[axis] <= stillMax[axis] : at[axis] >= stillMin[axis]) past = false;
                }
              }
              if (hit) break;
              if (past) return d + 1;
              Position moved = position;
              for (int p = 0; p < parts; ++p) {
                if (moving & (1u << p)) moved[p][axis] += sign * amount;
              }
              if (depth.emplace(moved, d + 1).second) next.push_back(moved);
            }
          }
        }
      }
    }
    frontier.swap(next);
  }
  return 0;
}

TEST(GroupDisassembly, AMazeTakesOneMovePerStraightRunOfItsTunnel) {
  for (int runs = 1; runs <= 12; ++runs) {
    SCOPED_TRACE("runs " + std::to_string(runs));
    const VoxelGrid maze = serpentineMaze(runs);
    const DisassemblyPlan result = plan(maze);
    ASSERT_TRUE(result.complete);
    EXPECT_EQ(result.level, std::vector<int>{runs});
    EXPECT_TRUE(result.levelMinimal);
    EXPECT_EQ(result.moves.size(), static_cast<size_t>(runs));
    EXPECT_EQ(testing::replayVoxelMoves(maze, result.moves, true), "");
    EXPECT_EQ(bruteForceFirstSeparation(maze, runs + 1), runs);
    // The single-part plan found the same way out (a bent path), kept as order and paths.
    EXPECT_TRUE(result.singlePartPaths);
    EXPECT_EQ(testing::verifyPlan(maze, assemblyFromVoxels(maze), result), "");
  }
}

struct BurrToolsSolution {
  std::string file, example;
  std::vector<int> level;
  int moves = 0, pieces = 0;
  bool complete = true;
};

std::vector<BurrToolsSolution> burrToolsSolutions() {
  const auto root = nlohmann::json::parse(testing::readFileText(testing::projectPath("tests/data/burrtools/levels.json")));
  std::vector<BurrToolsSolution> solutions;
  for (const auto& entry : root.at("solutions")) {
    solutions.push_back({entry.at("file"), entry.at("example"), entry.at("level").get<std::vector<int>>(),
                         entry.at("moves").get<int>(), entry.at("pieces").get<int>(), entry.at("complete").get<bool>()});
  }
  return solutions;
}

TEST(GroupDisassembly, BurrToolsOwnSolutionsGetBurrToolsLevels) {
  const std::vector<BurrToolsSolution> solutions = burrToolsSolutions();
  ASSERT_EQ(solutions.size(), 44u);
  int highest = 0;
  for (const BurrToolsSolution& expected : solutions) {
    SCOPED_TRACE(expected.file);
    const VoxelGrid grid = loadPuz("tests/data/burrtools/" + expected.file);
    ASSERT_EQ(grid.maxLabel(), expected.pieces);
    const DisassemblyPlan result = plan(grid);
    EXPECT_EQ(result.complete, expected.complete);
    EXPECT_FALSE(result.searchLimitReached);
    ASSERT_FALSE(result.level.empty());
    // The fewest moves before the first separation: BurrTools' breadth-first search and ours agree.
    EXPECT_EQ(result.level[0], expected.level[0]);
    highest = std::max(highest, result.level[0]);
    // Below the first separation, where several separations take equally few moves, BurrTools
    // takes the first its move order meets and so may we not: the two large puzzles with such a
    // choice get the same first level and as many moves give or take a few.
    if (expected.example == "PelikanBurr.xmpuzzle" || expected.example == "DraculasDentalDesaster.xmpuzzle") {
      EXPECT_NEAR(static_cast<double>(result.moves.size()), expected.moves, 0.05 * expected.moves);
    } else {
      EXPECT_EQ(result.level, expected.level);
      EXPECT_EQ(result.moves.size(), static_cast<size_t>(expected.moves));
    }
    EXPECT_EQ(testing::replayVoxelMoves(grid, result.moves, expected.complete), "");
    // Small ones: an independent search over every set of parts finds the same fewest moves.
    if (expected.pieces <= 6 && expected.level[0] <= 2) {
      EXPECT_EQ(bruteForceFirstSeparation(grid, expected.level[0] + 1), expected.level[0]);
    }
  }
  EXPECT_EQ(highest, 98);  // PelikanBurr
}

TEST(GroupDisassembly, TheLevelDoesNotDependOnHowThePuzzleIsTurned) {
  for (const std::string file : {"tests/data/burrtools/SolidSixPieceBurrs-p0-s257.puz",
                                 "tests/data/burrtools/CubeInCage-p0-s0.puz", "tests/data/burrtools/PelikanBurr-p0-s0.puz"}) {
    SCOPED_TRACE(file);
    const VoxelGrid grid = loadPuz(file);
    const DisassemblyPlan original = plan(grid);
    for (int axis = 0; axis < 3; ++axis) {
      for (int turns = 1; turns <= 3; turns += 2) {
        const VoxelGrid turned = quarterTurned(grid, axis, turns);
        const DisassemblyPlan result = plan(turned);
        EXPECT_EQ(result.complete, original.complete);
        ASSERT_FALSE(result.level.empty());
        EXPECT_EQ(result.level[0], original.level[0]) << "axis " << axis << ", " << turns << " quarter turns";
        EXPECT_EQ(testing::replayVoxelMoves(turned, result.moves, result.complete), "");
      }
    }
  }
}

TEST(GroupDisassembly, AnAssemblyThatCannotComeApartIsProvenStuck) {
  // BurrTools leaves CubeInCage's three cage pieces together (they are one group there): no move
  // of any set of them separates anything, and the search says so without reaching a limit.
  const VoxelGrid grid = loadPuz("tests/data/burrtools/CubeInCage-p0-s0.puz");
  const DisassemblyPlan result = plan(grid);
  EXPECT_FALSE(result.complete);
  EXPECT_FALSE(result.searchLimitReached);
  EXPECT_EQ(result.unseparated, (std::vector<std::vector<int>>{{0, 1, 2}}));
  EXPECT_EQ(result.stuck, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(result.level, (std::vector<int>{4, 9, 3}));
}

TEST(GroupDisassembly, ASearchStoppedAtItsBoundSaysSoAndNeverClaimsAPlan) {
  const VoxelGrid grid = loadPuz("tests/data/burrtools/PelikanBurr-p0-s0.puz");
  VoxelDisassemblyOptions tight;
  tight.maxGroupStates = 1000;
  const DisassemblyPlan result = plan(grid, tight);
  EXPECT_FALSE(result.complete);
  EXPECT_TRUE(result.searchLimitReached);
  EXPECT_NE(result.limit.find("maxGroupStates"), std::string::npos) << result.limit;
  EXPECT_EQ(result.unseparated.size(), 1u);
  EXPECT_EQ(result.unseparated[0].size(), 7u);
  EXPECT_EQ(testing::replayVoxelMoves(grid, result.moves, false), "");

  VoxelDisassemblyOptions small;
  small.maxGroupBytes = 64 << 10;
  const DisassemblyPlan bounded = plan(grid, small);
  EXPECT_FALSE(bounded.complete);
  EXPECT_NE(bounded.limit.find("MiB of positions"), std::string::npos) << bounded.limit;
}

// A closed box holding m single voxels, each in a cell of its own two voxels long: every voxel
// slides on its own, so 2^m - 1 sets move alike at every position. Nothing can come out.
VoxelGrid voxelsInCells(int m) {
  VoxelGrid grid(3 * m + 1, 3, 3);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) grid.setLabelAt(i, 1);
  for (int k = 0; k < m; ++k) {
    grid.setLabel(3 * k + 1, 1, 1, k + 2);
    grid.setLabel(3 * k + 2, 1, 1, 0);
  }
  return grid;
}

TEST(GroupDisassembly, ManyIndependentPartsStopAtTheWorkBoundNotAtTheUsersPatience) {
  // Small: the whole search runs and proves the parts stuck.
  const DisassemblyPlan small = plan(voxelsInCells(4));
  EXPECT_FALSE(small.complete);
  EXPECT_FALSE(small.searchLimitReached);
  EXPECT_EQ(small.unseparated.size(), 1u);
  // Eight voxels: 255 sets move alike; the work bound (here a small one) stops it and says so.
  VoxelDisassemblyOptions bounded;
  bounded.maxGroupWork = 20'000'000;
  const DisassemblyPlan large = plan(voxelsInCells(8), bounded);
  EXPECT_FALSE(large.complete);
  EXPECT_TRUE(large.searchLimitReached);
  EXPECT_NE(large.limit.find("maxGroupWork"), std::string::npos) << large.limit;
  EXPECT_EQ(large.stuck.size(), 9u);
}

TEST(GroupDisassembly, ThePapersPuzzlesKeepTheirSinglePartPlanAndAreLevelOne) {
  for (const std::string file : {"result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_4x4x4_K9_01.puz",
                                 "result_puz/Cube_Hollow_4x4x4_K7", "result_puz/cube_5x5x5_K16.puz",
                                 "result_puz/cartoon_dog.puz", "result_puz/bunny_15x14x11_K80.puz"}) {
    SCOPED_TRACE(file);
    const AssemblyDocument document = testing::loadReference(file);
    VoxelDisassemblyOptions singleParts;
    singleParts.groupMoves = false;
    const DisassemblyPlan before = planVoxelDisassembly(document.voxels, document.assembly, singleParts);
    const DisassemblyPlan result = planVoxelDisassembly(document.voxels, document.assembly);
    ASSERT_TRUE(result.complete);
    ASSERT_FALSE(result.level.empty());
    EXPECT_EQ(result.level[0], 1);  // the key comes out in one move (paper Section 3.3)
    EXPECT_TRUE(result.levelMinimal);
    ASSERT_TRUE(result.singlePartPaths);
    ASSERT_EQ(result.removals.size(), before.removals.size());
    for (size_t r = 0; r < before.removals.size(); ++r) EXPECT_EQ(result.removals[r].part, before.removals[r].part);
    EXPECT_EQ(testing::verifyPlan(document.voxels, document.assembly, result), "");
  }
}

TEST(GroupDisassembly, TheDesignersCheckLeavesMovesOfSeveralPartsAlone) {
  const VoxelGrid maze = serpentineMaze(4);
  VoxelDisassemblyOptions singleParts;
  singleParts.groupMoves = false;
  const DisassemblyPlan result = plan(maze, singleParts);
  EXPECT_TRUE(result.complete);
  EXPECT_TRUE(result.level.empty());  // a bent single-part plan: its level is not claimed
  EXPECT_EQ(result.groupStates, 0);
}

TEST(GroupDisassembly, TheReplayRefusesTamperedPlans) {
  const VoxelGrid grid = loadPuz("tests/data/burrtools/PelikanBurr-p0-s0.puz");
  const DisassemblyPlan result = plan(grid);
  ASSERT_TRUE(result.complete);
  ASSERT_EQ(testing::replayVoxelMoves(grid, result.moves, true), "");

  std::vector<GroupMove> reversed = result.moves;
  for (int a = 0; a < 3; ++a) reversed[0].direction[a] = -reversed[0].direction[a];
  EXPECT_NE(testing::replayVoxelMoves(grid, reversed, true), "");

  std::vector<GroupMove> skipped(result.moves.begin() + 1, result.moves.end());
  EXPECT_NE(testing::replayVoxelMoves(grid, skipped, true), "");

  std::vector<GroupMove> swapped = result.moves;  // parts 1 and 2 exchanged everywhere
  for (GroupMove& move : swapped) {
    for (int& part : move.parts) part = part == 0 ? 1 : part == 1 ? 0 : part;
  }
  EXPECT_NE(testing::replayVoxelMoves(grid, swapped, true), "");

  std::vector<GroupMove> longer = result.moves;
  for (GroupMove& move : longer) {
    if (!move.out) {
      move.steps += 1;
      break;
    }
  }
  EXPECT_NE(testing::replayVoxelMoves(grid, longer, true), "");

  std::vector<GroupMove> truncated(result.moves.begin(), result.moves.end() - 1);
  EXPECT_NE(testing::replayVoxelMoves(grid, truncated, true), "");
}

}  // namespace
}  // namespace desia
