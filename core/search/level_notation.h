// SPDX-License-Identifier: GPL-3.0-or-later
// BurrTools' disassembly level (its "movesText"), shared by the searches for moves of several parts
// on cells (voxel/group_disassembly.cpp) and on triangles (mesh/mesh_group_search.cpp): both take a
// sub-assembly apart by a separation, then each side on its own from an explicit work list, and
// read the level from the tree of separations made (paper Section 3.3).
#pragma once

#include <vector>

namespace desia::search {

// A separation of the tree: its moves (the last one out), and the separations of its two sides
// where they hold two parts or more (-1: none, or not separated).
struct Separation {
  int moves = 0;
  int left = -1, removed = -1;  // the side left in place, the side removed
};

// A sub-assembly waiting to be taken apart: its parts, where they were when it separated from the
// rest (`Offset`s, the search's own kind of position), and where its separation hangs in the tree.
template <typename Offset>
struct PendingSubAssembly {
  std::vector<int> parts;
  std::vector<Offset> offsets;
  int parent = -1;   // the separation it came out of; -1: the whole assembly
  bool left = true;  // the side left in place (else the side removed)
};

// Adds the separation of a pending sub-assembly (`parent`, `left` as above) made in `moves` moves
// to the tree, linked below its parent, and returns its index.
int addSeparation(std::vector<Separation>* tree, int moves, int parent, bool left);

// BurrTools' notation: a separation's moves, then, in pre-order, those of the side left in place
// and of the side removed, where that side holds a separation of more than one move. Children come
// after their parent in `tree`; no recursion (explicit stack).
std::vector<int> levelOf(const std::vector<Separation>& tree);

}  // namespace desia::search
