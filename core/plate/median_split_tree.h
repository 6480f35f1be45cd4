// SPDX-License-Identifier: GPL-3.0-or-later
// A tree of items' axis-aligned bounds built by median splits, the shared skeleton of the plate
// layer's two search trees (nearly square directions, plates in a plate's way). Built with an
// explicit stack; leaves of at most 8 items.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "desia/model.h"

namespace desia {

struct SplitTreeNode {
  size_t begin, end;  // the node's items: order[begin, end)
  Vec3 lo, hi;        // their bounds
  std::array<size_t, 2> children{0, 0};  // none for a leaf (the root is never a child)
};

// Reorders `order` (the items' indices) into the tree's leaves and returns its nodes, the root
// first. boundsOf(i) gives item i's {lo, hi}; centre(i, axis) orders the items along the node's
// widest axis.
template <class BoundsOf, class Centre>
std::vector<SplitTreeNode> buildMedianSplitTree(std::vector<int>& order, BoundsOf boundsOf, Centre centre) {
  std::vector<SplitTreeNode> nodes;
  if (order.empty()) return nodes;
  auto add = [&](size_t begin, size_t end) {
    const std::array<Vec3, 2> first = boundsOf(order[begin]);
    SplitTreeNode node{begin, end, first[0], first[1]};
    for (size_t r = begin; r < end; ++r) {
      const std::array<Vec3, 2> b = boundsOf(order[r]);
      for (int k = 0; k < 3; ++k) node.lo[k] = std::min(node.lo[k], b[0][k]), node.hi[k] = std::max(node.hi[k], b[1][k]);
    }
    nodes.push_back(node);
    return nodes.size() - 1;
  };
  std::vector<size_t> pending{add(0, order.size())};
  while (!pending.empty()) {
    const size_t at = pending.back();
    pending.pop_back();
    const size_t begin = nodes[at].begin, end = nodes[at].end;
    if (end - begin <= 8) continue;
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (nodes[at].hi[k] - nodes[at].lo[k] > nodes[at].hi[axis] - nodes[at].lo[axis]) axis = k;
    }
    const size_t middle = (begin + end) / 2;
    std::nth_element(order.begin() + static_cast<long>(begin), order.begin() + static_cast<long>(middle),
                     order.begin() + static_cast<long>(end), [&](int i, int j) { return centre(i, axis) < centre(j, axis); });
    const size_t left = add(begin, middle), right = add(middle, end);
    nodes[at].children = {left, right};
    pending.push_back(left);
    pending.push_back(right);
  }
  return nodes;
}

}  // namespace desia
