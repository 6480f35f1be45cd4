// SPDX-License-Identifier: GPL-3.0-or-later
// A small directed graph on nodes 0..n-1 and its strongly connected components.
#pragma once

#include <vector>

namespace desia {

class DirectedGraph {
 public:
  explicit DirectedGraph(int nodeCount = 0) : out_(nodeCount) {}

  int nodeCount() const { return static_cast<int>(out_.size()); }
  // Adds from->to once (duplicates are ignored, so edge lists stay sets).
  void addEdge(int from, int to);
  bool hasEdge(int from, int to) const;
  // Removes every edge, keeping the nodes and the memory (for graphs rebuilt many times).
  void clearEdges() {
    for (auto& list : out_) list.clear();
  }
  const std::vector<int>& successors(int node) const { return out_[node]; }
  int edgeCount() const;

 private:
  std::vector<std::vector<int>> out_;  // sorted successor lists
};

struct StronglyConnectedComponents {
  std::vector<int> componentOf;              // node -> component index
  std::vector<std::vector<int>> components;  // each sorted ascending; ordered by smallest node
  int count() const { return static_cast<int>(components.size()); }
};

// Tarjan's algorithm [Tarjan 1972] (paper Section 3.2), iterative with an explicit stack so the
// depth of the graph never reaches the (small) WebAssembly call stack.
StronglyConnectedComponents findStronglyConnectedComponents(const DirectedGraph& graph);

// For each component: does any edge leave it / enter it from another component?
struct CondensationDegrees {
  std::vector<bool> hasOutEdge;
  std::vector<bool> hasInEdge;
};
CondensationDegrees condensationDegrees(const DirectedGraph& graph,
                                        const StronglyConnectedComponents& scc);

}  // namespace desia
