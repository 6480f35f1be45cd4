// SPDX-License-Identifier: GPL-3.0-or-later
// The per-node incremental checks and ranking of the voxel designer (split_evaluation.h) agree,
// to the bit, with the whole-grid functions on the split grid, for random parts taken out of the
// remainder of real construction-tree nodes.
#include <gtest/gtest.h>

#include <random>

#include "desia/voxel_design.h"
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
    EXPECT_EQ(design::isListFaceConnected(steps, candidate.partVoxels), design::isFaceConnected(split, remainder));
    EXPECT_EQ(accessibility.sumWithout(candidate.partVoxels), compactnessSum(split, remainder + 1)) << trial;
    if (restConnected) ExpectSameContacts(assembly.assemblyAfter(candidate.partVoxels), assemblyFromVoxels(split));
    for (CandidateRanking ranking : {CandidateRanking::Compactness, CandidateRanking::HighestX, CandidateRanking::LowestZ}) {
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

}  // namespace
}  // namespace desia
