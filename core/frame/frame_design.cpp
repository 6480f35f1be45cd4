// SPDX-License-Identifier: GPL-3.0-or-later
// Voxel joints for interlocking frame structures (paper Section 5.3) on the construction tree of
// Algorithm 1 (Section 4.1).
//
// A node of the tree is A_i = [P_1, ..., P_i, R_i]: the beams taken so far, each with the axis it
// leaves along and the voxels it owns in the joint cubes at its two ends, and R_i, the beams not
// taken yet together with every voxel nobody owns yet, acting as one part. Every beam owns from
// the start the centre voxel of the cube face it enters.
//
// Taking beam P_i (a child of the node) is the paper's graph design and geometry realization
// within the two joint cubes of P_i (Sections 4.3 and 5.3):
// - P_i is a beam of R_{i-1} that shares a joint with a beam taken before (otherwise nothing but
//   R_i could block it, and both would need edges both ways in every DBG: K = 2 everywhere, never
//   removable), and that is not a cut point of the parts-graph of R_{i-1} (R_i stays connected).
// - A direction d_i: one of the six axis directions.
// - At each of its joints, a set of free voxels for P_i grown from its face voxel: connected to
//   it, closed along d_i (every free voxel ahead of one of P_i's voxels joins P_i; a voxel of a
//   beam still in R ahead forbids d_i), and leaving every piece of R's voxels in that cube attached
//   to a beam of R. At a joint where P_i is the last beam of R, it takes every free voxel.
//   Growing the set by the voxels next to parts taken before is what builds the paper's cycles
//   through P_out and P_in (cases K = 1 and K = 0): P_i then pushes against an earlier part.
// - The child is kept when P_i, its body and voxels swept along d_i, misses every body and voxel of
//   R_i (disassemblability, Section 4.1 (iii)), and A_i is interlocking with P_1 as its key: in each
//   axis DBG, the parts other than the key are strongly connected (Section 3.2). For the key
//   (A_1 = [P_1, R_1], Section 4.2) it is kept when P_1 is free along d_1 and blocked along the
//   five other axis directions.
// Children are ranked as a sweep (Section 4.1 ranks by the compactness of R_{i+1}, Fig. 15 by a
// coordinate): beams farthest along the diagonal x + y + z first, within a diagonal layer the
// highest, then a seeded random order; the voxel sets of a beam smallest first. The taken beams
// then grow from the key's corner as one front, and R_i stays the compact block behind it,
// shrinking onto the opposite corner, where joints hold the fewest beams (3 on a lattice) and
// their cubes keep free voxels for the last splits (Section 5.3: R's beams there share what the
// earlier parts left). Peeling the beams with the fewest neighbours in R first (the order
// before) ate R from every side at once and left it a path through joints of valence 6 whose
// cubes earlier beams had filled: each end of the path had one voxel set left and split an axis
// DBG, a dead end decided some 50 steps above, so SCAFFOLD 300 (71,103 nodes in 120 s, deepest
// 299 of 300) and every lattice of 3 x 3 x 3 cells or more never finished.
// A look-ahead keeps R_i from collapsing onto one joint: a beam is not taken when the three or more
// beams left in R_i would all meet at one joint (a star). The last splits of such an R_i are
// almost never interlocking (each of its beams owns every free voxel at its outer joint, so the
// earlier parts there decide alone whether it is blocked), and the depth-first search would then
// backtrack through every ordering of the star (thousands of dead nodes on SCAFFOLD).
// The search is depth first with backtracking over an explicit stack, restarted with a seed
// derived from the user's seed when a search tree spends its node budget (budgets follow the
// Luby sequence, so the heavy tail of a bad early choice is cut while no budget is too short
// for long); every complete design is verified (frameDesignFailure) before it is reported. All
// of it counts nodes, never time: the same seed gives the same bytes.
#include "desia/frame_design.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "analysis/vec3.h"
#include "search/construction_search.h"
#include "search/restarts.h"
#include "desia/cut_points.h"
#include "desia/error.h"
#include "desia/interlocking.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

// Said when a search finds nothing and no beam meets its joints along an axis: the joint cubes are
// square to x, y and z, so a frame turned off them (a design turned in a modelling tool) meets
// every cube at an angle, where joints rarely interlock.
std::string offTheAxesNote(const Frame& frame) {
  for (const FrameBeam& beam : frame.beams) {
    for (int end = 0; end < 2; ++end) {
      const Vec3& at = frame.joints[beam.joints[end]].position;
      const Vec3& next = beam.path.empty() ? frame.joints[beam.joints[1 - end]].position
                                           : (end == 0 ? beam.path.front() : beam.path.back());
      const Vec3 d = normalized(minus(next, at));
      for (const double c : d) {
        if (std::abs(c) > 1 - tolerance::kDirection) return "";  // a beam end along an axis: the frame is on the grid
      }
    }
  }
  return "; no beam meets its joints along the x, y or z axis, and the joint cubes are square to those "
         "axes: a frame turned off them meets every cube at an angle, so turn it square to the axes";
}


using Mask = uint32_t;  // a set of the 27 voxels of a joint cube

// The random state of restart `attempt` for the user's seed (search/restarts.h).
uint64_t attemptSeed(uint64_t seed, int64_t attempt) {
  return restartState(seed, attempt, seed * 0x9E3779B97F4A7C15ull + 7);
}


// The budget unit of a search tree, in work (beam-direction corridors and voxel-set pairs tried,
// so a tree of slow nodes is cut as soon as one of many fast ones): a node tries about as many
// pairs as R has beams next to taken ones, and a design of n beams takes n nodes, hence n^2. On
// SCAFFOLD (92 beams) seeds that succeed mostly do within this; the failing ones would thrash for
// tens of thousands of nodes. The floor lets small frames of slow curved beams (FLOWER) finish
// their first tree as before.
int64_t restartUnit(int beams) { return std::max<int64_t>(int64_t(1) << 16, 3 * int64_t(beams) * beams); }

