// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

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
