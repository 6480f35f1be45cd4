// SPDX-License-Identifier: GPL-3.0-or-later
// Joint design for plate structures (paper Section 5.2), on the construction tree of Algorithm 1.
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
// The joints are those cuts can make (core/plate/joints/): where P_i and a neighbour have a tenon
// site whose tenons leave along d_i, a mortise-and-tenon joint, with the contacts its faces will
// have: the shoulder, the tenons' cheeks (+-the tenon plate's thickness axis) and ends (+-along
// the edge). Otherwise an empty joint: the plates' own contact faces. The paper's halved joints
// (slots along d_i) join plates that cross (computePlateContacts finds crossings): the mover
// leaves along the crossing line, its slot behind it, the other's ahead. An open mortise lets its
// tenon plate leave two ways; the model says so, and the tests decide.
// A complete plan is cut into the plates and verified on that geometry before it is reported.
#include "desia/plate_design.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "search/construction_search.h"
#include "search/restarts.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"
#include "plate/plan_squaring.h"
#include "plate/plate_verification.h"
#include "plate/swept_collision.h"
#include "desia/cut_points.h"
#include "desia/error.h"
#include "desia/interlocking.h"

namespace desia {
namespace {

// Can `plate` leave each plate in `others` along d without pushing into it (its contact faces)?
bool leavesWithoutPushing(const PlateGraph& graph, int plate, const std::vector<bool>& inOthers, const Vec3& d) {
  for (int c : graph.contactsOf[plate]) {
    const PlateContact& contact = graph.contacts[c];
    const int other = contact.a == plate ? contact.b : contact.a;
    if (!inOthers[other]) continue;
    const double push = dot(d, contact.a == plate ? contact.normal : negated(contact.normal));
    if (push > 1e-9) return false;
  }
  return true;
}

// One planned step: plate P_i leaves along d_i; its joints with the plates of R'_i.
struct Step {
  int plate = -1;
  Vec3 direction{0, 0, 0};
  std::vector<PlateJoint> joints;
  int emptyJoints = 0;
  bool blocked = false;  // a crossing plate cannot part along the direction, or the joints' cuts collide
  std::vector<CutFootprint> cuts;  // where the joints cut into the plates (joints made only)
};

// The assembly of A_i: parts 0..i-1 are the steps' plates, part i (when any plate is left) is R_i.
// Every contact of a joint's two plates keeps its faces, except the one the joint is made in,
// which gets the faces of the joint (JointFamily::faceNormals: for tenons the shoulder, their
// cheeks and their ends).
Assembly modelAssembly(const PlateGraph& graph, const JointFamilies& families, const std::vector<Step>& steps) {
  const std::vector<Plate>& plates = graph.plates;
  std::vector<int> node(graph.plateCount, static_cast<int>(steps.size()));  // R_i by default
  Assembly assembly;
  for (size_t k = 0; k < steps.size(); ++k) {
    node[steps[k].plate] = static_cast<int>(k);
    assembly.parts.push_back({plates[steps[k].plate].id, plates[steps[k].plate].name});
  }
  if (static_cast<int>(steps.size()) < graph.plateCount) assembly.parts.push_back({0, "rest"});
  for (const Step& step : steps) {
    for (const PlateJoint& joint : step.joints) {
      const int a = node[joint.mover], b = node[joint.other];
      if (families.keepsOtherContacts(joint)) {
        for (int c : graph.contactsOf[joint.mover]) {
          const PlateContact& contact = graph.contacts[c];
          if (c == joint.contact || contact.crossing) continue;
          if (contact.a == joint.mover && contact.b == joint.other)
            assembly.contacts.push_back({a, b, contact.normal, contact.area});
          if (contact.b == joint.mover && contact.a == joint.other)
            assembly.contacts.push_back({a, b, negated(contact.normal), contact.area});
        }
      }
      for (const Vec3& n : families.faceNormals(joint)) assembly.contacts.push_back({a, b, *cleanedNormal(n), 1.0});
    }
  }
  return assembly;
}

// A complete plan made real: its joints cut into the plates (no clearance: the geometry the tests
// judge), in input order, and its verification on them (in removal order, as `desia check` reads
// the result: verifyJointedPlates).
struct JointedPlan {
  std::vector<Plate> plates;
  PlateRemovalVerification verification;
};

// The plates with the joints cut into them (and their milled solids attached).
std::vector<Plate> jointedPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                                 const std::vector<PlateJoint>& joints, double clearance,
                                 const JointCutOptions& options) {
  JointCutOptions cut = options;
  cut.clearance = clearance;
  return cutJoints(plates, families.cuts(joints, clearance), cut);
}

// The plates with the plan's joints cut, validated and snapped to their design as any plate read
// from a file is (so that the plates verified are the plates `desia check` reads back).
std::vector<Plate> cutPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                             const std::vector<PlateJoint>& joints, const PlateOptions& geometry, double clearance,
                             const JointCutOptions& options) {
  std::vector<Plate> cut = jointedPlates(plates, families, joints, clearance, options);
  validatePlates(cut, geometry, "the jointed plates");
  return regularizedPlates(cut, geometry, PlateOrigin::Computed);
}

