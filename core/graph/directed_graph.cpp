// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/model.h"

#include <algorithm>

namespace desia {

void DirectedGraph::addEdge(int from, int to) {
  std::vector<int>& list = out_[from];
  auto it = std::lower_bound(list.begin(), list.end(), to);
  if (it == list.end() || *it != to) list.insert(it, to);
}

bool DirectedGraph::hasEdge(int from, int to) const {
  const std::vector<int>& list = out_[from];
  return std::binary_search(list.begin(), list.end(), to);
}

int DirectedGraph::edgeCount() const {
  int count = 0;
  for (const auto& list : out_) count += static_cast<int>(list.size());
  return count;
}

StronglyConnectedComponents findStronglyConnectedComponents(const DirectedGraph& graph) {
  const int n = graph.nodeCount();
  constexpr int kUnvisited = -1;
  std::vector<int> order(n, kUnvisited), lowLink(n, 0), rawComponent(n, -1);
  std::vector<bool> onStack(n, false);
  std::vector<int> tarjanStack;
  // Explicit DFS stack of (node, position in its successor list) replaces the recursion.
  std::vector<std::pair<int, size_t>> callStack;
  int nextOrder = 0, rawCount = 0;

  for (int root = 0; root < n; ++root) {
    if (order[root] != kUnvisited) continue;
    callStack.emplace_back(root, 0);
    order[root] = lowLink[root] = nextOrder++;
    tarjanStack.push_back(root);
    onStack[root] = true;
    while (!callStack.empty()) {
      auto& [node, next] = callStack.back();
      const std::vector<int>& successors = graph.successors(node);
      if (next < successors.size()) {
        int succ = successors[next++];
        if (order[succ] == kUnvisited) {
          order[succ] = lowLink[succ] = nextOrder++;
          tarjanStack.push_back(succ);
          onStack[succ] = true;
          callStack.emplace_back(succ, 0);
        } else if (onStack[succ]) {
          lowLink[node] = std::min(lowLink[node], order[succ]);
        }
        continue;
      }
      // All successors done: close the node, then propagate its low-link to the caller.
      const int finished = node;
      if (lowLink[finished] == order[finished]) {
        int member;
        do {
          member = tarjanStack.back();
          tarjanStack.pop_back();
          onStack[member] = false;
          rawComponent[member] = rawCount;
        } while (member != finished);
        ++rawCount;
      }
      callStack.pop_back();
      if (!callStack.empty()) {
        int caller = callStack.back().first;
        lowLink[caller] = std::min(lowLink[caller], lowLink[finished]);
      }
    }
  }

  // Renumber components by their smallest node so results do not depend on traversal details.
  StronglyConnectedComponents result;
  result.componentOf.assign(n, -1);
  std::vector<int> renumbered(rawCount, -1);
  for (int node = 0; node < n; ++node) {
    int& target = renumbered[rawComponent[node]];
    if (target < 0) {
      target = static_cast<int>(result.components.size());
      result.components.emplace_back();
    }
    result.componentOf[node] = target;
    result.components[target].push_back(node);
  }
  return result;
}

CondensationDegrees condensationDegrees(const DirectedGraph& graph,
                                        const StronglyConnectedComponents& scc) {
  CondensationDegrees degrees;
  degrees.hasOutEdge.assign(scc.count(), false);
  degrees.hasInEdge.assign(scc.count(), false);
  for (int from = 0; from < graph.nodeCount(); ++from) {
    for (int to : graph.successors(from)) {
      int a = scc.componentOf[from], b = scc.componentOf[to];
      if (a == b) continue;
      degrees.hasOutEdge[a] = true;
      degrees.hasInEdge[b] = true;
    }
  }
  return degrees;
}

}  // namespace desia