constexpr int kFree = -1;
constexpr int kOptionsPerJoint = 20;
constexpr int kPairsPerDirection = 80;

int voxelIndex(int x, int y, int z) { return x + 3 * y + 9 * z; }

// The voxel next to `voxel` along signed axis direction `direction` (face numbering), or -1.
int stepVoxel(int voxel, int direction) {
  int c[3] = {voxel % 3, voxel / 3 % 3, voxel / 9};
  c[direction / 2] += direction % 2 == 0 ? 1 : -1;
  if (c[direction / 2] < 0 || c[direction / 2] > 2) return -1;
  return voxelIndex(c[0], c[1], c[2]);
}

int popCount(Mask mask) {
  int count = 0;
  for (; mask; mask &= mask - 1) ++count;
  return count;
}

// Voxels of `within` face-connected to `seeds`.
Mask reachable(Mask seeds, Mask within) {
  Mask reached = seeds & within, frontier = reached;
  while (frontier) {
    Mask next = 0;
    for (Mask m = frontier; m; m &= m - 1) {
      const int v = __builtin_ctz(m);
      for (int d = 0; d < 6; ++d) {
        const int w = stepVoxel(v, d);
        if (w >= 0 && (within >> w & 1) && !(reached >> w & 1)) next |= Mask(1) << w;
      }
    }
    reached |= next;
    frontier = next;
  }
  return reached;
}

Mask neighbours(Mask set) {
  Mask result = 0;
  for (Mask m = set; m; m &= m - 1) {
    const int v = __builtin_ctz(m);
    for (int d = 0; d < 6; ++d) {
      const int w = stepVoxel(v, d);
      if (w >= 0) result |= Mask(1) << w;
    }
  }
  return result & ~set;
}

struct Aabb {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

Aabb boundsOf(const OrientedBox& box) {
  Aabb bounds;
  for (int k = 0; k < 3; ++k) {
    double r = 0;
    for (int i = 0; i < 3; ++i) r += box.halfExtents[i] * std::abs(box.axes[i][k]);
    bounds.lo[k] = box.centre[k] - r;
    bounds.hi[k] = box.centre[k] + r;
  }
  return bounds;
}

void include(Aabb& bounds, const Aabb& more) {
  for (int k = 0; k < 3; ++k) {
    bounds.lo[k] = std::min(bounds.lo[k], more.lo[k]);
    bounds.hi[k] = std::max(bounds.hi[k], more.hi[k]);
  }
}

bool overlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] <= b.lo[k] || b.hi[k] <= a.lo[k]) return false;
  }
  return true;
}

Aabb swept(Aabb bounds, int direction) {
  const int axis = direction / 2;
  if (direction % 2 == 0)
    bounds.hi[axis] = std::numeric_limits<double>::infinity();
  else
    bounds.lo[axis] = -std::numeric_limits<double>::infinity();
  return bounds;
}

// One step of the design: a beam leaves along `direction` with the voxels `taken` (free voxels it
// takes at its joints[0] and joints[1]; its face voxels it owns from the start).
struct Step {
  int beam = -1;
  int direction = 0;
  std::array<Mask, 2> taken{0, 0};
};

// Something in the way of a moving beam: a box, and for a free voxel its joint and voxel.
struct Obstacle {
  OrientedBox box;
  Aabb bounds;
  int joint = -1, voxel = -1;  // a free voxel (it may still join the moving beam), else -1
};

class FrameDesigner {
 public:
  FrameDesigner(const FrameLayout& layout, const FrameDesignOptions& options)
      : layout_(layout), frame_(layout.frame), options_(options), random_(attemptSeed(options.seed, 0)) {
    const int beams = static_cast<int>(frame_.beams.size());
    for (int b = 0; b < beams; ++b) {
      bodies_.push_back(beamBodyBoxes(layout_, b));
      Aabb bounds = boundsOf(bodies_.back()[0]);
      for (const OrientedBox& box : bodies_.back()) include(bounds, boundsOf(box));
      bodyBounds_.push_back(bounds);
    }
    labels_.assign(frame_.joints.size(), JointLabels{});
    for (JointLabels& joint : labels_) joint.fill(kFree);
    for (int b = 0; b < beams; ++b) {
      for (int end = 0; end < 2; ++end)
        labels_[frame_.beams[b].joints[end]][faceCentreVoxel(layout_.endFace[b][end])] = b;
    }
    stepOf_.assign(beams, -1);
  }

  // The restarted search below the node `prefix` (the root: a whole design); the prefix's steps
  // stay, restarts re-seed below that node.
  FrameDesignResult run(const std::vector<Step>& prefix = {});
  class SearchTree;

  // For the session (FrameDesignSession): why no design can exist (a cut point, too few beams);
  // the ranked children of the current node; moving down and up the tree; and a complete design
  // from the current node (every beam but one taken), verified.
  std::optional<FrameDesignResult> refusal() const;
  std::vector<Step> sessionChildren() {
    width_ = options_.candidates;
    return childrenOfCurrent();
  }
  void take(const Step& step) { apply(step); }
  void untake() { undo(path_.back()); }
  bool completeHere(FrameDesignResult* result);
  int beamCount() const { return static_cast<int>(frame_.beams.size()); }
  const std::string& lastRejection() const { return lastRejection_; }