JointedPlan cutPlan(const std::vector<Plate>& plates, const JointFamilies& families, const std::vector<PlateJoint>& joints,
                    const std::vector<int>& order, const std::vector<Vec3>& directions, const PlateOptions& geometry,
                    const JointCutOptions& options) {
  JointedPlan plan;
  plan.plates = cutPlates(plates, families, joints, geometry, 0, options);
  std::vector<Plate> inRemovalOrder;
  for (int plate : order) inRemovalOrder.push_back(plan.plates[plate]);
  plan.verification = verifyJointedPlates(inRemovalOrder, directions, geometry);
  return plan;
}

class PlateJointPlanner {
 public:
  PlateJointPlanner(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                    const PlateDesignOptions& options)
      : plates_(plates),
        graph_(buildPlateGraph(plates, contacts, options.realization)),
        options_(options),
        families_(graph_, options_.joints, options_.realization),
        random_(options.seed * 0x9E3779B97F4A7C15ull + 1) {
    for (const Plate& plate : plates) meshes_.push_back(plateMesh(plate));
    for (int plate = 0; plate < graph_.plateCount; ++plate) {
      std::vector<Vec3> ways;
      for (const Vec3& d : rawCandidateDirections(plate)) ways.push_back(canonical(d));
      canonicalDirections_.push_back(ways);
    }
  }

  // The restarted search below the node `prefix` (the root: a whole design); the prefix's steps
  // stay, restarts re-seed below that node.
  PlateDesignResult run(const std::vector<Step>& prefix = {});
  class SearchTree;
  void backjump(size_t prefixSize, std::vector<Step>* path, std::vector<std::vector<Step>>* pending) const;

  // What the search and a step-by-step session share.
  // A structure no joints can make interlocking (a cut point, fewer than 3 plates): its result.
  std::optional<PlateDesignResult> refusal() const;
  std::vector<Step> childrenOf(const std::vector<Step>& steps);
  std::vector<Step> candidatesOf(const std::vector<Step>& steps);
  std::optional<Step> nextChild(const std::vector<Step>& steps, std::vector<Step>* candidates, int* accepted);
  bool acceptComplete(const std::vector<Step>& path, PlateDesignResult* result);
  int plateCount() const { return graph_.plateCount; }
  const std::string& lastRejection() const { return lastRejection_; }

 private:
  bool acceptable(const std::vector<Step>& steps) const;
  bool runsIntoARemainingPlate(int plate, const Vec3& d, const std::vector<int>& rest) const;
  bool runsIntoJointsSoFar(const std::vector<Step>& path) const;
  bool heldByInequalities(const std::vector<Step>& path) const;
  const Plate& jointedPlate(int plate, const std::vector<PlateJoint>& joints) const;
  bool cutAndVerify(const std::vector<PlateJoint>& joints, const std::vector<int>& order,
                    const std::vector<Vec3>& directions, PlateDesignResult* result);
  Step makeStep(const std::vector<Step>& steps, int plate, const Vec3& d) const;
  std::vector<CutFootprint> cutsOf(const std::vector<PlateJoint>& joints) const;
  bool cutsCollide(const std::vector<Step>& steps, const std::vector<CutFootprint>& cuts) const;
  std::vector<Vec3> candidateDirections(int plate) const;
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
};

