// SPDX-License-Identifier: GPL-3.0-or-later
// The plate joint planner (paper Section 5.2), on the construction tree of Algorithm 1.
//
// A node of the tree is A_i = [P_1, ..., P_i, R_i]: the plates taken so far, each with its removal
// direction d_i, and R_i, the plates not taken yet, which act as one part. Taking P_i gives a joint
// between P_i and each plate of R_i it touches (R'_i). Candidates for P_i are the plates of R_{i-1}
// that are not cut points of R_{i-1}'s parts-graph (R_i must stay connected); candidates for d_i
// are the edge vectors P_i shares with its neighbours, its thickness axis and the directions its
// tenons could leave in, both signs, that do not push P_i into a plate it touches. A child is kept
// when A_i is interlocking with P_1 as its key (for i >= 2; for A_1, when P_1 is free along d_1
// alone), and children are ranked by their number of empty joints, fewest first.
//
// The joints are those the joint families make (joints/joint_families.h asks them in turn): where
// P_i and a neighbour have a tenon site whose tenons leave along d_i, a mortise-and-tenon joint,
// with the contacts its faces will have: the shoulder, the tenons' cheeks (+-the tenon plate's
// thickness axis) and ends (+-along the edge); milled joints likewise with their own faces.
// Otherwise an empty joint: the plates' own contact faces. The paper's halved joints
// (slots along d_i) join plates that cross (computePlateContacts finds crossings): the mover
// leaves along the crossing line, its slot behind it, the other's ahead. An open mortise lets its
// tenon plate leave two ways; the model says so, and the tests decide.
// A complete plan is cut into the plates and verified on that geometry before it is reported.
#include "plate/plate_planner.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/error.h"
#include "desia/model.h"
#include "desia/tolerances.h"
#include "plate/joints/halved.h"
#include "plate/plate_verification.h"
#include "plate/swept_collision.h"