 private:
  std::vector<Step> childrenOfCurrent();
  void childrenOfBeam(int beam, int direction, int wanted, std::vector<Step>& children);
  std::vector<Mask> jointOptions(int beam, int end, int direction);
  std::vector<Obstacle> corridorObstacles(int beam, int direction) const;
  bool sweepClear(int beam, int direction, const std::array<Mask, 2>& taken,
                  const std::vector<Obstacle>& obstacles) const;
  bool acceptable(const Step& step);
  bool keyMovesAlongOnly(const Step& step) const;
  bool restStronglyConnected(int candidate);
  void apply(const Step& step);
  void undo(const Step& step);
  uint64_t nextRandom() {
    random_ = random_ * 6364136223846793005ull + 1442695040888963407ull;
    return random_ >> 11;
  }
  int endOf(int beam, int joint) const { return frame_.beams[beam].joints[0] == joint ? 0 : 1; }
  bool inRest(int beam) const { return stepOf_[beam] < 0; }
  int width_ = 1;     // children kept per node in the current search
  int64_t work_ = 0;  // beam-direction corridors and voxel-set pairs tried: the restart budget's unit

  const FrameLayout& layout_;
  const Frame& frame_;
  FrameDesignOptions options_;
  uint64_t random_;
  std::vector<std::vector<OrientedBox>> bodies_;
  std::vector<Aabb> bodyBounds_;
  std::vector<JointLabels> labels_;
  std::vector<int> stepOf_;  // per beam: its step in path_, or -1 while in R
  std::vector<Step> path_;
  std::string lastRejection_;  // why the last complete design failed verification
  // Scratch for the graph test.
  std::vector<std::pair<int, int>> edges_;
  std::vector<int> offsets_, targets_, reverseOffsets_, reverseTargets_, partOfBeam_;
};

void FrameDesigner::apply(const Step& step) {
  stepOf_[step.beam] = static_cast<int>(path_.size());
  path_.push_back(step);
  for (int end = 0; end < 2; ++end) {
    JointLabels& joint = labels_[frame_.beams[step.beam].joints[end]];
    for (Mask m = step.taken[end]; m; m &= m - 1) joint[__builtin_ctz(m)] = step.beam;
  }
}

void FrameDesigner::undo(const Step& step) {
  for (int end = 0; end < 2; ++end) {
    JointLabels& joint = labels_[frame_.beams[step.beam].joints[end]];
    for (Mask m = step.taken[end]; m; m &= m - 1) joint[__builtin_ctz(m)] = kFree;
  }
  stepOf_[step.beam] = -1;
  path_.pop_back();
}

// The voxel sets beam `beam` may take at its end `end` when it leaves along `direction`, smallest
// first; empty when no set works (a voxel of a beam of R lies ahead of its face voxel).
std::vector<Mask> FrameDesigner::jointOptions(int beam, int end, int direction) {
  const int joint = frame_.beams[beam].joints[end];
  const JointLabels& labels = labels_[joint];
  const int face = faceCentreVoxel(layout_.endFace[beam][end]);
  Mask free = 0, restFaces = 0, gone = 0;
  for (int v = 0; v < kJointVoxelCount; ++v) {
    if (labels[v] == kFree)
      free |= Mask(1) << v;
    else if (labels[v] != beam && inRest(labels[v]))
      restFaces |= Mask(1) << v;
    else if (labels[v] != beam)
      gone |= Mask(1) << v;  // owned by a beam taken before
  }
  if (!restFaces) return {free};  // the last beam of R here takes every free voxel
  // Closure along the direction: everything free ahead joins; a voxel of R ahead forbids it.
  auto close = [&](Mask set, Mask* closed) {
    Mask result = set;
    for (Mask m = set | (Mask(1) << face); m; m &= m - 1) {
      for (int w = stepVoxel(__builtin_ctz(m), direction); w >= 0; w = stepVoxel(w, direction)) {
        if (restFaces >> w & 1) return false;
        if (free >> w & 1) result |= Mask(1) << w;
      }
    }
    *closed = result;
    return true;
  };
  // P_i connected to its face voxel; each piece of R's voxels here attached to a beam of R.
  auto valid = [&](Mask set) {
    const Mask mine = set | (Mask(1) << face);
    if (reachable(Mask(1) << face, mine) != mine) return false;
    const Mask rest = (free & ~set) | restFaces;
    return reachable(restFaces, rest) == rest;
  };
  std::vector<Mask> options;
  auto add = [&](Mask set) {
    if (std::find(options.begin(), options.end(), set) == options.end() && valid(set)) options.push_back(set);
  };
  Mask base = 0;
  if (!close(0, &base)) return {};
  add(base);
  // One more voxel next to P_i's voxels, each in turn; voxels touching a part taken before first
  // (they make the edges to earlier parts that close the DBG cycles).
  const Mask around = neighbours(base | (Mask(1) << face)) & free;
  std::vector<std::pair<uint64_t, Mask>> grown;
  for (Mask m = around; m; m &= m - 1) {
    const int v = __builtin_ctz(m);
    Mask set = 0;
    if (!close(base | (Mask(1) << v), &set)) continue;
    // Best: a part taken before lies ahead along the direction (P_i -> P_out, case K = 1); next:
    // one touches it at all.
    const int ahead = stepVoxel(v, direction);
    const bool blockedAhead = ahead >= 0 && (gone >> ahead & 1);
    const bool touchesEarlier = (neighbours(Mask(1) << v) & gone) != 0;
    const uint64_t rank = blockedAhead ? 0 : touchesEarlier ? 1 : 2;
    grown.push_back({(rank << 60) + (nextRandom() >> 4), set});
  }
  std::sort(grown.begin(), grown.end());
  for (const auto& [rank, set] : grown) add(set);
  // Random growth by two to eight voxels.
  for (int attempt = 0; attempt < 3 * kOptionsPerJoint && static_cast<int>(options.size()) < kOptionsPerJoint;
       ++attempt) {
    Mask set = base;
    const int extra = 2 + static_cast<int>(nextRandom() % 7);
    for (int k = 0; k < extra; ++k) {
      const Mask choices = neighbours(set | (Mask(1) << face)) & free;
      if (!choices) break;
      int pick = static_cast<int>(nextRandom() % popCount(choices));
      Mask m = choices;
      for (; pick > 0; --pick) m &= m - 1;
      Mask closed = 0;
      if (!close(set | (m & (~m + 1)), &closed)) continue;
      set = closed;
    }
    add(set);
  }
  std::stable_sort(options.begin(), options.end(), [](Mask a, Mask b) { return popCount(a) < popCount(b); });
  if (static_cast<int>(options.size()) > kOptionsPerJoint) options.resize(kOptionsPerJoint);
  return options;
}

