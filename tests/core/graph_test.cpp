// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

#include "desia/model.h"

namespace desia {
namespace {

TEST(StronglyConnectedComponents, CycleIsOneComponent) {
  DirectedGraph graph(3);
  graph.addEdge(0, 1);
  graph.addEdge(1, 2);
  graph.addEdge(2, 0);
  const auto scc = findStronglyConnectedComponents(graph);
  EXPECT_EQ(scc.count(), 1);
  EXPECT_EQ(scc.components[0], (std::vector<int>{0, 1, 2}));
}

TEST(StronglyConnectedComponents, ComponentsAreNumberedBySmallestNode) {
  // 3 <-> 4 form a cycle, 0 -> 3, 1 -> 2 -> 1, 4 -> 1.
  DirectedGraph graph(5);
  graph.addEdge(0, 3);
  graph.addEdge(3, 4);
  graph.addEdge(4, 3);
  graph.addEdge(1, 2);
  graph.addEdge(2, 1);
  graph.addEdge(4, 1);
  const auto scc = findStronglyConnectedComponents(graph);
  ASSERT_EQ(scc.count(), 3);
  EXPECT_EQ(scc.components[0], (std::vector<int>{0}));
  EXPECT_EQ(scc.components[1], (std::vector<int>{1, 2}));
  EXPECT_EQ(scc.components[2], (std::vector<int>{3, 4}));
  const auto degrees = condensationDegrees(graph, scc);
  EXPECT_EQ(degrees.hasOutEdge, (std::vector<bool>{true, false, true}));
  EXPECT_EQ(degrees.hasInEdge, (std::vector<bool>{false, true, true}));
}

TEST(StronglyConnectedComponents, DeepChainNeedsNoRecursion) {
  // A 200000-node path followed by a closing edge: recursion this deep would overflow the
  // WebAssembly stack; the iterative Tarjan must handle it.
  const int n = 200000;
  DirectedGraph graph(n);
  for (int i = 0; i + 1 < n; ++i) graph.addEdge(i, i + 1);
  EXPECT_EQ(findStronglyConnectedComponents(graph).count(), n);
  graph.addEdge(n - 1, 0);
  EXPECT_EQ(findStronglyConnectedComponents(graph).count(), 1);
}

// The bit-mask test against Tarjan's algorithm on random graphs of every size it takes (node 63's
// bit included), from sparse to dense, and nothing for 65 nodes.
TEST(StronglyConnectedComponents, TheBitMaskTestAgreesWithTarjanUpTo64Nodes) {
  uint64_t state = 12345;
  auto next = [&]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  int connected = 0, notConnected = 0;
  for (int n = 1; n <= 64; ++n) {
    for (int trial = 0; trial < 40; ++trial) {
      DirectedGraph graph(n);
      const double density = (1.0 + trial % 8) / n;  // about 1 to 8 edges per node
      for (int from = 0; from < n; ++from)
        for (int to = 0; to < n; ++to)
          if (from != to && next() < density) graph.addEdge(from, to);
      const std::optional<bool> byMasks = isStronglyConnectedSmall(graph);
      ASSERT_TRUE(byMasks.has_value()) << n;
      const bool byTarjan = findStronglyConnectedComponents(graph).count() == 1;
      EXPECT_EQ(*byMasks, byTarjan) << n << " nodes, trial " << trial;
      (byTarjan ? connected : notConnected) += 1;
    }
  }
  EXPECT_GT(connected, 300);
  EXPECT_GT(notConnected, 300);
  // A cycle through all 64 nodes, then broken at its last edge (into node 0 from node 63).
  DirectedGraph cycle(64);
  for (int i = 0; i < 64; ++i) cycle.addEdge(i, (i + 1) % 64);
  EXPECT_EQ(isStronglyConnectedSmall(cycle), std::optional<bool>(true));
  DirectedGraph path(64);
  for (int i = 0; i + 1 < 64; ++i) path.addEdge(i, i + 1);
  EXPECT_EQ(isStronglyConnectedSmall(path), std::optional<bool>(false));
  EXPECT_FALSE(isStronglyConnectedSmall(DirectedGraph(65)).has_value());
  EXPECT_FALSE(isStronglyConnectedSmall(DirectedGraph(0)).has_value());
}

TEST(DirectedGraph, IgnoresDuplicateEdges) {
  DirectedGraph graph(2);
  graph.addEdge(0, 1);
  graph.addEdge(0, 1);
  EXPECT_EQ(graph.edgeCount(), 1);
  EXPECT_TRUE(graph.hasEdge(0, 1));
  EXPECT_FALSE(graph.hasEdge(1, 0));
}

}  // namespace
}  // namespace desia
