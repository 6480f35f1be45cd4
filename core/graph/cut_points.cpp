// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/model.h"

#include <algorithm>

namespace desia {

std::vector<int> findCutPoints(int nodeCount, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> neighbours(nodeCount);
  for (const auto& [a, b] : edges) {
    if (a == b) continue;
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  constexpr int kUnvisited = -1;
  std::vector<int> order(nodeCount, kUnvisited), low(nodeCount, 0), parent(nodeCount, -1);
  std::vector<bool> isCut(nodeCount, false);
  struct Frame {
    int node;
    size_t next;  // position in the node's neighbour list
  };
  std::vector<Frame> stack;
  int nextOrder = 0;
  for (int root = 0; root < nodeCount; ++root) {
    if (order[root] != kUnvisited) continue;
    int rootChildren = 0;
    order[root] = low[root] = nextOrder++;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      Frame& frame = stack.back();
      const int node = frame.node;
      if (frame.next < neighbours[node].size()) {
        const int other = neighbours[node][frame.next++];
        if (order[other] == kUnvisited) {
          parent[other] = node;
          order[other] = low[other] = nextOrder++;
          if (node == root) ++rootChildren;
          stack.push_back({other, 0});
        } else if (other != parent[node]) {
          low[node] = std::min(low[node], order[other]);
        }
        continue;
      }
      // All neighbours done: hand the low link up, and test the parent.
      stack.pop_back();
      const int up = parent[node];
      if (up < 0) continue;
      low[up] = std::min(low[up], low[node]);
      if (up != root && low[node] >= order[up]) isCut[up] = true;
    }
    if (rootChildren > 1) isCut[root] = true;
  }
  std::vector<int> cuts;
  for (int node = 0; node < nodeCount; ++node) {
    if (isCut[node]) cuts.push_back(node);
  }
  return cuts;
}

}  // namespace desia