// The edge vectors the plate shares with its neighbours (paper Section 5.2), both signs, and, beyond
// the paper, its own thickness axis (a plate closed in on every edge can only leave across its
// faces) and the axes of its tenon sites (the only ways a tenon joint lets it leave).
// One vector for each way out that several plates share: edges meant to be parallel, computed from
// a design given to a micrometre, differ by 1e-7 rad, and a contact square to one of them would
// block the other by more than the tests' 1e-9 (squaredToPlan makes contacts square to the plan's
// directions, which it can only do if they are one vector). The first plate's vector stands for all.
Vec3 PlateJointPlanner::canonical(const Vec3& d) {
  constexpr double kSameWay = 1 - 1e-12;  // within 1.4e-6 rad
  for (const Vec3& known : canonical_) {
    if (dot(known, d) > kSameWay) return known;
    if (dot(known, d) < -kSameWay) return negated(known);
  }
  canonical_.push_back(d);
  return d;
}

std::vector<Vec3> PlateJointPlanner::candidateDirections(int plate) const {
  const auto& known = canonicalDirections_[static_cast<size_t>(plate)];
  return known;
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

Step PlateJointPlanner::makeStep(const std::vector<Step>& steps, int plate, const Vec3& d) const {
  std::vector<bool> taken(graph_.plateCount, false);
  for (const Step& s : steps) taken[s.plate] = true;
  Step step;
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
    step.blocked = cutsCollide(steps, step.cuts);
  }
  return step;
}

// Where the joints cut into the plates (as cutPlan verifies them).
std::vector<CutFootprint> PlateJointPlanner::cutsOf(const std::vector<PlateJoint>& joints) const {
  return families_.footprints(joints);
}

// Would the new cuts run into each other or into the cuts of the steps before? Then no plan
// through this step can be cut (cutTenonJoints refuses it): drop the step now, not after every
// ordering of the plates after it has been tried (BOOKSHELF: a mortise from below and a dovetail
// housing from above at the same place in a shelf).
bool PlateJointPlanner::cutsCollide(const std::vector<Step>& steps, const std::vector<CutFootprint>& cuts) const {
  for (size_t i = 0; i < cuts.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (footprintsOverlap(plates_, cuts[i], cuts[j])) return true;
    }
    for (const Step& step : steps) {
      for (const CutFootprint& earlier : step.cuts) {
        if (footprintsOverlap(plates_, cuts[i], earlier)) return true;
      }
    }
  }
  return false;
}

// A_1: the key is free along d_1 and along no other base direction of its joints. A_i (i >= 2):
// interlocking with P_1 as the only movable part (the DBG test on the joint contacts; heldByInequalities adds the LP test).
bool PlateJointPlanner::acceptable(const std::vector<Step>& steps) const {
  const Assembly model = modelAssembly(graph_, families_, steps);
  if (steps.size() == 1) {
    for (const BaseDirection& base : computeBaseDirections(model)) {
      for (const Vec3& d : {base.vector, negated(base.vector)}) {
        const bool free = isPartFreeAlong(model, nullptr, 0, d);
        const bool planned = parallel(d, steps[0].direction) && dot(d, steps[0].direction) > 0;
        if (free != planned) return false;
      }
    }
    return true;
  }
  const InterlockingResult result = testInterlockingByGraphs(model, computeBaseDirections(model));
  return result.verdict == Verdict::Interlocking && result.key == 0;
}

// Do the contact normals lie along at most three mutually square lines? Then the LP test adds
// nothing to the DBG test: the constraints n·(v_b - v_a) >= 0 split into one set per line, so any
// motion is motions along the lines, and the parts moving along one line (all at the speed of the
// fastest) are a motion the DBG along it finds (the BOOKCASE: 123 plates, 614 nodes, 4.5 s of LP
// saved).
bool hasSquareNormalsOnly(const Assembly& model) {
  std::vector<Vec3> lines;
  for (const Contact& contact : model.contacts) {
    bool known = false;
    for (const Vec3& line : lines) {
      const double c = std::abs(dot(line, contact.normal));
      if (c > 1 - 1e-12) {
        known = true;
        break;
      }
      if (c > 1e-12) return false;  // neither along nor square to a line
    }
    if (known) continue;
    if (lines.size() == 3) return false;
    lines.push_back(contact.normal);
  }
  return true;
}

