// SPDX-License-Identifier: GPL-3.0-or-later
// The complete disassembler of voxel assemblies: moves of several parts at once, searched
// breadth-first for the fewest moves before each separation (BurrTools' notion of a puzzle's
// level, after Bill Cutler's analysis of six-piece burrs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/voxel.h"

namespace desia {

struct GroupPlan {
  bool complete = false;                       // every part came free
  std::vector<GroupMove> moves;                // in order; each separation ends with an `out` move
  std::vector<int> level;                      // BurrTools' notation, of the separations made
  std::vector<int> freeOrder;                  // parts in the order they came free
  std::vector<std::vector<int>> unseparated;   // sub-assemblies left together (incomplete plans)
  bool limitReached = false;                   // some sub-assembly's search stopped at a bound
  std::string limit;                           // that bound, in words
  int64_t states = 0;                          // positions visited, all searches together
  int64_t work = 0;                            // part-pair tests and set unions, all searches together
};

// Takes the grid's parts (labels 1..partCount) apart. Each sub-assembly is searched breadth-first
// over the positions of its parts: a move translates a set of parts that nothing else blocks by
// one or more units along one axis, a separation takes such a set out to infinity, after which
// both sides are taken apart on their own (left side first). A sub-assembly whose search runs
// out of positions cannot be taken apart; one whose search reaches options' bounds is reported
// with `limitReached`, never as proven.
GroupPlan planGroupDisassembly(const VoxelGrid& grid, int partCount, const VoxelDisassemblyOptions& options);

// The level of a plan of single-part removals, each along a path of `moveCounts[k]` moves, in
// BurrTools' notation: the removals form a chain of separations, each removing one part.
std::vector<int> singlePartLevel(const std::vector<int>& moveCounts);

}  // namespace desia
