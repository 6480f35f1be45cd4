// SPDX-License-Identifier: GPL-3.0-or-later
// The per-node incremental checks and ranking of the voxel designer (split_evaluation.h) agree,
// to the bit, with the whole-grid functions on the split grid, for random parts taken out of the
// remainder of real construction-tree nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "desia/voxel.h"
#include "voxel/candidate_checks.h"
#include "voxel/design_internals.h"
#include "voxel/split_evaluation.h"

namespace desia {
namespace {

using design::Candidate;

VoxelGrid solidCube(int side) {
  VoxelGrid cube(side, side, side);
  for (int64_t i = 0; i < cube.voxelCount(); ++i) cube.setLabelAt(i, 1);
  return cube;
}

// A node of the construction tree with `parts` parts placed (remainder label parts + 1).
VoxelGrid nodeWithParts(const VoxelGrid& shape, int totalParts, int parts, uint64_t seed) {
  VoxelDesignOptions options;
  options.parts = totalParts;
  options.seed = seed;
  VoxelDesignSession session(shape, options);
  for (int k = 0; k < parts; ++k) EXPECT_TRUE(session.generateNextPart());
  return session.current();
}

// A random set of remainder voxels: grown face to face from a random voxel (mostly), or scattered.
std::vector<int64_t> randomPart(const VoxelGrid& grid, int remainder, std::mt19937_64& random) {
  std::vector<int64_t> rest;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == remainder) rest.push_back(i);
  }
  const size_t size = 1 + random() % std::min<size_t>(rest.size(), 24);
  std::vector<int64_t> part{rest[random() % rest.size()]};
  const design::GridSteps steps(grid);
  const bool scattered = random() % 5 == 0;
  while (part.size() < size) {
    int64_t next = -1;
    if (scattered) {
      next = rest[random() % rest.size()];
    } else {
      const int64_t from = part[random() % part.size()];
      next = steps.neighbour(from, static_cast<int>(random() % 6));
      if (next >= 0 && grid.labelAt(next) != remainder) next = -1;
    }
    if (next >= 0 && std::find(part.begin(), part.end(), next) == part.end()) part.push_back(next);
    if (scattered && part.size() >= rest.size()) break;
  }
  std::sort(part.begin(), part.end());
  return part;
}

double compactnessSum(const VoxelGrid& split, int label) {
  double sum = 0;
  for (double a : design::accessibility(split, label)) sum += a;
  return sum;
}

void ExpectSameContacts(const Assembly& actual, const Assembly& expected) {
  ASSERT_EQ(actual.partCount(), expected.partCount());
  ASSERT_EQ(actual.contacts.size(), expected.contacts.size());
  for (size_t k = 0; k < expected.contacts.size(); ++k) {
    const Contact& a = actual.contacts[k];
    const Contact& e = expected.contacts[k];
    EXPECT_EQ(a.a, e.a) << k;
    EXPECT_EQ(a.b, e.b) << k;
    EXPECT_EQ(a.normal, e.normal) << k;
    EXPECT_EQ(a.area, e.area) << k;
  }
}