namespace desia {

PlateJointPlanner::PlateJointPlanner(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                     const PlateDesignOptions& options)
    : plates_(plates),
      graph_(buildPlateGraph(plates, contacts, options.realization)),
      options_(options),
      families_(graph_, options_.joints, options_.realization),
      random_(options.seed * 0x9E3779B97F4A7C15ull + 1) {
  for (const Plate& plate : plates) meshes_.push_back(plateMesh(plate));
  meshIndex_.emplace(meshes_);
  for (int plate = 0; plate < graph_.plateCount; ++plate) {
    std::vector<Vec3> ways;
    for (const Vec3& d : rawCandidateDirections(plate)) ways.push_back(canonical(d));
    canonicalDirections_.push_back(ways);
    lastInTheWay_.push_back(std::vector<int>(ways.size(), -1));
  }
}

// The edge vectors the plate shares with its neighbours (paper Section 5.2), both signs, and, beyond
// the paper, its own thickness axis (a plate closed in on every edge can only leave across its
// faces) and the axes of its tenon sites (the only ways a tenon joint lets it leave).
// One vector for each way out that several plates share: edges meant to be parallel, computed from
// a design given to a micrometre, differ by 1e-7 rad, and a contact square to one of them would
// block the other by more than the tests' tolerance::kDirection (squaredToPlan makes contacts square to the plan's
// directions, which it can only do if they are one vector). The first plate's vector stands for all.
Vec3 PlateJointPlanner::canonical(const Vec3& d) {
  constexpr double kSameWay = 1 - tolerance::kExactCosine;
  for (const Vec3& known : canonical_) {
    if (dot(known, d) > kSameWay) return known;
    if (dot(known, d) < -kSameWay) return negated(known);
  }
  canonical_.push_back(d);
  return d;
}

const std::vector<Vec3>& PlateJointPlanner::candidateDirections(int plate) const {
  return canonicalDirections_[static_cast<size_t>(plate)];
}

std::vector<Vec3> PlateJointPlanner::rawCandidateDirections(int plate) const {
  std::vector<Vec3> directions;
  std::vector<Vec3> lines = graph_.edgeTo[plate];
  lines.push_back(graph_.thicknessAxis[plate]);
  for (int c : graph_.contactsOf[plate]) families_.addWaysOut(c, plate, lines);
  for (const Vec3& edge : lines) {
    for (const Vec3& d : {edge, negated(edge)}) {
      bool known = false;
      for (const Vec3& existing : directions) known = known || (parallel(existing, d) && dot(existing, d) > 0);
      if (!known) directions.push_back(d);
    }
  }
  return directions;
}

PlateJointPlanner::NodeFacts PlateJointPlanner::factsOf(const std::vector<PlanStep>& steps) const {
  NodeFacts node;
  node.taken.assign(graph_.plateCount, false);
  node.cutsOn.resize(graph_.plateCount);
  for (const PlanStep& s : steps) {
    node.taken[s.plate] = true;
    for (const CutFootprint& cut : s.cuts) node.cutsOn[cut.plate].push_back(&cut);
  }
  return node;
}

PlanStep PlateJointPlanner::makeStep(const NodeFacts& node, int plate, const Vec3& d) const {
  const std::vector<bool>& taken = node.taken;
  PlanStep step;
  step.plate = plate;
  step.direction = d;
  for (int other : graph_.neighbours[plate]) {
    if (taken[other]) continue;
    const std::optional<PlateJoint> joint = families_.jointFor(plate, other, d);
    if (!joint) {
      step.blocked = true;
      continue;
    }
    step.joints.push_back(*joint);
    step.emptyJoints += joint->type == JointType::Empty ? 1 : 0;
  }
  if (makesJoints(options_.realization) && !step.blocked) {
    step.cuts = cutsOf(step.joints);
    step.blocked = cutsCollide(node, step.cuts);
  }
  return step;
}

// Where the joints cut into the plates (as cutPlan verifies them).
std::vector<CutFootprint> PlateJointPlanner::cutsOf(const std::vector<PlateJoint>& joints) const {
  return families_.footprints(joints);
}

// Would the new cuts run into each other or into the cuts of the steps before? Then no plan
// through this step can be cut (cutJoints refuses it): drop the step now, not after every
// ordering of the plates after it has been tried (BOOKSHELF: a mortise from below and a dovetail
// housing from above at the same place in a shelf).
// Only cuts in one plate can overlap: the node's cuts are looked up by plate.
bool PlateJointPlanner::cutsCollide(const NodeFacts& node, const std::vector<CutFootprint>& cuts) const {
  for (size_t i = 0; i < cuts.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (footprintsOverlap(plates_, cuts[i], cuts[j])) return true;
    }
    for (const CutFootprint* earlier : node.cutsOn[cuts[i].plate]) {
      if (footprintsOverlap(plates_, cuts[i], *earlier)) return true;
    }
  }
  return false;
}

// A_1: the key is free along d_1 and along no other base direction of its joints. A_i (i >= 2):
// interlocking with P_1 as the only movable part (the DBG test on the joint contacts; heldByInequalities adds the LP test).
std::shared_ptr<JointNodeModel> PlateJointPlanner::nodeModelOf(const std::vector<PlanStep>& steps) const {
  auto node = std::make_shared<JointNodeModel>();
  node->model = jointModel(graph_, families_, steps);
  node->bases = computeBaseDirections(node->model);
  return node;
}

std::shared_ptr<const JointNodeModel> PlateJointPlanner::acceptedModel(const std::vector<PlanStep>& steps) const {
  std::shared_ptr<JointNodeModel> node = nodeModelOf(steps);
  if (steps.size() == 1) {
    for (const BaseDirection& base : node->bases) {
      for (const Vec3& d : {base.vector, negated(base.vector)}) {
        const bool free = isPartFreeAlong(node->model, nullptr, 0, d);
        const bool planned = parallel(d, steps[0].direction) && dot(d, steps[0].direction) > 0;
        if (free != planned) return nullptr;
      }
    }
    return node;
  }
  const InterlockingResult result = testInterlockingByGraphs(node->model, node->bases);
  return result.verdict == Verdict::Interlocking && result.key == 0 ? std::move(node) : nullptr;
}

