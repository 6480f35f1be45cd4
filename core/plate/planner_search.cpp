// SPDX-License-Identifier: GPL-3.0-or-later
// The plate planner's restarted search (paper Algorithm 1) on the shared construction-tree search
// (search/construction_search.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "plate/plate_planner.h"
#include "search/construction_search.h"
#include "search/restarts.h"

namespace desia {
namespace {

// A whole number of degrees as such ("40"), else to one decimal ("37.5").
std::string degreesText(double degrees) {
  char text[32];
  std::snprintf(text, sizeof text, degrees == std::floor(degrees) ? "%.0f" : "%.1f", degrees);
  return text;
}

}  // namespace

// The construction tree below the node `prefix` (the root for a whole design) as the shared search
// walks it (search/construction_search.h): an explicit stack of each node's ranked candidates, of
// which the paper's m per node are tested and entered lazily (nextChild). A child whose plate runs
// into the joints made so far or that the LP test (paper Section 4.2) lets more than one part move
// is refused; a complete plan is accepted only if its jointed plates verify, else the search
// backjumps past the step it collided with.
class PlateJointPlanner::SearchTree : public search::ConstructionTree {
 public:
  SearchTree(PlateJointPlanner& planner, const std::vector<PlanStep>& prefix, PlateDesignResult& result)
      : planner_(planner), prefix_(prefix), result_(result) {}

  // Each tree has its own tie-breaking order (restarts.h); the ties only order the children.
  void restart(int64_t attempt) override {
    const uint64_t seed = planner_.options_.seed;
    planner_.random_ = restartState(seed, attempt, seed * 0x9E3779B97F4A7C15ull + 1);
    path_ = prefix_;
    pending_.clear();
    pending_.push_back(planner_.rankedCandidatesOf(prefix_));
  }

  // Tree k gets luby(k) units of nodes; the unit counts the plates still to take (at least 64). A
  // wrong choice near the root (the CABINET's shelf as the key: 5,811 nodes of plans whose roof
  // cannot close) is left for another tree.
  bool budgetSpent(int64_t attempt, int64_t nodes) const override {
    const int64_t left = planner_.graph_.plateCount - static_cast<int>(prefix_.size());
    return nodes >= std::max<int64_t>(64, 4 * left) * lubyTerm(attempt);
  }

  bool exhausted() const override { return pending_.empty(); }

  search::Move step() override {
    std::optional<PlanStep> child = planner_.nextChild(&path_, &pending_.back());
    if (!child) {  // no child left here: back to the parent's next sibling
      pending_.pop_back();
      if (path_.size() > prefix_.size()) path_.pop_back();
      return search::Move::Returned;
    }
    path_.push_back(std::move(*child));
    const bool held = !(makesJoints(planner_.options_.realization) && planner_.runsIntoJointsSoFar(path_)) &&
                      planner_.heldByInequalities(path_);
    path_.back().nodeModel.reset();  // used; a path of 400 models would hold megabytes
    if (!held) {
      path_.pop_back();
      return search::Move::Returned;
    }
    if (path_.size() > deepest_.size()) deepest_ = path_;
    if (!complete()) pending_.push_back(planner_.rankedCandidatesOf(path_));
    return search::Move::Entered;
  }

  int depth() const override { return static_cast<int>(path_.size()) + 1; }  // R counts as one
  // R is the last plate: a complete plan.
  bool complete() const override { return depth() == planner_.graph_.plateCount; }

  bool acceptComplete() override {
    planner_.lastDoomedDepth_ = -1;
    if (planner_.acceptComplete(path_, &result_)) return true;
    path_.pop_back();
    planner_.backjump(prefix_.size(), &path_, &pending_);
    return false;
  }

  // The deepest node entered in any tree: where a search that got no further says why.
  const std::vector<PlanStep>& deepest() const { return deepest_.size() > prefix_.size() ? deepest_ : prefix_; }

  void snapshotDeepest(DesignProgress& progress) const override {
    progress.deepestPlaced.clear();
    for (const PlanStep& step : path_) progress.deepestPlaced.push_back(step.plate);
  }

