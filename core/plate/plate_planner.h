// SPDX-License-Identifier: GPL-3.0-or-later
// The plate joint planner (paper Section 5.2) on the construction tree of Algorithm 1: the ranked
// children of a node, the node tests, and a complete plan cut and verified (plate_planner.cpp);
// the restarted search over the tree (planner_search.cpp). designPlateJoints and the step-by-step
// session (plate_design.cpp) both drive it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/plate.h"
#include "plate/joint_model.h"
#include "plate/joints/joint_families.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"

namespace desia {

// One design's planner: its plates' graph, the joint families it may use, its seeded tie-breaking
// and what it learnt from the complete plans that failed. It refers to `plates` (kept by the
// caller) and to its own members: not copied.
class PlateJointPlanner {
 public:
  PlateJointPlanner(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                    const PlateDesignOptions& options);
  PlateJointPlanner(const PlateJointPlanner&) = delete;
  PlateJointPlanner& operator=(const PlateJointPlanner&) = delete;

  // The restarted search below the node `prefix` (the root: a whole design); the prefix's steps
  // stay, restarts re-seed below that node.
  PlateDesignResult run(const std::vector<PlanStep>& prefix = {});
  class SearchTree;

  // What the search and a step-by-step session share.
  // A structure no joints can make interlocking (a cut point, fewer than 3 plates): its result.
  std::optional<PlateDesignResult> refusal() const;
  std::vector<PlanStep> childrenOf(const std::vector<PlanStep>& steps);
  std::vector<PlanStep> candidatesOf(const std::vector<PlanStep>& steps);
  // A node's ranked candidates, taken from the front. Only a window of them is kept: a design of
  // thousands of plates has thousands at each of thousands of depths (a LONG TABLE of 9,998
  // plates held 2.6 GB of them 592 deep). When the window runs out the node is ranked again from
  // the tie-breaking state it was first ranked with, which gives the same order.
  struct RankedCandidates {
    std::vector<PlanStep> window;
    size_t next = 0;          // the window's next one
    size_t windowStart = 0;   // its rank in the node's whole ranking
    bool rankedAll = true;    // the window ends the ranking
    uint64_t randomState = 0; // the tie-breaking state the node was ranked with
    int accepted = 0;         // how many passed the node test
  };
  RankedCandidates rankedCandidatesOf(const std::vector<PlanStep>& steps);
  // The next candidate of the node `path` that passes the node test, while fewer than m have
  // passed; none when none is left. `path` is the same on return.
  std::optional<PlanStep> nextChild(std::vector<PlanStep>* path, RankedCandidates* candidates);
  bool acceptComplete(const std::vector<PlanStep>& path, PlateDesignResult* result);
  int plateCount() const { return graph_.plateCount; }
  const std::string& lastRejection() const { return lastRejection_; }
  // Why no plate can be the first step, for a search that ended at its root (planner_first_step.cpp).
  std::string whyNoPlateLeavesFirst() const;
  // Why no plate of R can be taken after `path` (the deepest node of a search that got no further),
  // plate by plate: how far each gets through the node's tests (planner_first_step.cpp).
  std::string whyNoPlateLeavesAfter(const std::vector<PlanStep>& path) const;
  std::string atTheDeepestNode(const std::vector<PlanStep>& deepest) const;
  void backjump(size_t prefixSize, std::vector<PlanStep>* path, std::vector<RankedCandidates>* pending) const;

 private:
  bool acceptable(const std::vector<PlanStep>& steps) const { return acceptedModel(steps) != nullptr; }
  // The joint model of the node `steps` ends in (its contacts and base directions).
  std::shared_ptr<JointNodeModel> nodeModelOf(const std::vector<PlanStep>& steps) const;
  // The node test's model of the node `steps` ends in when it passes, else null.
  std::shared_ptr<const JointNodeModel> acceptedModel(const std::vector<PlanStep>& steps) const;
  std::vector<bool> cutPointsOfRest(const std::vector<bool>& taken) const;
  enum class NextStepStage;
  NextStepStage furthestStage(const std::vector<PlanStep>& path, int plate, const std::vector<bool>& isCutPoint,
                              std::set<int>* crossingPartners) const;
  void takeWindow(std::vector<PlanStep> ranked, RankedCandidates* candidates) const;
  bool runsIntoARemainingPlate(int plate, size_t way, const std::vector<bool>& taken) const;
  bool runsIntoJointsSoFar(const std::vector<PlanStep>& path) const;
  bool heldByInequalities(const std::vector<PlanStep>& path) const;
  const Plate& jointedPlate(int plate, const std::vector<PlateJoint>& joints) const;
  bool cutAndVerify(const std::vector<PlateJoint>& joints, const std::vector<int>& order,
                    const std::vector<Vec3>& directions, PlateDesignResult* result);
  // What every candidate of a node asks of it: the plates taken, and the cuts of its steps by plate.
  struct NodeFacts {
    std::vector<bool> taken;
    std::vector<std::vector<const CutFootprint*>> cutsOn;
  };
  NodeFacts factsOf(const std::vector<PlanStep>& steps) const;
  PlanStep makeStep(const NodeFacts& node, int plate, const Vec3& d) const;
  std::vector<CutFootprint> cutsOf(const std::vector<PlateJoint>& joints) const;
  bool cutsCollide(const NodeFacts& node, const std::vector<CutFootprint>& cuts) const;
  const std::vector<Vec3>& candidateDirections(int plate) const;
  std::vector<Vec3> rawCandidateDirections(int plate) const;
  Vec3 canonical(const Vec3& d);
  std::vector<Vec3> canonical_;                        // see canonical()
  std::vector<std::vector<Vec3>> canonicalDirections_;  // each plate's candidate ways out, canonical
  uint64_t nextRandom() {
    random_ = random_ * 6364136223846793005ull + 1442695040888963407ull;
    return random_ >> 11;
  }

  const std::vector<Plate>& plates_;
  PlateGraph graph_;
  PlateDesignOptions options_;
  JointFamilies families_;  // what joints the pairs can take (on graph_, with options_.joints)
  uint64_t random_;
  std::string lastRejection_;  // why the last complete plan failed
  // When the last complete plan failed because a jointed plate, swept out, ran into the plate
  // taken at this depth of the path: every plan through the path's first depth + 1 steps fails so.
  int lastDoomedDepth_ = -1;
  // Plates with their joints cut (runsIntoJointsSoFar), by plate and the joints they have: a node
  // changes only its plate and the plates it leaves; cleared when it grows large.
  mutable std::map<std::string, Plate> jointedCache_;
  std::vector<TriangleMesh> meshes_;  // the plates as given (for the sweep of each step)
  std::optional<SweptBoxIndex> meshIndex_;  // their bounds, for the sweep's first test
  // For each plate and way out (candidateDirections' index), the last plate found in its way
  // (-1: none yet): while that plate is in place, the way is blocked, whatever else has left.
  mutable std::vector<std::vector<int>> lastInTheWay_;
};

}  // namespace desia