// The node's A_i interlocking by the LP test too, with P_1 as the only movable part. The DBG test
// (acceptable, on every child ranked) sees only parts that move along one direction together; the
// LP test (paper Section 4.2) also parts that move at once in different directions (a plate
// leaving together with the key), which the verification of every complete plan would otherwise
// find only many steps later. Made when a node is entered, as its cost (ms on 100 plates) is too
// much for every child ranked; made from the first node on, as a node it prunes early saves the
// subtree below it, while designs it never prunes pay its cost at every node.
bool PlateJointPlanner::heldByInequalities(const std::vector<PlanStep>& path) const {
  if (path.size() < 2) return true;
  std::shared_ptr<const JointNodeModel> node = path.back().nodeModel;
  if (!node) node = nodeModelOf(path);
  if (hasSquareNormalsOnly(node->model)) return true;
  const InterlockingResult result = testInterlockingByInequalities(node->model, node->bases);
  return result.verdict == Verdict::Interlocking && result.key == 0;
}

// Would the plate, as given, leaving along d run into a plate of R (touching it or not; plates that
// cross part by their slots)? Joints only make room where plates meet, so the step cannot be part
// of a plan that verifies: skip it now rather than when a complete plan's sweep fails (the TABLE's
// divider would hit the back apron; the LIZARD's plate 34 ran 13 mm into plate 2 beyond their mitre).
// Whether a plate is in the way depends on the two plates alone: the last one found stays in the
// way while it is in place, and only the plates whose bounds reach into the swept region are tried.
bool PlateJointPlanner::runsIntoARemainingPlate(int plate, size_t way, const std::vector<bool>& taken) const {
  int& last = lastInTheWay_[plate][way];
  if (last >= 0 && !taken[last]) return true;
  const Vec3& d = candidateDirections(plate)[way];
  const double tolerance = options_.geometry.contactTolerance;
  return meshIndex_->anyInTheWay(plate, d, tolerance, [&](int q) {
    // Plates that cross part by their slots; the others, touching or not, must let it pass.
    if (taken[q] || crossingBetween(graph_, plate, q) >= 0) return false;
    if (!meshCollidesAlong(meshes_[plate], meshes_[q], d, tolerance)) return false;
    last = q;
    return true;
  });
}

// Would the plate just taken (the path's last step), with the joints made so far cut into it and
// into the plates still in place, run into one of them as it leaves? Joints made at earlier steps
// leave solids standing on plates still in place (a tenon or tongue whose partner has left, the
// wood round a pocket), which the plates as given do not show: the LIZARD's plate 33 ran into such
// a solid on plate 1, which stays to the end, and 64 complete plans failed on it. Later joints
// only cut between plates still in place, so such a collision stays; the check is made when a node
// is entered (its cut costs milliseconds, too much for every child ranked).
bool PlateJointPlanner::runsIntoJointsSoFar(const std::vector<PlanStep>& path) const {
  std::vector<PlateJoint> joints;
  std::vector<bool> taken(graph_.plateCount, false);
  for (const PlanStep& step : path) {
    joints.insert(joints.end(), step.joints.begin(), step.joints.end());
    taken[step.plate] = true;
  }
  const PlanStep& last = path.back();
  try {
    const Plate& mover = jointedPlate(last.plate, joints);
    std::optional<TriangleMesh> moverMesh;
    for (int q = 0; q < graph_.plateCount; ++q) {
      if (taken[q] || crossingBetween(graph_, last.plate, q) >= 0) continue;
      const Plate& obstacle = jointedPlate(q, joints);
      // Only solids the joints attach stand where the plates as given do not (runsIntoARemainingPlate).
      if (obstacle.attached.empty() && mover.attached.empty()) continue;
      if (!moverMesh) moverMesh = plateMesh(mover);
      if (meshCollidesAlong(*moverMesh, plateMesh(obstacle), last.direction, options_.geometry.contactTolerance))
        return true;
    }
  } catch (const Error&) {
    return true;  // cuts that run into each other: no plan through here can be cut
  }
  return false;
}