// The node's A_i interlocking by the LP test too, with P_1 as the only movable part. The DBG test
// (acceptable, on every child ranked) sees only parts that move along one direction together; the
// LP test (paper Section 4.2) also parts that move at once in different directions: the LIZARD's
// plate 35 left together with the key in such a motion, found only on every complete plan 30
// steps later (with exact normals; rounding noise of 1e-9 had hidden it). Made when a node is
// entered, as its cost (ms on 100 plates) is too much for every child ranked. Made from the first
// node on: the LIZARD designs in 44 nodes, 7.8 s (made only once a complete plan has failed it:
// 197 nodes, 18 s); the BOOKCASE, which it never prunes, pays 3.2 s -> 7.1 s.
bool PlateJointPlanner::heldByInequalities(const std::vector<Step>& path) const {
  if (path.size() < 2) return true;
  const Assembly model = modelAssembly(graph_, families_, path);
  if (hasSquareNormalsOnly(model)) return true;
  const InterlockingResult result = testInterlockingByInequalities(model, computeBaseDirections(model));
  return result.verdict == Verdict::Interlocking && result.key == 0;
}

// Would the plate, as given, leaving along d run into a plate of R (touching it or not; plates that
// cross part by their slots)? Joints only make room where plates meet, so the step cannot be part
// of a plan that verifies: skip it now rather than when a complete plan's sweep fails (the TABLE's
// divider would hit the back apron; the LIZARD's plate 34 ran 13 mm into plate 2 beyond their mitre).
bool PlateJointPlanner::runsIntoARemainingPlate(int plate, const Vec3& d, const std::vector<int>& rest) const {
  for (int q : rest) {
    // Plates that cross part by their slots; the others, touching or not, must let it pass.
    if (q == plate || crossingBetween(graph_, plate, q) >= 0) continue;
    if (meshCollidesAlong(meshes_[plate], meshes_[q], d, options_.geometry.contactTolerance)) return true;
  }
  return false;
}