// Everything of R in the way of `beam` leaving along `direction` with any voxels of its cubes:
// bodies of R's beams and voxels of R (free voxels of the beam's own cubes included, tagged).
std::vector<Obstacle> FrameDesigner::corridorObstacles(int beam, int direction) const {
  Aabb reach = bodyBounds_[beam];
  for (int joint : frame_.beams[beam].joints) {
    const Vec3& p = frame_.joints[joint].position;
    const double half = frame_.jointSize / 2;
    include(reach, {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}});
  }
  reach = swept(reach, direction);
  std::vector<Obstacle> obstacles;
  for (size_t j = 0; j < frame_.joints.size(); ++j) {
    const Vec3& p = frame_.joints[j].position;
    const double half = frame_.jointSize / 2;
    if (!overlap(reach, {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}})) continue;
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int label = labels_[j][v];
      if (label == beam || (label != kFree && !inRest(label))) continue;
      Obstacle obstacle;
      obstacle.box = jointVoxelBox(layout_, static_cast<int>(j), v);
      obstacle.bounds = boundsOf(obstacle.box);
      if (!overlap(reach, obstacle.bounds)) continue;
      if (label == kFree) {
        obstacle.joint = static_cast<int>(j);
        obstacle.voxel = v;
      }
      obstacles.push_back(obstacle);
    }
  }
  for (size_t other = 0; other < frame_.beams.size(); ++other) {
    if (static_cast<int>(other) == beam || !inRest(static_cast<int>(other)) || !overlap(reach, bodyBounds_[other]))
      continue;
    for (const OrientedBox& box : bodies_[other]) {
      const Aabb bounds = boundsOf(box);
      if (overlap(reach, bounds)) obstacles.push_back({box, bounds, -1, -1});
    }
  }
  return obstacles;
}

// The beam's body and voxels (face voxels and `taken`) swept along `direction` miss R.
bool FrameDesigner::sweepClear(int beam, int direction, const std::array<Mask, 2>& taken,
                               const std::vector<Obstacle>& obstacles) const {
  const Vec3 d = cubeFaceNormal(direction);
  const std::array<int, 2>& joints = frame_.beams[beam].joints;
  std::vector<OrientedBox> moving = bodies_[beam];
  for (int end = 0; end < 2; ++end) {
    Mask mine = taken[end];
    for (int v = 0; v < kJointVoxelCount; ++v) {
      if (labels_[joints[end]][v] == beam) mine |= Mask(1) << v;
    }
    for (Mask m = mine; m; m &= m - 1) moving.push_back(jointVoxelBox(layout_, joints[end], __builtin_ctz(m)));
  }
  std::vector<Aabb> movingBounds;
  for (const OrientedBox& box : moving) movingBounds.push_back(swept(boundsOf(box), direction));
  for (const Obstacle& obstacle : obstacles) {
    if (obstacle.joint >= 0) {
      const int end = obstacle.joint == joints[0] ? 0 : obstacle.joint == joints[1] ? 1 : -1;
      if (end >= 0 && (taken[end] >> obstacle.voxel & 1)) continue;  // it moves with the beam
    }
    for (size_t m = 0; m < moving.size(); ++m) {
      if (overlap(movingBounds[m], obstacle.bounds) && sweptBoxesCollide(moving[m], d, obstacle.box)) return false;
    }
  }
  return true;
}

// A_1: the key is blocked by R_1 along every axis direction but its own (voxel faces in contact).
bool FrameDesigner::keyMovesAlongOnly(const Step& step) const {
  std::array<bool, 6> blocked{};
  for (int joint : frame_.beams[step.beam].joints) {
    const JointLabels& labels = labels_[joint];
    for (int v = 0; v < kJointVoxelCount; ++v) {
      if (labels[v] != step.beam) continue;
      for (int d = 0; d < 6; ++d) {
        const int w = stepVoxel(v, d);
        if (w >= 0 && labels[w] != step.beam) blocked[d] = true;
      }
    }
  }
  for (int d = 0; d < 6; ++d) {
    if (blocked[d] == (d == step.direction)) return false;
  }
  return true;
}