// `plate` with those of `joints` it has cut into it (and their solids attached).
const Plate& PlateJointPlanner::jointedPlate(int plate, const std::vector<PlateJoint>& joints) const {
  std::vector<PlateJoint> mine;
  std::string key = std::to_string(plate);
  for (const PlateJoint& joint : joints) {
    if ((joint.mover != plate && joint.other != plate) || joint.type == JointType::Empty) continue;
    mine.push_back(joint);
    key += ' ' + std::to_string(joint.mover) + ',' + std::to_string(joint.other) + ',' +
           std::to_string(static_cast<int>(joint.type)) + ',' + std::to_string(joint.contact);
    for (double c : joint.direction) {
      uint64_t bits = 0;
      std::memcpy(&bits, &c, sizeof bits);
      key += ',' + std::to_string(bits);
    }
  }
  if (mine.empty()) return plates_[static_cast<size_t>(plate)];
  const auto known = jointedCache_.find(key);
  if (known != jointedCache_.end()) return known->second;
  if (jointedCache_.size() > 20000) jointedCache_.clear();
  Plate jointed = jointedPlates(plates_, families_, mine, 0, options_.joints)[static_cast<size_t>(plate)];
  return jointedCache_.emplace(key, std::move(jointed)).first->second;
}

// The ranked children of a node: every plate of R that is not a cut point of R's parts-graph,
// with every direction it may leave in, kept if A_i passes; fewest empty joints first, ties in a
// seeded random order; at most `candidates` of them.
// Every way the next plate can leave, ranked: the paper's preference (below), then a random order
// from the seed. The node test is left to nextChild.
// The plates of R (those not taken) whose removal would split R's parts-graph.
std::vector<bool> PlateJointPlanner::cutPointsOfRest(const std::vector<bool>& taken) const {
  std::vector<int> rest, index(graph_.plateCount, -1);
  for (int p = 0; p < graph_.plateCount; ++p) {
    if (!taken[p]) {
      index[p] = static_cast<int>(rest.size());
      rest.push_back(p);
    }
  }
  std::vector<std::pair<int, int>> restEdges;
  for (int p : rest) {
    for (int q : graph_.neighbours[p]) {
      if (!taken[q] && p < q) restEdges.push_back({index[p], index[q]});
    }
  }
  std::vector<bool> isCut(graph_.plateCount, false);
  for (int i : findCutPoints(static_cast<int>(rest.size()), restEdges)) isCut[rest[i]] = true;
  return isCut;
}

std::vector<PlanStep> PlateJointPlanner::candidatesOf(const std::vector<PlanStep>& steps) {
  std::vector<bool> taken(graph_.plateCount, false);
  for (const PlanStep& s : steps) taken[s.plate] = true;
  std::vector<int> rest;
  for (int p = 0; p < graph_.plateCount; ++p) {
    if (!taken[p]) rest.push_back(p);
  }
  const std::vector<bool> isCut = cutPointsOfRest(taken);

  const NodeFacts node = factsOf(steps);
  std::vector<bool> inRest(graph_.plateCount);
  for (int p = 0; p < graph_.plateCount; ++p) inRest[p] = !taken[p];
  std::vector<std::pair<uint64_t, PlanStep>> ranked;
  for (int plate : rest) {
    if (isCut[plate]) continue;
    const std::vector<Vec3>& ways = candidateDirections(plate);
    for (size_t way = 0; way < ways.size(); ++way) {
      const Vec3& d = ways[way];
      if (!leavesWithoutPushing(graph_, plate, inRest, d)) continue;
      if (runsIntoARemainingPlate(plate, way, taken)) continue;
      PlanStep step = makeStep(node, plate, d);
      if (step.blocked) continue;
      ranked.push_back({nextRandom(), std::move(step)});
    }
  }
  // The paper picks the key with the most edges parallel to d_1, for its halved joints (planned
  // joints only: cut halved joints need crossing plates). Then fewest empty joints first.
  auto parallelEdges = [&](const PlanStep& step) {
    if (!steps.empty() || options_.realization != JointRealization::Planned) return 0;
    int count = 0;
    for (const Vec3& edge : graph_.edgeTo[step.plate]) count += parallel(edge, step.direction) ? 1 : 0;
    return count;
  };
  // Among those, the plates with the fewest neighbours still in place first: peeling the rest from
  // its edges keeps it in one piece with room to part. Without it the BOOKCASE's milled searches
  // died 110-117 plates deep after an early choice from its middle (seeds 1-12: 7 found a plan
  // within 3,000 nodes; with it seeds 1-8 all did, 6 of them in the first restart).
  std::vector<int> restDegree(graph_.plateCount, 0);
  for (int p : rest) {
    for (int q : graph_.neighbours[p]) restDegree[p] += taken[q] ? 0 : 1;
  }
  std::sort(ranked.begin(), ranked.end(), [&](const auto& x, const auto& y) {
    if (parallelEdges(x.second) != parallelEdges(y.second)) return parallelEdges(x.second) > parallelEdges(y.second);
    if (x.second.emptyJoints != y.second.emptyJoints) return x.second.emptyJoints < y.second.emptyJoints;
    if (restDegree[x.second.plate] != restDegree[y.second.plate]) return restDegree[x.second.plate] < restDegree[y.second.plate];
    return x.first < y.first;
  });
  std::vector<PlanStep> candidates;
  for (auto& [key, step] : ranked) candidates.push_back(std::move(step));
  return candidates;
}

