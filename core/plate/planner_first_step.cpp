// SPDX-License-Identifier: GPL-3.0-or-later
// Why a joint plan search ended without a first step (paper Section 5.2: the key P_1 must leave
// A_1 along d_1 and nothing else may move): the root's candidates again, each plate's ways out
// with what stops each one, summed up so that a design refused at once says why (issue 26: "the
// rest refused with the reason named").
#include <set>
#include <string>
#include <vector>

#include "plate/plate_planner.h"

namespace desia {
namespace {

enum class FirstStepHold { Free, Crossings, Others };

std::string plateList(const std::vector<Plate>& plates, const std::set<int>& which) {
  std::string text;
  size_t k = 0;
  for (int p : which) {
    text += (k == 0 ? "" : k + 1 == which.size() ? " and " : ", ") + std::to_string(plates[p].id);
    ++k;
  }
  return text;
}

}  // namespace

std::string PlateJointPlanner::whyNoPlateLeavesFirst() const {
  const std::vector<bool> taken(graph_.plateCount, false);
  const std::vector<bool> inRest(graph_.plateCount, true);
  const NodeFacts node = factsOf({});
  int free = 0, heldByCrossings = 0, heldByOthers = 0, example = -1;
  std::set<int> examplePartners;
  for (int plate = 0; plate < graph_.plateCount; ++plate) {
    FirstStepHold hold = FirstStepHold::Others;
    std::set<int> crossingPartners;
    const std::vector<Vec3>& ways = candidateDirections(plate);
    for (size_t way = 0; way < ways.size() && hold != FirstStepHold::Free; ++way) {
      const Vec3& d = ways[way];
      if (!leavesWithoutPushing(graph_, plate, inRest, d) || runsIntoARemainingPlate(plate, way, taken)) continue;
      bool jointed = true;
      for (int other : graph_.neighbours[plate]) {
        if (families_.jointFor(plate, other, d)) continue;
        jointed = false;
        if (crossingBetween(graph_, plate, other) >= 0) {
          crossingPartners.insert(other);
          hold = FirstStepHold::Crossings;
        }
      }
      if (jointed && !makeStep(node, plate, d).blocked) hold = FirstStepHold::Free;
    }
    if (hold == FirstStepHold::Free) {
      ++free;
    } else if (hold == FirstStepHold::Crossings) {
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

}  // namespace desia