// The face-connected pieces of `label` in `grid`, each a sorted voxel list (an independent
// whole-grid flood fill).
std::vector<std::vector<int64_t>> piecesOf(const VoxelGrid& grid, int label) {
  std::vector<std::vector<int64_t>> pieces;
  std::vector<bool> seen(static_cast<size_t>(grid.voxelCount()), false);
  for (int64_t start = 0; start < grid.voxelCount(); ++start) {
    if (seen[start] || grid.labelAt(start) != label) continue;
    std::vector<int64_t> piece, stack{start};
    seen[start] = true;
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      piece.push_back(v);
      const Int3 c = grid.coordinates(v);
      for (const Int3& d : design::kAxisSteps) {
        const Int3 n{c.x + d.x, c.y + d.y, c.z + d.z};
        if (!grid.inside(n.x, n.y, n.z)) continue;
        const int64_t w = grid.index(n.x, n.y, n.z);
        if (seen[w] || grid.labelAt(w) != label) continue;
        seen[w] = true;
        stack.push_back(w);
      }
    }
    std::sort(piece.begin(), piece.end());
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// piecesCutOff against the pieces of the split grid's rest (label `rest`): nothing when the rest is
// one piece; otherwise, given room for the whole rest, every piece but one, whole.
void ExpectPiecesCutOffAreWholePieces(const VoxelGrid& split, int rest, design::RemainderConnectivity& connectivity,
                                      const std::vector<int64_t>& part) {
  const std::vector<std::vector<int64_t>> pieces = piecesOf(split, rest);
  const auto cut = connectivity.piecesCutOff(part, static_cast<size_t>(split.voxelCount()));
  if (pieces.empty()) {
    EXPECT_FALSE(cut.has_value());  // the part takes all of R
    return;
  }
  ASSERT_TRUE(cut.has_value());
  std::vector<int64_t> sortedCut = *cut;
  std::sort(sortedCut.begin(), sortedCut.end());
  size_t kept = 0;
  std::vector<int64_t> expected;
  for (const auto& piece : pieces) {
    const bool inCut = std::binary_search(sortedCut.begin(), sortedCut.end(), piece.front());
    if (!inCut) ++kept;
    if (inCut) expected.insert(expected.end(), piece.begin(), piece.end());
  }
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(kept, 1u);
  EXPECT_EQ(sortedCut, expected);
  if (pieces.size() == 1) {
    EXPECT_TRUE(sortedCut.empty());
  }
}

struct NodeCase {
  int side, totalParts, placed;
  uint64_t seed;
};

class SplitEvaluation : public ::testing::TestWithParam<NodeCase> {};

TEST_P(SplitEvaluation, AgreesWithTheWholeGridFunctionsOnRandomParts) {
  const NodeCase c = GetParam();
  const VoxelGrid grid = nodeWithParts(solidCube(c.side), c.totalParts, c.placed, c.seed);
  const int remainder = c.placed + 1;
  ASSERT_EQ(grid.maxLabel(), remainder);
  design::IncrementalAccessibility accessibility(grid, remainder);
  EXPECT_EQ(accessibility.values(), design::accessibility(grid, remainder));
  design::SplitAssembly assembly(grid, remainder);
  design::RemainderConnectivity connectivity(grid, remainder);
  const design::GridSteps steps(grid);
  std::mt19937_64 random(c.seed * 7 + 1);
  int connectedRests = 0, accepted = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Candidate candidate{randomPart(grid, remainder, random), 0};
    VoxelGrid split = grid;
    design::applyCandidate(split, remainder, candidate);
    const bool restConnected = design::isFaceConnected(split, remainder + 1);
    connectedRests += restConnected ? 1 : 0;
    EXPECT_EQ(connectivity.connectedWithout(candidate.partVoxels), restConnected) << trial;
    ExpectPiecesCutOffAreWholePieces(split, remainder + 1, connectivity, candidate.partVoxels);
    EXPECT_EQ(design::isListFaceConnected(steps, candidate.partVoxels), design::isFaceConnected(split, remainder));
    EXPECT_EQ(accessibility.sumWithout(candidate.partVoxels), compactnessSum(split, remainder + 1)) << trial;
    if (restConnected) ExpectSameContacts(assembly.assemblyAfter(candidate.partVoxels), assemblyFromVoxels(split));
    for (CandidateRanking ranking :
         {CandidateRanking::Compactness, CandidateRanking::HighestX, CandidateRanking::LowestZ}) {
      design::SplitEvaluator evaluator(grid, remainder, Int3{0, 1, 0}, ranking);
      const bool accepts = design::acceptsSplit(split, remainder, Int3{0, 1, 0});
      EXPECT_EQ(evaluator.accepts(candidate), accepts) << trial;
      accepted += accepts ? 1 : 0;
      EXPECT_EQ(evaluator.rankKey(candidate), design::rankingKey(split, remainder, remainder + 1, ranking)) << trial;
    }
  }
  EXPECT_GT(connectedRests, 0);  // the random parts exercise both answers
  EXPECT_LT(connectedRests, 150);
}