// The node's children as the paper keeps them: its ranked candidates that pass the node test
// (acceptable), the first m (options_.candidates) of them.
std::vector<PlanStep> PlateJointPlanner::childrenOf(const std::vector<PlanStep>& steps) {
  RankedCandidates candidates = rankedCandidatesOf(steps);
  std::vector<PlanStep> path = steps;
  std::vector<PlanStep> children;
  while (std::optional<PlanStep> child = nextChild(&path, &candidates)) {
    child->nodeModel.reset();  // kept for the search's LP test on entering only
    children.push_back(std::move(*child));
  }
  return children;
}

namespace {
constexpr size_t kCandidateWindow = 32;
}  // namespace

void PlateJointPlanner::takeWindow(std::vector<PlanStep> ranked, RankedCandidates* candidates) const {
  const size_t start = std::min(candidates->windowStart, ranked.size());
  const size_t end = std::min(start + kCandidateWindow, ranked.size());
  candidates->window.assign(std::make_move_iterator(ranked.begin() + static_cast<long>(start)),
                            std::make_move_iterator(ranked.begin() + static_cast<long>(end)));
  candidates->next = 0;
  candidates->rankedAll = end == ranked.size();
}

PlateJointPlanner::RankedCandidates PlateJointPlanner::rankedCandidatesOf(const std::vector<PlanStep>& steps) {
  RankedCandidates candidates;
  candidates.randomState = random_;
  takeWindow(candidatesOf(steps), &candidates);
  return candidates;
}

// The search asks for children one at a time: the node test (a model of all contacts and its DBGs,
// milliseconds on 400 plates) is made only for the children it enters, not for every candidate of
// every node it passes.
std::optional<PlanStep> PlateJointPlanner::nextChild(std::vector<PlanStep>* path, RankedCandidates* candidates) {
  while (candidates->accepted < options_.candidates) {
    if (candidates->next == candidates->window.size()) {
      if (candidates->rankedAll) break;
      // Ranked again as first ranked; the tie-breaking stream goes on where it was.
      const uint64_t state = random_;
      random_ = candidates->randomState;
      candidates->windowStart += candidates->window.size();
      takeWindow(candidatesOf(*path), candidates);
      random_ = state;
      if (candidates->window.empty()) break;
    }
    path->push_back(std::move(candidates->window[candidates->next++]));
    std::shared_ptr<const JointNodeModel> model = acceptedModel(*path);
    PlanStep child = std::move(path->back());
    path->pop_back();
    if (model) {
      ++candidates->accepted;
      child.nodeModel = std::move(model);
      return child;
    }
  }
  candidates->window.clear();
  candidates->next = 0;
  candidates->rankedAll = true;
  return std::nullopt;
}