// A_i (i >= 2) with the candidate applied: the DBG of the key's axis is strongly connected without
// the key, the two others are strongly connected (paper Section 4.3, footnote 1), so every DBG is
// strongly connected or splits off the key alone (Section 3.2). The DBGs of +axis and -axis are
// reverses of one another: three graphs suffice.
bool FrameDesigner::restStronglyConnected(int candidate) {
  const int parts = static_cast<int>(path_.size()) + 1;  // path_ holds the candidate as its last step
  const int rest = parts - 1;
  partOfBeam_.assign(frame_.beams.size(), rest);
  for (size_t k = 0; k < path_.size(); ++k) partOfBeam_[path_[k].beam] = static_cast<int>(k);
  (void)candidate;
  // Joints where two parts meet: those of beams taken so far.
  std::vector<int> joints;
  for (const Step& step : path_) {
    for (int joint : frame_.beams[step.beam].joints) joints.push_back(joint);
  }
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
  const int keyAxis = path_[0].direction / 2;
  for (int axis = 0; axis < 3; ++axis) {
    const int stride = axis == 0 ? 1 : axis == 1 ? 3 : 9;
    const int skipped = axis == keyAxis ? 0 : -1;  // the part left out of the graph
    edges_.clear();
    for (int joint : joints) {
      const JointLabels& labels = labels_[joint];
      for (int v = 0; v < kJointVoxelCount; ++v) {
        const int c = axis == 0 ? v % 3 : axis == 1 ? v / 3 % 3 : v / 9;
        if (c == 2) continue;
        const int a = labels[v] == kFree ? rest : partOfBeam_[labels[v]];
        const int b = labels[v + stride] == kFree ? rest : partOfBeam_[labels[v + stride]];
        if (a != b && a != skipped && b != skipped) edges_.push_back({a, b});
      }
    }
    // Compressed adjacency both ways, then reach every non-key part from R forwards and backwards.
    offsets_.assign(parts + 1, 0);
    reverseOffsets_.assign(parts + 1, 0);
    for (const auto& [a, b] : edges_) {
      ++offsets_[a + 1];
      ++reverseOffsets_[b + 1];
    }
    for (int p = 0; p < parts; ++p) {
      offsets_[p + 1] += offsets_[p];
      reverseOffsets_[p + 1] += reverseOffsets_[p];
    }
    targets_.assign(edges_.size(), 0);
    reverseTargets_.assign(edges_.size(), 0);
    {
      std::vector<int> fill(offsets_.begin(), offsets_.end() - 1),
          reverseFill(reverseOffsets_.begin(), reverseOffsets_.end() - 1);
      for (const auto& [a, b] : edges_) {
        targets_[fill[a]++] = b;
        reverseTargets_[reverseFill[b]++] = a;
      }
    }
    for (int way = 0; way < 2; ++way) {
      const std::vector<int>& offsets = way == 0 ? offsets_ : reverseOffsets_;
      const std::vector<int>& targets = way == 0 ? targets_ : reverseTargets_;
      std::vector<char> seen(parts, 0);
      std::vector<int> stack{rest};
      seen[rest] = 1;
      int count = 1;
      while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        for (int e = offsets[p]; e < offsets[p + 1]; ++e) {
          if (!seen[targets[e]]) {
            seen[targets[e]] = 1;
            ++count;
            stack.push_back(targets[e]);
          }
        }
      }
      if (count != (skipped == 0 ? parts - 1 : parts)) return false;
    }
  }
  return true;
}

bool FrameDesigner::acceptable(const Step& step) {
  apply(step);
  const bool ok = path_.size() == 1 ? keyMovesAlongOnly(step) : restStronglyConnected(step.beam);
  undo(step);
  return ok;
}

// Up to `wanted` children for taking `beam` along `direction`: pairs of voxel sets at its two
// joints, smallest first, kept when the beam sweeps clear and A_i passes.
void FrameDesigner::childrenOfBeam(int beam, int direction, int wanted, std::vector<Step>& children) {
  ++work_;
  const std::vector<Obstacle> obstacles = corridorObstacles(beam, direction);
  // The body alone against everything that will not join the beam.
  {
    std::vector<Obstacle> fixed;
    for (const Obstacle& o : obstacles) {
      const bool ownFree =
          o.joint >= 0 && (o.joint == frame_.beams[beam].joints[0] || o.joint == frame_.beams[beam].joints[1]);
      if (!ownFree) fixed.push_back(o);
    }
    if (!sweepClear(beam, direction, {0, 0}, fixed)) return;
  }
  const std::vector<Mask> first = jointOptions(beam, 0, direction);
  const std::vector<Mask> second = jointOptions(beam, 1, direction);
  if (first.empty() || second.empty()) return;
  std::vector<std::pair<uint64_t, std::array<Mask, 2>>> pairs;
  for (Mask a : first) {
    for (Mask b : second) pairs.push_back({(uint64_t(popCount(a) + popCount(b)) << 40) + (nextRandom() >> 24), {a, b}});
  }
  std::sort(pairs.begin(), pairs.end());
  int tried = 0, found = 0;
  for (const auto& [rank, taken] : pairs) {
    if (++tried > kPairsPerDirection || found >= wanted) break;
    ++work_;
    const Step step{beam, direction, taken};
    if (!sweepClear(beam, direction, taken, obstacles)) continue;
    if (!acceptable(step)) continue;
    children.push_back(step);
    ++found;
  }
}