INSTANTIATE_TEST_SUITE_P(Nodes, SplitEvaluation,
                         ::testing::Values(NodeCase{6, 12, 0, 1}, NodeCase{6, 12, 1, 2}, NodeCase{7, 20, 6, 3},
                                           NodeCase{8, 30, 14, 4}));

TEST(SplitEvaluation, PiecesCutOffAreReturnedOnlyWhenTheyFit) {
  // A row of seven remainder voxels; the part at x = 1 cuts off x = 0, the part at x = 2 cuts off
  // x = 0..1, the part at x = 3 leaves two pieces of three.
  VoxelGrid grid(7, 1, 1);
  for (int64_t i = 0; i < 7; ++i) grid.setLabelAt(i, 1);
  design::RemainderConnectivity connectivity(grid, 1);
  EXPECT_EQ(connectivity.piecesCutOff({1}, 1), (std::vector<int64_t>{0}));
  EXPECT_FALSE(connectivity.piecesCutOff({1}, 0).has_value());
  EXPECT_FALSE(connectivity.piecesCutOff({2}, 1).has_value());
  auto two = connectivity.piecesCutOff({2}, 2);
  ASSERT_TRUE(two.has_value());
  std::sort(two->begin(), two->end());
  EXPECT_EQ(*two, (std::vector<int64_t>{0, 1}));
  EXPECT_EQ(connectivity.piecesCutOff({3}, 3)->size(), 3u);
  EXPECT_EQ(connectivity.piecesCutOff({0}, 0), (std::vector<int64_t>{}));  // the rest stays whole
  EXPECT_FALSE(connectivity.piecesCutOff({0, 1, 2, 3, 4, 5, 6}, 7).has_value());
  // The checks still agree after these calls (scratch state cleared).
  EXPECT_TRUE(connectivity.connectedWithout({6}));
  EXPECT_FALSE(connectivity.connectedWithout({5}));
}

TEST(SplitEvaluation, FallsBackToTheWholeGridWhereTheRemainderIsNotTheLastLabel) {
  // Remainder 1 in two pieces, with a part 2 beyond it: the local checks do not apply.
  VoxelGrid grid(5, 1, 1);
  const int labels[5] = {1, 1, 2, 1, 1};
  for (int64_t i = 0; i < 5; ++i) grid.setLabelAt(i, labels[i]);
  design::SplitEvaluator evaluator(grid, 1, Int3{1, 0, 0}, CandidateRanking::Compactness);
  const Candidate candidate{{0}, 0};
  VoxelGrid split = grid;
  design::applyCandidate(split, 1, candidate);
  EXPECT_EQ(evaluator.accepts(candidate), design::acceptsSplit(split, 1, Int3{1, 0, 0}));
  EXPECT_EQ(evaluator.rankKey(candidate), design::rankingKey(split, 1, 2, CandidateRanking::Compactness));
}

// The breadth-first searches PartBuilder used before its searches were aimed at their targets
// (issue 10), on a copy of the builder's states: the reference for the connection and the
// look-ahead. States: 0 other, 1 free, 2 part, 3 forced remainder.
struct ReferenceBuilder {
  const VoxelGrid& grid;
  std::vector<int> state;
  std::vector<int64_t> forced;

  bool passable(int64_t v) const { return v >= 0 && (state[v] == 1 || state[v] == 2); }

  bool forcedConnectable() const {
    std::vector<bool> seen(state.size(), false);
    std::vector<int64_t> queue{forced[0]};
    seen[forced[0]] = true;
    for (size_t head = 0; head < queue.size(); ++head) {
      for (const Int3& step : design::kAxisSteps) {
        const int64_t w = design::neighbourIndex(grid, queue[head], step);
        if (!passable(w) || seen[w]) continue;
        seen[w] = true;
        queue.push_back(w);
      }
    }
    for (int64_t v : forced) {
      if (!seen[v]) return false;
    }
    return true;
  }

