// SPDX-License-Identifier: GPL-3.0-or-later
#include "search/level_notation.h"

#include <cstddef>

namespace desia::search {

int addSeparation(std::vector<Separation>* tree, int moves, int parent, bool left) {
  const int node = static_cast<int>(tree->size());
  tree->push_back({moves, -1, -1});
  if (parent >= 0) {
    Separation& above = (*tree)[static_cast<size_t>(parent)];
    (left ? above.left : above.removed) = node;
  }
  return node;
}

std::vector<int> levelOf(const std::vector<Separation>& tree) {
  if (tree.empty()) return {};
  // multi[n]: separation n, or one below it, takes more than one move.
  std::vector<bool> multi(tree.size(), false);
  const auto multiAt = [&](int n) { return n >= 0 && multi[static_cast<size_t>(n)]; };
  for (size_t n = tree.size(); n-- > 0;) {
    const Separation& s = tree[n];
    multi[n] = s.moves > 1 || multiAt(s.left) || multiAt(s.removed);
  }
  std::vector<int> level, stack{0};
  while (!stack.empty()) {
    const Separation& s = tree[static_cast<size_t>(stack.back())];
    stack.pop_back();
    level.push_back(s.moves);
    if (multiAt(s.removed)) stack.push_back(s.removed);
    if (multiAt(s.left)) stack.push_back(s.left);
  }
  return level;
}

}  // namespace desia::search