std::vector<Step> FrameDesigner::childrenOfCurrent() {
  const int beams = static_cast<int>(frame_.beams.size());
  // The parts-graph of R: beams sharing a joint.
  std::vector<int> rest, index(beams, -1);
  for (int b = 0; b < beams; ++b) {
    if (inRest(b)) {
      index[b] = static_cast<int>(rest.size());
      rest.push_back(b);
    }
  }
  std::vector<std::pair<int, int>> edges;
  std::vector<bool> touchesTaken(beams, false);
  for (const std::vector<int>& atJoint : layout_.beamsAtJoint) {
    bool taken = false;
    for (int b : atJoint) taken = taken || !inRest(b);
    for (size_t x = 0; x < atJoint.size(); ++x) {
      if (!inRest(atJoint[x])) continue;
      touchesTaken[atJoint[x]] = touchesTaken[atJoint[x]] || taken;
      for (size_t y = x + 1; y < atJoint.size(); ++y) {
        if (!inRest(atJoint[y])) continue;
        edges.push_back({index[atJoint[x]], index[atJoint[y]]});
      }
    }
  }
  std::vector<bool> isCut(beams, false);
  for (int i : findCutPoints(static_cast<int>(rest.size()), edges)) isCut[rest[i]] = true;
  struct Candidate {
    int beam;
    double sweep;   // x + y + z of its two joints
    double height;  // y of its two joints
    uint64_t tie;
  };
  // The look-ahead (see the top): joints holding all but one of R's beams; taking a beam of R
  // that is not at such a joint would leave R_i a star there.
  const int restCount = static_cast<int>(rest.size());
  std::vector<int> restAtJoint(frame_.joints.size(), 0);
  for (int b : rest) {
    for (int joint : frame_.beams[b].joints) ++restAtJoint[joint];
  }
  std::vector<int> crowded;  // joints where R_i would be a star of restCount - 1 >= 3 beams
  for (size_t j = 0; j < restAtJoint.size(); ++j) {
    if (restCount - 1 >= 3 && restAtJoint[j] >= restCount - 1) crowded.push_back(static_cast<int>(j));
  }
  auto leavesStar = [&](int beam) {
    for (int joint : crowded) {
      const bool here = frame_.beams[beam].joints[0] == joint || frame_.beams[beam].joints[1] == joint;
      if (restAtJoint[joint] - (here ? 1 : 0) == restCount - 1) return true;
    }
    return false;
  };
  std::vector<Candidate> candidates;
  for (int b : rest) {
    if (isCut[b] || (!path_.empty() && !touchesTaken[b]) || leavesStar(b)) continue;
    const Vec3& p = frame_.joints[frame_.beams[b].joints[0]].position;
    const Vec3& q = frame_.joints[frame_.beams[b].joints[1]].position;
    candidates.push_back({b, (p[0] + q[0]) + (p[1] + q[1]) + (p[2] + q[2]), p[1] + q[1], nextRandom()});
  }
  // The sweep (see the top): the front of taken beams moves along the diagonal, so R_i stays a
  // compact corner block (Section 4.1's compactness of R) and ends at the corner of fewest beams
  // per joint, not as a path through crowded joints; the key, the first of the sweep, is at the
  // top (Section 4.2: it leaves upwards).
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.sweep != y.sweep) return x.sweep > y.sweep;
    if (x.height != y.height) return x.height > y.height;
    return x.tie < y.tie;
  });
  // More keys than later children: a key whose subtree dies costs little, the whole search less.
  const int wanted = path_.empty() ? 6 * width_ : width_;
  std::vector<Step> children;
  for (const Candidate& candidate : candidates) {
    // The key leaves upwards when it can (paper Section 4.2: gravity keeps it in); other
    // directions in a seeded order.
    std::array<int, 6> directions{2, 0, 1, 3, 4, 5};
    for (int k = 5; k > (path_.empty() ? 1 : 0); --k) {
      const int j = (path_.empty() ? 1 : 0) + static_cast<int>(nextRandom() % (k - (path_.empty() ? 1 : 0) + 1));
      std::swap(directions[k], directions[j]);
    }
    for (int direction : directions) {
      if (static_cast<int>(children.size()) >= wanted) return children;
      childrenOfBeam(candidate.beam, direction, 1, children);
    }
  }
  return children;
}

std::optional<FrameDesignResult> FrameDesigner::refusal() const {
  FrameDesignResult result;
  const int beams = static_cast<int>(frame_.beams.size());
  result.progress.targetParts = beams;
  const std::vector<int> cuts = frameCutBeams(layout_);
  if (!cuts.empty()) {
    result.status = DesignStatus::CutPoint;
    result.message =
        "beam " + std::to_string(frame_.beams[cuts[0]].id) +
        " is a cut point of the parts-graph: taking it away splits the other beams, and no joints can make such "
        "a frame interlocking (paper Section 5.2, Fig. 18); add a beam that joins the two sides";
    return result;
  }
  if (beams < 3) {
    result.message = "an interlocking frame needs at least three beams; this one has " + std::to_string(beams);
    return result;
  }
  return std::nullopt;
}

// Every beam but one taken: the last owns every voxel still free. Verified (frameDesignFailure);
// on success the result holds the order, directions, labels and assembly (status Success).
bool FrameDesigner::completeHere(FrameDesignResult* result) {
  int last = 0;
  while (!inRest(last)) ++last;
  std::vector<JointLabels> labels = labels_;
  for (JointLabels& joint : labels) std::replace(joint.begin(), joint.end(), kFree, last);
  std::vector<int> order;
  std::vector<Vec3> directions;
  for (const Step& s : path_) {
    order.push_back(s.beam);
    directions.push_back(cubeFaceNormal(s.direction));
  }
  order.push_back(last);
  lastRejection_ = frameDesignFailure(layout_, labels, order, directions);
  if (!lastRejection_.empty()) return false;
  result->order = order;
  result->directions = directions;
  result->labels = labels;
  result->assembly = frameAssembly(layout_, result->labels, result->order);
  result->status = DesignStatus::Success;
  return true;
}

// The construction tree below the node `prefix` (the root for a whole design) as the shared search
// walks it (search/construction_search.h): an explicit stack of each node's ranked children. Within
// a restart, iterative widening: a tree searched to the end with m children per node is searched
// again with 2m (up to 32), so a narrow first search costs little; a tree exhausted at the widest
// means no design.
class FrameDesigner::SearchTree : public search::ConstructionTree {
 public:
  SearchTree(FrameDesigner& designer, size_t floor, FrameDesignResult& result)
      : designer_(designer), floor_(floor), result_(result),
        remaining_(designer.beamCount() - static_cast<int>(floor)) {}

  void restart(int64_t attempt) override {
    backToFloor();
    designer_.random_ = attemptSeed(designer_.options_.seed, attempt);
    designer_.width_ = designer_.options_.candidates;
    workAtStart_ = designer_.work_;
    pending_ = {designer_.childrenOfCurrent()};
  }

