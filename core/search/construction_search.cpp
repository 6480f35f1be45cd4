// SPDX-License-Identifier: GPL-3.0-or-later
#include "search/construction_search.h"

namespace desia::search {

ConstructionSearch::ConstructionSearch(ConstructionTree& tree, const DesignLimits& limits, SearchRules rules)
    : tree_(tree), limits_(limits), rules_(rules), start_(std::chrono::steady_clock::now()) {}

double ConstructionSearch::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool ConstructionSearch::limitReached(const DesignProgress& progress, SearchEnd* end) const {
  if (limits_.timeLimitSeconds > 0 && seconds() > limits_.timeLimitSeconds) {
    *end = SearchEnd::TimeLimit;
    return true;
  }
  if (limits_.nodeLimit > 0 && progress.nodes >= limits_.nodeLimit) {
    *end = SearchEnd::NodeLimit;
    return true;
  }
  return false;
}

bool ConstructionSearch::report(DesignProgress& progress) {
  progress.depth = tree_.depth();
  progress.seconds = seconds();
  return !limits_.onProgress || limits_.onProgress(progress);
}

// Paper Algorithm 1 (lines 18-29: siblings first, then the nearest ancestor's next sibling), with
// restarts: a depth-first search is heavy tailed (a poor choice high in the tree is paid for with
// thousands of dead ends near the last parts, which chronological backtracking explores before it
// gets back up there), so a tree that spends its budget is abandoned for a new one whose ties are
// broken by another random state derived from the user's seed. Budgets follow the Luby sequence,
// which grows without bound, so some tree is always searched to its end: the search terminates.
SearchEnd ConstructionSearch::run(DesignProgress& progress) {
  int64_t attempt = 0;
  int64_t attemptStart = progress.nodes;
  tree_.restart(attempt);
  SearchEnd end = SearchEnd::Exhausted;
  while (true) {
    if (tree_.exhausted()) {
      if (tree_.widen()) continue;
      return SearchEnd::Exhausted;
    }
    if (limitReached(progress, &end)) return end;
    if (tree_.budgetSpent(attempt, progress.nodes - attemptStart)) {
      tree_.restart(++attempt);
      attemptStart = progress.nodes;
      ++counts_.restarts;
      continue;
    }
    const Move move = tree_.step();
    if (move == Move::Exhausted) {
      if (tree_.widen()) continue;
      return SearchEnd::Exhausted;
    }
    if (move == Move::Returned) {
      ++counts_.backtracks;
      if (!rules_.returnsAreNodes) continue;
      ++progress.nodes;
      if (!report(progress)) return SearchEnd::Cancelled;
      continue;
    }
    ++progress.nodes;
    const int depth = tree_.depth();
    if (depth > progress.bestDepth) {
      progress.bestDepth = depth;
      if (limits_.deepestSnapshots) tree_.snapshotDeepest(progress);
    }
    if (!report(progress)) return SearchEnd::Cancelled;
    if (tree_.complete()) {
      if (tree_.acceptComplete()) return SearchEnd::Found;
      ++counts_.rejectedComplete;
    }
  }
}

}  // namespace desia::search

namespace desia {

const char* designStatusName(DesignStatus status) {
  switch (status) {
    case DesignStatus::Success: return "success";
    case DesignStatus::NotFound: return "not-found";
    case DesignStatus::LimitReached: return "limit-reached";
    case DesignStatus::Cancelled: return "cancelled";
    case DesignStatus::CutPoint: return "cut-point";
  }
  return "not-found";
}

}  // namespace desia
