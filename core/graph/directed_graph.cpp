// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/model.h"

#include <algorithm>
#include <array>
#include <cstdint>

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

namespace {

// The nodes reached from node 0 by following `next` (per node, the mask of its neighbours).
uint64_t reachedFromFirst(const std::array<uint64_t, 64>& next) {
  uint64_t seen = 1, frontier = 1;
  while (frontier != 0) {
    uint64_t grown = 0;
    for (uint64_t left = frontier; left != 0; left &= left - 1) grown |= next[__builtin_ctzll(left)];  // GCC, Clang
    frontier = grown & ~seen;
    seen |= grown;
  }
  return seen;
}

}  // namespace

std::optional<bool> isStronglyConnectedSmall(const DirectedGraph& graph) {
  const int n = graph.nodeCount();
  if (n < 1 || n > 64) return std::nullopt;
  std::array<uint64_t, 64> along{}, against{};  // per node: the nodes it has an edge to / from
  for (int from = 0; from < n; ++from) {
    for (int to : graph.successors(from)) {
      along[static_cast<size_t>(from)] |= uint64_t{1} << to;
      against[static_cast<size_t>(to)] |= uint64_t{1} << from;
    }
  }
  const uint64_t all = n == 64 ? ~uint64_t{0} : (uint64_t{1} << n) - 1;
  return reachedFromFirst(along) == all && reachedFromFirst(against) == all;
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
