// SPDX-License-Identifier: GPL-3.0-or-later
// Why a joint plan search got no further (paper Section 5.2: the key P_1 must leave A_1 along d_1
// and nothing else may move; each later P_i leaves A_i with A_{i+1} interlocking): a node's
// candidates again, each plate's ways out with how far each gets through the node's tests, summed
// up so that a design refused at once, or stopped at its limits, says why with evidence (issue 26:
// "design or say with evidence why none exists"; "the rest refused with the reason named").
#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "plate/plate_planner.h"

namespace desia {
namespace {

std::string plateList(const std::vector<Plate>& plates, const std::set<int>& which) {
  std::string text;
  size_t k = 0;
  for (int p : which) {
    text += (k == 0 ? "" : k + 1 == which.size() ? " and " : ", ") + std::to_string(plates[p].id);
    ++k;
  }
  return text;
}

// The plates a path took, in order; a long path by its last few (where the search turned back).
std::string takenList(const std::vector<Plate>& plates, const std::vector<PlanStep>& path) {
  constexpr size_t kShown = 6;
  const size_t from = path.size() > kShown ? path.size() - kShown : 0;
  std::string text = path.size() > 1 ? "plates " : "plate ";
  if (from > 0) text += "…, ";
  for (size_t k = from; k < path.size(); ++k) text += (k == from ? "" : ", ") + std::to_string(plates[path[k].plate].id);
  return text;
}

// At most a few of a long list of plates, and how many more.
std::string shortPlateList(const std::vector<Plate>& plates, const std::set<int>& which) {
  constexpr size_t kShown = 8;
  if (which.size() <= kShown) return plateList(plates, which);
  std::set<int> shown;
  for (int p : which) {
    if (shown.size() == kShown) break;
    shown.insert(p);
  }
  std::string text;
  for (int p : shown) text += std::to_string(plates[p].id) + (p == *shown.rbegin() ? " " : ", ");
  return text + "and " + std::to_string(which.size() - kShown) + " more";
}

}  // namespace

// How far each plate of R gets, the furthest over its ways out (the order of the checks in
// candidatesOf, nextChild and the search's step).
enum class PlateJointPlanner::NextStepStage {
  CutPoint,        // taking it would split the rest
  Blocked,         // every way runs into a plate in place (or pushes one)
  HeldByCrossing,  // a crossing's slots do not let it out that way
  NoJoint,         // no joint of the realization lets it out that way
  CutsCollide,     // its joints would run into each other or into joints cut before
  RestNotHeld,     // the rest would not interlock with the key alone (DBG; at the root: the key moves more ways)
  JointSolids,     // it would run into solids earlier joints left standing
  Passes,          // passes every test: a child the search did not enter (limits, or m kept)
};

PlateJointPlanner::NextStepStage PlateJointPlanner::furthestStage(const std::vector<PlanStep>& path, int plate,
                                                                  const std::vector<bool>& isCutPoint,
                                                                  std::set<int>* crossingPartners) const {
  if (isCutPoint[plate]) return NextStepStage::CutPoint;
  const NodeFacts node = factsOf(path);
  std::vector<bool> inRest(graph_.plateCount);
  for (int p = 0; p < graph_.plateCount; ++p) inRest[p] = !node.taken[p];
  NextStepStage furthest = NextStepStage::Blocked;
  const std::vector<Vec3>& ways = candidateDirections(plate);
  for (size_t way = 0; way < ways.size() && furthest != NextStepStage::Passes; ++way) {
    const Vec3& d = ways[way];
    if (!leavesWithoutPushing(graph_, plate, inRest, d) || runsIntoARemainingPlate(plate, way, node.taken)) continue;
    NextStepStage stage = NextStepStage::CutsCollide;
    for (int other : graph_.neighbours[plate]) {
      if (node.taken[other] || families_.jointFor(plate, other, d)) continue;
      if (crossingBetween(graph_, plate, other) >= 0) {
        crossingPartners->insert(other);
        stage = NextStepStage::HeldByCrossing;
      } else if (stage != NextStepStage::HeldByCrossing) {
        stage = NextStepStage::NoJoint;
      }
    }
    if (stage == NextStepStage::CutsCollide) {
      std::vector<PlanStep> child = path;
      child.push_back(makeStep(node, plate, d));
      if (!child.back().blocked && path.empty()) {
        stage = NextStepStage::RestNotHeld;  // at the root: free, but (the search found) not along d alone
      } else if (!child.back().blocked) {
        // Not the LP test (heldByInequalities): this runs after the search's time limit, and its
        // cost on 100+ plates for every way left would overrun it.
        stage = !acceptable(child) ? NextStepStage::RestNotHeld
                : makesJoints(options_.realization) && runsIntoJointsSoFar(child) ? NextStepStage::JointSolids
                                                                                 : NextStepStage::Passes;
      }
    }
    furthest = std::max(furthest, stage);
  }
  return furthest;
}

std::string PlateJointPlanner::whyNoPlateLeavesFirst() const {
  const std::vector<bool> noCutPoints(graph_.plateCount, false);
  int free = 0, heldByCrossings = 0, heldByOthers = 0, example = -1;
  std::set<int> examplePartners;
  for (int plate = 0; plate < graph_.plateCount; ++plate) {
    std::set<int> crossingPartners;
    const NextStepStage stage = furthestStage({}, plate, noCutPoints, &crossingPartners);
    if (stage >= NextStepStage::RestNotHeld) {
      ++free;
    } else if (!crossingPartners.empty()) {  // a way held by a crossing: held by crossings
      ++heldByCrossings;
      // The clearest example: a plate held by two crossings, else the fewest that hold one.
      const auto clearer = [](size_t n, size_t than) { return (n >= 2) != (than >= 2) ? n >= 2 : n < than; };
      if (example < 0 || clearer(crossingPartners.size(), examplePartners.size())) {
        example = plate;
        examplePartners = crossingPartners;
      }
    } else {
      ++heldByOthers;
    }
  }
  std::vector<std::string> parts;
  if (heldByCrossings > 0) {
    parts.push_back(std::to_string(heldByCrossings) +
                    " held by their crossings (whose slots let a plate out along the crossing line only, towards "
                    "their open ends) and the plates they touch: plate " +
                    std::to_string(plates_[example].id) + ", crossing plate" + (examplePartners.size() > 1 ? "s " : " ") +
                    plateList(plates_, examplePartners));
  }
  if (heldByOthers > 0) {
    parts.push_back(std::to_string(heldByOthers) +
                    " blocked along every way out by the plates they touch or would run into, or with no joint that "
                    "lets them out");
  }
  if (free > 0) parts.push_back(std::to_string(free) + " free to leave, but along more than the one way a key may");
  std::string text = "no plate can be taken first: of " + std::to_string(graph_.plateCount) + " plates, ";
  for (size_t k = 0; k < parts.size(); ++k) text += (k == 0 ? "" : "; ") + parts[k];
  return text;
}

std::string PlateJointPlanner::whyNoPlateLeavesAfter(const std::vector<PlanStep>& path) const {
  std::vector<bool> taken(graph_.plateCount, false);
  for (const PlanStep& step : path) taken[step.plate] = true;
  std::vector<int> rest;
  for (int p = 0; p < graph_.plateCount; ++p) {
    if (!taken[p]) rest.push_back(p);
  }
  const std::vector<bool> isCutPoint = cutPointsOfRest(taken);
  std::vector<std::set<int>> byStage(static_cast<size_t>(NextStepStage::Passes) + 1);
  for (int plate : rest) {
    std::set<int> crossingPartners;
    byStage[static_cast<size_t>(furthestStage(path, plate, isCutPoint, &crossingPartners))].insert(plate);
  }
  // What the plates of each stage are: [0] for one plate, [1] for several.
  static const char* const kSaid[][2] = {
      {"is a cut point of the plates left (taking it splits them)", "are cut points of the plates left (taking one splits them)"},
      {"is blocked along every way out by the plates it touches or would run into",
       "are blocked along every way out by the plates they touch or would run into"},
      {"is held by its crossings", "are held by their crossings"},
      {"has no joint that lets it out along a way it is free to take",
       "have no joint that lets them out along a way they are free to take"},
      {"would have joints running into joints cut before or into each other",
       "would have joints running into joints cut before or into each other"},
      {"would leave the rest not held by the key alone", "would leave the rest not held by the key alone"},
      {"would run into solids earlier joints leave standing", "would run into solids earlier joints leave standing"},
      {"passes every test here but was not tried (the search stopped at its limits, or kept other candidates)",
       "pass every test here but were not tried (the search stopped at its limits, or kept other candidates)"},
  };
  static_assert(std::size(kSaid) == static_cast<size_t>(NextStepStage::Passes) + 1, "a text for every stage");
  std::string text = takenList(plates_, path) + " taken (" + std::to_string(path.size()) + " of " +
                     std::to_string(graph_.plateCount) + "); of the " + std::to_string(rest.size()) + " left, ";
  bool first = true;
  for (size_t stage = 0; stage < byStage.size(); ++stage) {
    const std::set<int>& plates = byStage[stage];
    if (plates.empty()) continue;
    text += std::string(first ? "" : "; ") + (plates.size() > 1 ? "plates " : "plate ") + shortPlateList(plates_, plates) +
            " " + kSaid[stage][plates.size() > 1 ? 1 : 0];
    first = false;
  }
  return text;
}

}  // namespace desia