  // connect() as it was: flood the first forced voxel's part piece, then breadth-first from the
  // whole piece to each forced voxel not in it, taking the first path found.
  bool connect() {
    std::vector<bool> connected(state.size(), false);
    std::vector<int64_t> component;
    auto flood = [&](int64_t from) {
      if (connected[from]) return;
      std::vector<int64_t> stack{from};
      connected[from] = true;
      while (!stack.empty()) {
        const int64_t v = stack.back();
        stack.pop_back();
        component.push_back(v);
        for (const Int3& step : design::kAxisSteps) {
          const int64_t w = design::neighbourIndex(grid, v, step);
          if (w < 0 || connected[w] || state[w] != 2) continue;
          connected[w] = true;
          stack.push_back(w);
        }
      }
    };
    auto reach = [&](int64_t target) {
      std::vector<int64_t> cameFrom(state.size(), -2);
      std::vector<int64_t> queue(component.begin(), component.end());
      for (int64_t v : component) cameFrom[v] = -1;
      for (size_t head = 0; head < queue.size(); ++head) {
        for (const Int3& step : design::kAxisSteps) {
          const int64_t w = design::neighbourIndex(grid, queue[head], step);
          if (!passable(w) || cameFrom[w] != -2) continue;
          cameFrom[w] = queue[head];
          queue.push_back(w);
          if (w != target) continue;
          for (int64_t v = target; cameFrom[v] >= 0; v = cameFrom[v]) state[v] = 2;
          return true;
        }
      }
      return false;
    };
    flood(forced[0]);
    for (size_t k = 1; k < forced.size(); ++k) {
      if (connected[forced[k]]) continue;
      if (!reach(forced[k])) return false;
      flood(forced[k]);
    }
    return true;
  }

  std::vector<int64_t> partVoxels() const {
    std::vector<int64_t> part;
    for (size_t v = 0; v < state.size(); ++v) {
      if (state[v] == 2) part.push_back(static_cast<int64_t>(v));
    }
    return part;
  }
};

TEST(PartBuilderSearches, AgreeWithTheWholeBreadthFirstSearchesOnRandomForcings) {
  VoxelDesignOptions options;
  options.parts = 3;
  std::mt19937_64 random(11);
  int connectedCases = 0, failedCases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    VoxelGrid grid(9, 8, 7);
    for (int64_t i = 0; i < grid.voxelCount(); ++i) grid.setLabelAt(i, random() % 10 < 7 ? 1 : 2);
    design::DesignContext context{options, {}, {}, grid.voxelCount(), std::mt19937_64(1)};
    const std::vector<double> access = design::accessibility(grid, 1);
    design::PartBuilder builder(grid, 1, context, access);
    ReferenceBuilder reference{grid, std::vector<int>(static_cast<size_t>(grid.voxelCount()), 0), {}};
    for (int64_t i = 0; i < grid.voxelCount(); ++i) reference.state[i] = grid.labelAt(i) == 1 ? 1 : 0;
    const int forcedParts = 2 + static_cast<int>(random() % 5), forcedRests = static_cast<int>(random() % 400);
    for (int k = 0; k < forcedRests; ++k) {
      const int64_t v = static_cast<int64_t>(random() % grid.voxelCount());
      if (builder.forceRemainder(v)) reference.state[v] = 3;
    }
    for (int k = 0; k < forcedParts; ++k) {
      const int64_t v = static_cast<int64_t>(random() % grid.voxelCount());
      if (!builder.forcePart(v)) continue;
      reference.state[v] = 2;
      reference.forced.push_back(v);
    }
    if (reference.forced.empty()) continue;
    const bool connectable = reference.forcedConnectable();
    EXPECT_EQ(builder.forcedPartConnectable(), connectable) << trial;
    EXPECT_EQ(builder.connect(), reference.connect()) << trial;
    EXPECT_EQ(builder.sortedPartVoxels(), reference.partVoxels()) << trial;  // the same paths
    (connectable ? connectedCases : failedCases) += 1;
  }
  EXPECT_GT(connectedCases, 50);
  EXPECT_GT(failedCases, 10);
}

}  // namespace
}  // namespace desia