 private:
  PlateJointPlanner& planner_;
  const std::vector<PlanStep>& prefix_;
  PlateDesignResult& result_;
  std::vector<PlanStep> path_, deepest_;
  // pending_[k]: the candidates left at depth prefix + k, and how many of them passed.
  std::vector<RankedCandidates> pending_;
};

// After a complete plan failed because plate i, swept out, ran into plate j taken at depth j of the
// path (i < j): plate i's joints are made at steps 0..i, plate j's at steps 0..j, so every plan that
// shares the path's first j + 1 steps fails the same way. Backjumping goes straight to the next
// sibling of step j (the LIZARD: 28 complete plans in a row failed on one collision at depth 8
// while the search tried orders of the plates after it). The pruned plans would all fail, so a
// tree searched to its end still proves that no plan exists.
void PlateJointPlanner::backjump(size_t prefixSize, std::vector<PlanStep>* path,
                                 std::vector<RankedCandidates>* pending) const {
  if (lastDoomedDepth_ < 0) return;
  const size_t depth = static_cast<size_t>(lastDoomedDepth_);
  if (depth >= path->size()) return;  // the last plate, or the step just undone
  if (depth < prefixSize) {  // the given prefix itself is doomed: nothing below it can work
    pending->clear();
    return;
  }
  // pending[k] holds the siblings left at depth prefixSize + k; keep those up to `depth`.
  pending->resize(depth - prefixSize + 1);
  path->resize(depth);
}

// Where the search got no further, and why no plate could be taken there (the evidence a design
// refused or stopped at its limits gives; issue 26).
std::string PlateJointPlanner::atTheDeepestNode(const std::vector<PlanStep>& deepest) const {
  if (deepest.empty() || static_cast<int>(deepest.size()) + 1 >= graph_.plateCount) return "";
  return " (the deepest node: " + whyNoPlateLeavesAfter(deepest) + ")";
}

PlateDesignResult PlateJointPlanner::run(const std::vector<PlanStep>& prefix) {
  if (std::optional<PlateDesignResult> refused = refusal()) return *refused;
  PlateDesignResult result;
  DesignProgress& progress = result.progress;
  progress.targetParts = graph_.plateCount;
  if (static_cast<int>(prefix.size()) + 1 >= graph_.plateCount) {  // a complete node: nothing left to search
    progress.depth = progress.bestDepth = graph_.plateCount;
    if (!acceptComplete(prefix, &result)) {
      result.status = DesignStatus::NotFound;
      result.message = "this complete plan fails: " + lastRejection_;
      return result;
    }
    result.message = "designed " + std::to_string(result.joints.size()) + " joints";
    return result;
  }
  SearchTree tree(*this, prefix, result);
  search::ConstructionSearch search(tree, options_.limits, search::SearchRules{/*returnsAreNodes=*/true});
  const search::SearchEnd end = search.run(progress);
  progress.seconds = search.seconds();
  if (end == search::SearchEnd::Cancelled) {
    result.status = DesignStatus::Cancelled;
    result.message = "cancelled after " + std::to_string(progress.nodes) + " nodes";
    return result;
  }
  if (end == search::SearchEnd::NodeLimit || end == search::SearchEnd::TimeLimit) {
    result.status = DesignStatus::LimitReached;
    result.message =
        "no plan within the limits (" + std::to_string(progress.nodes) + " nodes; deepest " +
        std::to_string(progress.bestDepth) + " of " + std::to_string(graph_.plateCount) + " plates" +
        (lastRejection_.empty() ? std::string(")") : "; the last complete plan failed: " + lastRejection_ + ")") +
        atTheDeepestNode(tree.deepest());
    return result;
  }
  if (end == search::SearchEnd::Exhausted) {
    result.status = DesignStatus::NotFound;
    result.message =
        std::string(prefix.empty() ? "no interlocking joint plan exists within the search ("
                                   : "no interlocking joint plan exists below this node (") +
        std::to_string(progress.nodes) + " nodes; deepest " +
        std::to_string(progress.bestDepth) + " of " + std::to_string(graph_.plateCount) + " plates" +
        (lastRejection_.empty() ? std::string(")")
                                : "; the last complete plan failed on its jointed plates: " + lastRejection_ + ")") +
        (options_.realization == JointRealization::Cut
             ? " with the joints that can be cut (through and open mortise-and-tenon on square edges standing on a "
               "face at a right angle, halved joints where plates cross, through slots where halved slots cannot "
               "open, in-plane dovetails where plates meet edge to edge in one plane); joints "
               "'milled' adds sliding dovetails (CNC), joints 'planned' gives the paper's graph design alone"
             : options_.realization == JointRealization::Milled
                   ? " with the joints that can be cut or milled (mortise-and-tenon, halved and sliding dovetail "
                     "joints on square edges at right angles, halved joints where plates cross, through slots, "
                     "in-plane dovetails, tenons across mitres, step tenons where plates meet edge to edge with their planes " +
                         degreesText(options_.joints.stepTenon.leastDegrees) + " to " +
                         degreesText(options_.joints.stepTenon.mostDegrees) +
                         " degrees apart, slanted tenons where a bevelled side lies on a face " +
                         degreesText(options_.joints.slantedTenon.leastDegrees) +
                         " to 90 degrees apart, slanted sliding dovetails along such a side " +
                         degreesText(options_.joints.slantedDovetail.leastDegrees) +
                         " to 90 degrees apart); joints 'planned' gives the paper's graph design alone"
                   : "") +
        (prefix.empty() && progress.bestDepth == 0 ? " (" + whyNoPlateLeavesFirst() + ")"
                                                   : atTheDeepestNode(tree.deepest()));
    return result;
  }
  result.message =
      "designed " + std::to_string(result.joints.size()) + " joints in " + std::to_string(progress.nodes) + " nodes";
  return result;
}

}  // namespace desia
