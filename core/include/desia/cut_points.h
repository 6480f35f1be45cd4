// SPDX-License-Identifier: GPL-3.0-or-later
// Cut points (articulation points) of an undirected graph.
#pragma once

#include <utility>
#include <vector>

namespace desia {

// The nodes whose removal splits their connected component, sorted. Hopcroft and Tarjan's
// depth-first search, iterative with an explicit stack (no recursion depth grows with the graph).
// Parallel edges and self-loops are allowed.
std::vector<int> findCutPoints(int nodeCount, const std::vector<std::pair<int, int>>& edges);

}  // namespace desia