  // Restart k may spend restartUnit * luby(k) work, and 12 nodes per beam (at least 1,000) times
  // luby(k): dead ends near the last beam are cheap, and thousands of them there mean a choice
  // far above went wrong.
  bool budgetSpent(int64_t attempt, int64_t nodes) const override {
    const int64_t luby = lubyTerm(attempt);
    return designer_.work_ - workAtStart_ >= restartUnit(remaining_) * luby ||
           nodes >= std::max<int64_t>(1000, 12 * int64_t(remaining_)) * luby;
  }

  bool exhausted() const override { return pending_.empty(); }

  bool widen() override {
    backToFloor();
    designer_.width_ *= 2;
    if (designer_.width_ > std::max(32, designer_.options_.candidates)) return false;
    pending_ = {designer_.childrenOfCurrent()};
    return true;
  }

  search::Move step() override {
    if (pending_.back().empty()) {  // no child left here: back to the parent's next sibling
      pending_.pop_back();
      if (designer_.path_.size() > floor_) designer_.undo(designer_.path_.back());
      return search::Move::Returned;
    }
    const Step step = pending_.back().front();
    pending_.back().erase(pending_.back().begin());
    designer_.apply(step);
    if (!complete()) pending_.push_back(designer_.childrenOfCurrent());
    return search::Move::Entered;
  }

  int depth() const override { return static_cast<int>(designer_.path_.size()) + 1; }  // R counts as one
  bool complete() const override { return depth() == designer_.beamCount(); }

  // R is the last beam: it owns every voxel still free. Accepted only if it verifies.
  bool acceptComplete() override {
    if (designer_.completeHere(&result_)) return true;
    designer_.undo(designer_.path_.back());
    return false;
  }

  void snapshotDeepest(DesignProgress& progress) const override {
    progress.deepestPlaced.clear();
    for (const Step& s : designer_.path_) progress.deepestPlaced.push_back(s.beam);
  }

 private:
  void backToFloor() {
    while (designer_.path_.size() > floor_) designer_.undo(designer_.path_.back());
  }

  FrameDesigner& designer_;
  size_t floor_;
  FrameDesignResult& result_;
  int remaining_;  // beams the search still decides
  int64_t workAtStart_ = 0;
  std::vector<std::vector<Step>> pending_;
};

FrameDesignResult FrameDesigner::run(const std::vector<Step>& prefix) {
  if (std::optional<FrameDesignResult> refused = refusal()) return *refused;
  FrameDesignResult result;
  DesignProgress& progress = result.progress;
  const int beams = static_cast<int>(frame_.beams.size());
  progress.targetParts = beams;
  // The floor: the search never goes above the prefix's node.
  for (const Step& step : prefix) apply(step);
  const size_t floor = prefix.size();
  if (static_cast<int>(floor) + 1 >= beams) {  // a complete node: nothing left to search
    progress.depth = progress.bestDepth = beams;
    if (!completeHere(&result)) {
      result.status = DesignStatus::NotFound;
      result.message = "this complete design fails: " + lastRejection_;
    }
    return result;
  }
  SearchTree tree(*this, floor, result);
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
    result.message = "no design within the limits (" + std::to_string(progress.nodes) + " nodes; deepest " +
                     std::to_string(progress.bestDepth) + " of " + std::to_string(beams) + " beams)";
    return result;
  }
  const bool complete = end == search::SearchEnd::Found;
  if (!complete) {
    result.status = DesignStatus::NotFound;
    result.message = std::string(floor == 0 ? "no interlocking joints exist within the search ("
                                            : "no interlocking joints exist below this node (") +
                     std::to_string(progress.nodes) +
                     " nodes; deepest " + std::to_string(progress.bestDepth) + " of " + std::to_string(beams) +
                     " beams)" + offTheAxesNote(frame_);
    return result;
  }
  result.message = "designed the joints of " + std::to_string(beams) + " beams (key: beam " +
                   std::to_string(frame_.beams[result.order[0]].id) + ") in " + std::to_string(progress.nodes) +
                   " nodes";
  return result;
}

}  // namespace

// The session keeps its own copy of the layout (the designer refers to it) and a stack of the
// ranked children of every node on its path, generated when first asked for. The designer's
// labels and path follow the session's path (take / untake).
struct FrameDesignSession::State {
  State(FrameLayout layout_, const FrameDesignOptions& options)
      : layout(std::move(layout_)), designer(layout, options), options(options) {}
  FrameLayout layout;
  FrameDesigner designer;
  FrameDesignOptions options;  // what finish() searches with (its limits replaced)
  std::vector<Step> path;
  std::vector<FrameDesignStep> steps;
  std::vector<std::optional<std::vector<Step>>> children{std::nullopt};  // per node on the path, root first
  FrameDesignResult result;

  std::vector<Step>& childrenHere() {
    if (!children.back()) children.back() = designer.sessionChildren();
    return *children.back();
  }
  void showProgress() {
    result = FrameDesignResult{};
    result.status = DesignStatus::NotFound;
    result.progress.targetParts = designer.beamCount();
    result.message = std::to_string(path.size()) + " of " + std::to_string(designer.beamCount()) +
                     " beams taken (the last one stays): choose the next";
  }
  FrameDesignStep publicStep(const Step& step) const {
    FrameDesignStep result{step.beam, cubeFaceNormal(step.direction), {}};
    for (int end = 0; end < 2; ++end) {
      for (Mask m = step.taken[end]; m; m &= m - 1) result.voxels[end].push_back(__builtin_ctz(m));
    }
    return result;
  }
};