// Would the plate just taken (the path's last step), with the joints made so far cut into it and
// into the plates still in place, run into one of them as it leaves? Joints made at earlier steps
// leave solids standing on plates still in place (a tenon or tongue whose partner has left, the
// wood round a pocket), which the plates as given do not show: the LIZARD's plate 33 ran into such
// a solid on plate 1, which stays to the end, and 64 complete plans failed on it. Later joints
// only cut between plates still in place, so such a collision stays; the check is made when a node
// is entered (its cut costs milliseconds, too much for every child ranked).
bool PlateJointPlanner::runsIntoJointsSoFar(const std::vector<Step>& path) const {
  std::vector<PlateJoint> joints;
  std::vector<bool> taken(graph_.plateCount, false);
  for (const Step& step : path) {
    joints.insert(joints.end(), step.joints.begin(), step.joints.end());
    taken[step.plate] = true;
  }
  const Step& last = path.back();
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
std::vector<Step> PlateJointPlanner::candidatesOf(const std::vector<Step>& steps) {
  std::vector<bool> taken(graph_.plateCount, false);
  for (const Step& s : steps) taken[s.plate] = true;
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

  std::vector<std::pair<uint64_t, Step>> ranked;
  for (int plate : rest) {
    if (isCut[plate]) continue;
    std::vector<bool> others = std::vector<bool>(graph_.plateCount, false);
    for (int q : rest) others[q] = q != plate;
    for (const Vec3& d : candidateDirections(plate)) {
      if (!leavesWithoutPushing(graph_, plate, others, d)) continue;
      if (runsIntoARemainingPlate(plate, d, rest)) continue;
      Step step = makeStep(steps, plate, d);
      if (step.blocked) continue;
      ranked.push_back({nextRandom(), std::move(step)});
    }
  }
  // The paper picks the key with the most edges parallel to d_1, for its halved joints (planned
  // joints only: cut halved joints need crossing plates). Then fewest empty joints first.
  auto parallelEdges = [&](const Step& step) {
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
  std::vector<Step> candidates;
  for (auto& [key, step] : ranked) candidates.push_back(std::move(step));
  return candidates;
}

// The node's children as the paper keeps them: its ranked candidates that pass the node test
// (acceptable), the first m (options_.candidates) of them.
std::vector<Step> PlateJointPlanner::childrenOf(const std::vector<Step>& steps) {
  std::vector<Step> candidates = candidatesOf(steps);
  std::vector<Step> children;
  int accepted = 0;
  while (std::optional<Step> child = nextChild(steps, &candidates, &accepted)) children.push_back(std::move(*child));
  return children;
}

// The next of `candidates` (ranked, taken from the front) that passes the node test, while fewer
// than m have passed (`accepted`); none when none is left. The search asks for children one at a
// time: the node test (a model of all contacts and its DBGs, milliseconds on 400 plates) is then
// made only for the children it enters, not for every candidate of every node it passes (the
// LONG TABLE of 402 plates: 39 s -> see the commit).
std::optional<Step> PlateJointPlanner::nextChild(const std::vector<Step>& steps, std::vector<Step>* candidates,
                                                 int* accepted) {
  std::vector<Step> next = steps;
  while (!candidates->empty() && *accepted < options_.candidates) {
    next.push_back(std::move(candidates->front()));
    candidates->erase(candidates->begin());
    if (acceptable(next)) {
      ++*accepted;
      return std::move(next.back());
    }
    next.pop_back();
  }
  candidates->clear();
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
  if (graph_.plateCount < 3) {
    result.message =
        "an interlocking structure needs at least three plates; this one has " + std::to_string(graph_.plateCount);
    return result;
  }
  return std::nullopt;
}

// The construction tree below the node `prefix` (the root for a whole design) as the shared search
// walks it (search/construction_search.h): an explicit stack of each node's ranked candidates, of
// which the paper's m per node are tested and entered lazily (nextChild). A child whose plate runs
// into the joints made so far or that the LP test (paper Section 4.2) lets more than one part move
// is refused; a complete plan is accepted only if its jointed plates verify, else the search
// backjumps past the step it collided with.
class PlateJointPlanner::SearchTree : public search::ConstructionTree {
 public:
  SearchTree(PlateJointPlanner& planner, const std::vector<Step>& prefix, PlateDesignResult& result)
      : planner_(planner), prefix_(prefix), result_(result) {}

  // Each tree has its own tie-breaking order (restarts.h); the ties only order the children.
  void restart(int64_t attempt) override {
    const uint64_t seed = planner_.options_.seed;
    planner_.random_ = restartState(seed, attempt, seed * 0x9E3779B97F4A7C15ull + 1);
    path_ = prefix_;
    pending_ = {planner_.candidatesOf(prefix_)};
    accepted_ = {0};
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
    std::optional<Step> child = planner_.nextChild(path_, &pending_.back(), &accepted_.back());
    if (!child) {  // no child left here: back to the parent's next sibling
      pending_.pop_back();
      accepted_.pop_back();
      if (path_.size() > prefix_.size()) path_.pop_back();
      return search::Move::Returned;
    }
    path_.push_back(std::move(*child));
    if ((makesJoints(planner_.options_.realization) && planner_.runsIntoJointsSoFar(path_)) ||
        !planner_.heldByInequalities(path_)) {
      path_.pop_back();
      return search::Move::Returned;
    }
    if (!complete()) {
      pending_.push_back(planner_.candidatesOf(path_));
      accepted_.push_back(0);
    }
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
    accepted_.resize(pending_.size());
    return false;
  }

  void snapshotDeepest(DesignProgress& progress) const override {
    progress.deepestPlaced.clear();
    for (const Step& step : path_) progress.deepestPlaced.push_back(step.plate);
  }

 private:
  PlateJointPlanner& planner_;
  const std::vector<Step>& prefix_;
  PlateDesignResult& result_;
  std::vector<Step> path_;
  // pending_[k]: the candidates left at depth prefix + k; accepted_[k]: how many of them passed.
  std::vector<std::vector<Step>> pending_;
  std::vector<int> accepted_;
};

// After a complete plan failed because plate i, swept out, ran into plate j taken at depth j of the
// path (i < j): plate i's joints are made at steps 0..i, plate j's at steps 0..j, so every plan that
// shares the path's first j + 1 steps fails the same way. Backjumping goes straight to the next
// sibling of step j (the LIZARD: 28 complete plans in a row failed on one collision at depth 8
// while the search tried orders of the plates after it). The pruned plans would all fail, so a
// tree searched to its end still proves that no plan exists.
void PlateJointPlanner::backjump(size_t prefixSize, std::vector<Step>* path,
                                 std::vector<std::vector<Step>>* pending) const {
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

PlateDesignResult PlateJointPlanner::run(const std::vector<Step>& prefix) {
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
        (lastRejection_.empty() ? std::string(")") : "; the last complete plan failed: " + lastRejection_ + ")");
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
               "face at a right angle, halved joints where plates cross); joints 'milled' adds sliding dovetails "
               "(CNC), joints 'planned' gives the paper's graph design alone"
             : options_.realization == JointRealization::Milled
                   ? " with the joints that can be cut or milled (mortise-and-tenon, halved and sliding dovetail "
                     "joints on square edges at right angles, tenons across mitres); joints 'planned' gives the "
                     "paper's graph design alone"
                   : "");
    return result;
  }
  result.message =
      "designed " + std::to_string(result.joints.size()) + " joints in " + std::to_string(progress.nodes) + " nodes";
  return result;
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
bool PlateJointPlanner::acceptComplete(const std::vector<Step>& path, PlateDesignResult* result) {
  std::vector<bool> taken(graph_.plateCount, false);
  std::vector<int> order;
  std::vector<Vec3> directions;
  std::vector<PlateJoint> joints;
  for (const Step& step : path) {
    taken[step.plate] = true;
    order.push_back(step.plate);
    directions.push_back(step.direction);
    joints.insert(joints.end(), step.joints.begin(), step.joints.end());
  }
  order.push_back(static_cast<int>(std::find(taken.begin(), taken.end(), false) - taken.begin()));
  if (options_.realization == JointRealization::Planned) {
    // Nothing is cut: the joint model is the result, verified as `desia check` verifies it.
    Assembly model = modelAssembly(graph_, families_, path);
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

// A successful result verified once more, as `desia check` will read it (the plates in removal
// order): a failure here is a bug, never the user's.
void requireVerified(const std::vector<Plate>& plates, const PlateDesignResult& result, const PlateOptions& geometry) {
  if (result.status != DesignStatus::Success) return;
  std::vector<Plate> inRemovalOrder;
  const bool cut = result.realization != JointRealization::Planned;
  for (int plate : result.order) inRemovalOrder.push_back(cut ? result.jointedPlates[plate] : plates[plate]);
  const std::string failure =
      cut ? verifyJointedPlates(inRemovalOrder, result.directions, geometry).failure
          : verifyPlannedPlates(result.jointAssembly, inRemovalOrder, result.directions, geometry).failure;
  if (!failure.empty()) throw Error(ErrorCode::Internal, "the plan did not verify: " + failure);
}

}  // namespace

// The session keeps its own copy of the plates (the planner refers to them) and a stack of the
// ranked children of every node on its path, generated when first asked for.
struct PlateDesignSession::State {
  State(std::vector<Plate> plates_, std::vector<PlateContact> contacts_, const PlateDesignOptions& options)
      : plates(std::move(plates_)), contacts(std::move(contacts_)), planner(plates, contacts, options), options(options) {}
  std::vector<Plate> plates;
  std::vector<PlateContact> contacts;
  PlateJointPlanner planner;
  PlateDesignOptions options;  // what finish() searches with (its limits replaced)
  std::vector<Step> path;
  std::vector<PlateDesignStep> steps;
  std::vector<std::optional<std::vector<Step>>> children{std::nullopt};  // per node on the path, root first
  PlateDesignResult result;

  std::vector<Step>& childrenHere() {
    if (!children.back()) children.back() = planner.childrenOf(path);
    return *children.back();
  }
  void showProgress() {
    result.status = DesignStatus::NotFound;
    result.message = std::to_string(path.size()) + " of " + std::to_string(planner.plateCount()) +
                     " plates taken (the last one stays): choose the next";
  }
};

namespace {

PlateDesignStep publicStep(const Step& step) { return {step.plate, step.direction, step.joints}; }

}  // namespace

PlateDesignSession::PlateDesignSession(std::vector<Plate> plates, std::vector<PlateContact> contacts,
                                       const PlateDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  state_ = std::make_unique<State>(std::move(plates), std::move(contacts), options);
  if (std::optional<PlateDesignResult> refused = state_->planner.refusal()) throwBadInput("", refused->message);
  state_->showProgress();
}

PlateDesignSession::~PlateDesignSession() = default;

const std::vector<PlateDesignStep>& PlateDesignSession::steps() const { return state_->steps; }
int PlateDesignSession::targetPlates() const { return state_->planner.plateCount(); }
bool PlateDesignSession::complete() const { return state_->result.status == DesignStatus::Success; }
const PlateDesignResult& PlateDesignSession::result() const { return state_->result; }

int PlateDesignSession::childCount() {
  return complete() ? 0 : static_cast<int>(state_->childrenHere().size());
}

PlateDesignStep PlateDesignSession::childPreview(int n) {
  if (n < 0 || n >= childCount()) {
    throwBadInput("", "child " + std::to_string(n) + " does not exist: this node has " + std::to_string(childCount()));
  }
  return publicStep(state_->childrenHere()[static_cast<size_t>(n)]);
}

void PlateDesignSession::chooseChild(int n) {
  const PlateDesignStep preview = childPreview(n);  // checks n
  State& state = *state_;
  std::vector<Step>& here = state.childrenHere();
  state.path.push_back(here[static_cast<size_t>(n)]);
  if (static_cast<int>(state.path.size()) + 1 == state.planner.plateCount()) {
    // The last plate stays: this choice completes the plan, which must verify.
    PlateDesignResult result;
    result.progress.targetParts = state.planner.plateCount();
    if (!state.planner.acceptComplete(state.path, &result)) {
      state.path.pop_back();
      here.erase(here.begin() + n);
      throwBadInput("", "taking plate " + std::to_string(state.plates[preview.plate].id) +
                            " completes a plan that fails: " + state.planner.lastRejection() + "; choose another");
    }
    result.message = "designed " + std::to_string(result.joints.size()) + " joints step by step";
    state.result = result;
  } else {
    state.showProgress();
  }
  state.steps.push_back(preview);
  state.children.push_back(std::nullopt);
}

bool PlateDesignSession::next() {
  while (childCount() > 0) {
    try {
      chooseChild(0);
      return true;
    } catch (const Error&) {
      // That child completed a plan that failed and was dropped: try the next one.
    }
  }
  return false;
}

bool PlateDesignSession::back() {
  State& state = *state_;
  if (state.path.empty()) return false;
  state.path.pop_back();
  state.steps.pop_back();
  state.children.pop_back();
  state.showProgress();
  return true;
}

PlateDesignResult PlateDesignSession::finish(const DesignLimits& limits) {
  const State& state = *state_;
  if (complete()) return state.result;  // a complete node: its verified plan
  PlateDesignOptions options = state.options;
  options.limits = limits;
  // A planner of its own: its tie-breaking does not depend on what this session explored before,
  // and the session's own children stay as they are.
  PlateJointPlanner planner(state.plates, state.contacts, options);
  PlateDesignResult result = planner.run(state.path);
  requireVerified(state.plates, result, options.geometry);
  return result;
}

JointRealization parseJointRealization(const std::string& name) {
  if (name == "cut") return JointRealization::Cut;
  if (name == "milled") return JointRealization::Milled;
  if (name == "planned") return JointRealization::Planned;
  throwBadInput("",
                "joints must be 'cut' (laser or router cuts through the plates, verified there), 'milled' (also "
                "sliding dovetails) or 'planned' (the paper's graph design alone), got '" +
                    name + "'");
}

const char* jointRealizationName(JointRealization realization) {
  switch (realization) {
    case JointRealization::Cut: return "cut";
    case JointRealization::Milled: return "milled";
    case JointRealization::Planned: return "planned";
  }
  return "cut";
}

PlateDesignResult designPlateJoints(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                    const PlateDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  PlateJointPlanner planner(plates, contacts, options);
  PlateDesignResult result = planner.run();
  // The search accepts only what passes; checking again guards the result, never a guess.
  requireVerified(plates, result, options.geometry);
  return result;
}

}  // namespace desia
