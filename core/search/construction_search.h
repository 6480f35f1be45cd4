// SPDX-License-Identifier: GPL-3.0-or-later
// The construction-tree search of paper Algorithm 1, written once for every kind of assembly:
// depth first over ranked children, with restarts, limits, progress, cancellation and snapshots of
// the deepest node. A kind (voxel puzzles, plate joints, frame joints) supplies the tree: how a
// node's children are made and ranked, how a step is taken and undone, and how a complete
// assembly is verified. The walk itself is the kind's (an explicit stack, never recursion: the
// WebAssembly stack is small and N can be in the thousands).
#pragma once

#include <chrono>
#include <cstdint>

#include "desia/search.h"

namespace desia::search {

// What one step of the walk did.
enum class Move {
  Entered,    // went down to the next untried child of the current node
  Returned,   // went back up (no untried child was left), or refused the child it tried
  Exhausted,  // nothing is left at or below the floor: this tree holds no solution
};

// The tree a kind searches. The floor is the node the search starts from (the root for a whole
// design, the current node for a session's "finish from here"); the walk never goes above it.
class ConstructionTree {
 public:
  virtual ~ConstructionTree() = default;

  // Back to the floor, with the random state of restart `attempt` (0: the first tree). Restarts
  // change only the order in which ties are broken, so a tree searched to its end still proves
  // that no solution exists.
  virtual void restart(int64_t attempt) = 0;
  // Restart `attempt` has spent its budget, having visited `nodes` nodes so far (the kind may also
  // count its own work). Counted in work the search does, never in time: the same seed gives the
  // same result on every machine and in WebAssembly.
  virtual bool budgetSpent(int64_t attempt, int64_t nodes) const = 0;
  // Known without a step that nothing is left at or below the floor.
  virtual bool exhausted() const { return false; }
  virtual Move step() = 0;
  // After Move::Entered: the node's depth as the kind counts it, and whether it is complete.
  virtual int depth() const = 0;
  virtual bool complete() const = 0;
  // A complete node verified by the project's own checks: true ends the search with it; false
  // leaves the walk where the kind wants the search to go on (its backtracking included).
  virtual bool acceptComplete() = 0;
  // A tree searched to its end: search it again more widely within the same restart (true), or
  // accept that no solution exists (false, the default).
  virtual bool widen() { return false; }
  // Records the current node as the deepest so far (on demand only, see DesignLimits).
  virtual void snapshotDeepest(DesignProgress& progress) const = 0;
};

struct SearchRules {
  // Whether a step back up counts as a visited node (the plate and frame designers' budgets and
  // reported node counts were measured so) or only a step down does (voxel puzzles).
  bool returnsAreNodes = false;
};

enum class SearchEnd { Found, Exhausted, NodeLimit, TimeLimit, Cancelled };

struct SearchCounts {
  int64_t backtracks = 0;  // steps back up
  int64_t restarts = 0;
  int64_t rejectedComplete = 0;  // complete nodes that failed verification
};

// Runs the restarted depth-first search on `tree` (restarts: core/search/restarts.h). `progress`
// carries the counters in and out (a caller may start bestDepth at the floor's depth).
class ConstructionSearch {
 public:
  ConstructionSearch(ConstructionTree& tree, const DesignLimits& limits, SearchRules rules);
  SearchEnd run(DesignProgress& progress);
  const SearchCounts& counts() const { return counts_; }
  double seconds() const;

 private:
  bool limitReached(const DesignProgress& progress, SearchEnd* end) const;
  bool report(DesignProgress& progress);

  ConstructionTree& tree_;
  const DesignLimits& limits_;
  SearchRules rules_;
  SearchCounts counts_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace desia::search