FrameDesignSession::FrameDesignSession(FrameLayout layout, const FrameDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  state_ = std::make_unique<State>(std::move(layout), options);
  if (std::optional<FrameDesignResult> refused = state_->designer.refusal()) throwBadInput("", refused->message);
  state_->showProgress();
}

FrameDesignSession::~FrameDesignSession() = default;

const std::vector<FrameDesignStep>& FrameDesignSession::steps() const { return state_->steps; }
int FrameDesignSession::targetBeams() const { return state_->designer.beamCount(); }
bool FrameDesignSession::complete() const { return state_->result.status == DesignStatus::Success; }
const FrameDesignResult& FrameDesignSession::result() const { return state_->result; }

int FrameDesignSession::childCount() { return complete() ? 0 : static_cast<int>(state_->childrenHere().size()); }

FrameDesignStep FrameDesignSession::childPreview(int n) {
  if (n < 0 || n >= childCount()) {
    throwBadInput("", "child " + std::to_string(n) + " does not exist: this node has " + std::to_string(childCount()));
  }
  return state_->publicStep(state_->childrenHere()[static_cast<size_t>(n)]);
}

void FrameDesignSession::chooseChild(int n) {
  const FrameDesignStep preview = childPreview(n);  // checks n
  State& state = *state_;
  std::vector<Step>& here = state.childrenHere();
  const Step step = here[static_cast<size_t>(n)];
  state.designer.take(step);
  state.path.push_back(step);
  if (static_cast<int>(state.path.size()) + 1 == state.designer.beamCount()) {
    // The last beam stays with every free voxel: this choice completes the design, which must verify.
    FrameDesignResult result;
    result.progress.targetParts = state.designer.beamCount();
    if (!state.designer.completeHere(&result)) {
      state.designer.untake();
      state.path.pop_back();
      here.erase(here.begin() + n);
      throwBadInput("", "taking beam " + std::to_string(state.layout.frame.beams[preview.beam].id) +
                            " completes a design that fails: " + state.designer.lastRejection() + "; choose another");
    }
    const int key = state.layout.frame.beams[result.order[0]].id;
    result.message = "designed the joints of " + std::to_string(state.designer.beamCount()) +
                     " beams step by step (key: beam " + std::to_string(key) + ")";
    state.result = result;
  } else {
    state.showProgress();
  }
  state.steps.push_back(preview);
  state.children.push_back(std::nullopt);
}

bool FrameDesignSession::next() {
  while (childCount() > 0) {
    try {
      chooseChild(0);
      return true;
    } catch (const Error&) {
      // That child completed a design that failed and was dropped: try the next one.
    }
  }
  return false;
}

bool FrameDesignSession::back() {
  State& state = *state_;
  if (state.path.empty()) return false;
  state.designer.untake();
  state.path.pop_back();
  state.steps.pop_back();
  state.children.pop_back();
  state.showProgress();
  return true;
}

FrameDesignResult FrameDesignSession::finish(const DesignLimits& limits) {
  const State& state = *state_;
  if (complete()) return state.result;  // a complete node: its verified design
  FrameDesignOptions options = state.options;
  options.limits = limits;
  // A designer of its own: its random state does not depend on what this session explored before,
  // and the session's labels and children stay as they are.
  FrameDesigner designer(state.layout, options);
  FrameDesignResult result = designer.run(state.path);
  if (result.status == DesignStatus::Success) {
    const std::string failure = frameDesignFailure(state.layout, result.labels, result.order, result.directions);
    if (!failure.empty()) throw Error(ErrorCode::Internal, "the frame design did not verify: " + failure);
  }
  return result;
}

std::string frameDesignFailure(const FrameLayout& layout, const std::vector<JointLabels>& labels,
                               const std::vector<int>& order, const std::vector<Vec3>& directions) {
  const Frame& frame = layout.frame;
  try {
    validateJointLabels(layout, labels, "design");
  } catch (const Error& e) {
    return e.what();
  }
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (size_t k = 0; k < sorted.size(); ++k) {
    if (sorted[k] != static_cast<int>(k)) return "the removal order does not list every beam once";
  }
  if (directions.size() + 1 != order.size()) return "every beam but the last needs a removal direction";
  const Assembly assembly = frameAssembly(layout, labels, order);
  const InterlockingResult byGraphs = testInterlockingByGraphs(assembly, computeBaseDirections(assembly));
  if (byGraphs.verdict != Verdict::Interlocking || byGraphs.key != 0) return "dbg: " + byGraphs.reason;
  bool keyDirection = false;
  for (const Vec3& d : byGraphs.keyDirections) {
    keyDirection = keyDirection || dot(d, directions[0]) > 1 - tolerance::kDirection;
  }
  if (!keyDirection) return "the key is not free along its planned direction " + directionLabel(directions[0]);
  std::vector<bool> present(frame.beams.size(), true);
  for (size_t k = 0; k < directions.size(); ++k) {
    const std::string obstacle = frameSweepObstacle(layout, labels, order[k], directions[k], present);
    if (!obstacle.empty()) {
      return "beam " + std::to_string(frame.beams[order[k]].id) + " cannot leave along " +
             directionLabel(directions[k]) + ": it hits " + obstacle;
    }
    present[order[k]] = false;
  }
  return "";
}

FrameDesignResult designFrame(const FrameLayout& layout, const FrameDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  FrameDesigner designer(layout, options);
  FrameDesignResult result = designer.run();
  if (result.status == DesignStatus::Success) {
    // The search accepts only what passes; checking again guards the result, never a guess.
    const std::string failure = frameDesignFailure(layout, result.labels, result.order, result.directions);
    if (!failure.empty()) throw Error(ErrorCode::Internal, "the frame design did not verify: " + failure);
  }
  return result;
}

}  // namespace desia