std::optional<PlateDesignResult> PlateJointPlanner::refusal() const {
  PlateDesignResult result;
  result.progress.targetParts = graph_.plateCount;
  const std::vector<int> cuts = findCutPoints(graph_.plateCount, [&] {
    std::vector<std::pair<int, int>> edges;
    for (const PlateContact& c : graph_.contacts) edges.push_back({c.a, c.b});
    return edges;
  }());
  if (!cuts.empty()) {
    result.status = DesignStatus::CutPoint;
    result.message =
        "plate " + std::to_string(plates_[cuts[0]].id) +
        " is a cut point of the parts-graph: taking it away splits the other plates, and no joints can make such "
        "a structure interlocking (paper Section 5.2, Fig. 18); add a plate or bar that joins the two sides";
    return result;
  }
  // Plates crossing at a slant part only along their crossing line, through notches a laser cannot
  // cut (their walls slanted to the sheet): no cut plan exists, so say why before searching.
  if (options_.realization == JointRealization::Cut) {
    const std::string slanted = slantedCrossingsNeedMilling(graph_);
    if (!slanted.empty()) {
      result.status = DesignStatus::NotFound;
      result.message = "no interlocking joint plan exists with the joints that can be cut: " + slanted;
      return result;
    }
  }
  if (graph_.plateCount < 3) {
    result.message =
        "an interlocking structure needs at least three plates; this one has " + std::to_string(graph_.plateCount);
    return result;
  }
  return std::nullopt;
}

// Cuts the joints into the plates and verifies the plan there; keeps the jointed plates on success.
bool PlateJointPlanner::cutAndVerify(const std::vector<PlateJoint>& joints, const std::vector<int>& order,
                                     const std::vector<Vec3>& directions, PlateDesignResult* result) {
  try {
    JointedPlan jointed = cutPlan(plates_, families_, joints, order, directions, options_.geometry, options_.joints);
    lastRejection_ = jointed.verification.failure;
    lastDoomedDepth_ = jointed.verification.hitPosition;
    if (!lastRejection_.empty()) return false;
    result->jointedPlates = std::move(jointed.plates);
    result->jointAssembly = std::move(jointed.verification.assembly);
    result->clearance = options_.joints.clearance;
    result->fabricationPlates =
        options_.joints.clearance > 0
            ? cutPlates(plates_, families_, joints, options_.geometry, options_.joints.clearance, options_.joints)
            : result->jointedPlates;
    return true;
  } catch (const Error& error) {  // cuts that split a plate or run into each other: not this plan
    lastRejection_ = error.what();
    return false;
  }
}

// A complete plan: its order (the steps' plates, then the one left), its joints cut into the
// plates and verified there. On success the result holds the plan and its jointed plates.
bool PlateJointPlanner::acceptComplete(const std::vector<PlanStep>& path, PlateDesignResult* result) {
  std::vector<bool> taken(graph_.plateCount, false);
  std::vector<int> order;
  std::vector<Vec3> directions;
  std::vector<PlateJoint> joints;
  for (const PlanStep& step : path) {
    taken[step.plate] = true;
    order.push_back(step.plate);
    directions.push_back(step.direction);
    joints.insert(joints.end(), step.joints.begin(), step.joints.end());
  }
  order.push_back(static_cast<int>(std::find(taken.begin(), taken.end(), false) - taken.begin()));
  if (options_.realization == JointRealization::Planned) {
    // Nothing is cut: the joint model is the result, verified as `desia check` verifies it.
    Assembly model = jointModel(graph_, families_, path);
    model.parts.back() = {plates_[order.back()].id, plates_[order.back()].name};
    std::vector<Plate> inRemovalOrder;
    for (int plate : order) inRemovalOrder.push_back(plates_[plate]);
    const PlateRemovalVerification verification = verifyPlannedPlates(model, inRemovalOrder, directions, options_.geometry);
    lastRejection_ = verification.failure;
    lastDoomedDepth_ = verification.hitPosition;
    if (!lastRejection_.empty()) return false;
    result->jointAssembly = model;
  } else if (!cutAndVerify(joints, order, directions, result)) {
    // Joints made: the jointed plates are the judge, not the model. The model lists each joint's
    // faces but not every solid of a milled joint; exact (snapped) normals showed it letting the
    // LIZARD's plate 35 leave with the key where its jointed plates hold it.
    return false;
  }
  // A joint leaves along its mover's way out.
  for (PlateJoint& joint : joints)
    joint.direction = directions[static_cast<size_t>(std::find(order.begin(), order.end(), joint.mover) - order.begin())];
  result->realization = options_.realization;
  result->order = order;
  result->directions = directions;
  result->joints = joints;
  result->status = DesignStatus::Success;
  return true;
}

}  // namespace desia
