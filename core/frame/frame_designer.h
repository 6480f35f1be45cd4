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
// earlier parts left). Peeling the beams with the fewest neighbours in R first instead eats R from
// every side at once and leaves it a path through joints of valence 6 whose cubes earlier beams
// have filled: each end of the path has one voxel set left and splits an axis DBG, a dead end
// decided some 50 steps above, and lattices of 3 x 3 x 3 cells or more do not finish.
// A look-ahead keeps R_i from collapsing onto one joint: a beam is not taken when the three or more
// beams left in R_i would all meet at one joint (a star). The last splits of such an R_i are
// almost never interlocking (each of its beams owns every free voxel at its outer joint, so the
// earlier parts there decide alone whether it is blocked), and the depth-first search would then
// backtrack through every ordering of the star (thousands of dead nodes on a lattice).
// The search is depth first with backtracking over an explicit stack, restarted with a seed
// derived from the user's seed when a search tree spends its node budget (budgets follow the
// Luby sequence, so the heavy tail of a bad early choice is cut while no budget is too short
// for long); every complete design is verified (frameDesignFailure) before it is reported. All
// of it counts nodes, never time: the same seed gives the same bytes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/vec3.h"
#include "desia/frame.h"
#include "frame/geometry_internals.h"

namespace desia::frame_design {

using Mask = uint32_t;  // a set of the 27 voxels of a joint cube

constexpr int kFree = -1;  // a joint voxel no beam owns yet

using frame_geometry::Aabb;

// The random state of restart `attempt` for the user's seed (search/restarts.h).
uint64_t attemptSeed(uint64_t seed, int64_t attempt);
// The budget unit of a search tree, in work (see frame_designer.cpp).
int64_t restartUnit(int beams);
// Said when a search finds nothing and no beam meets its joints along an axis.
std::string offTheAxesNote(const Frame& frame);
// "beam 1 (input beam 12)": the key as the result document names it (its beams renumbered in
// removal order, so the key is beam 1, as in `desia check` and the part list), with the id it had
// in this input (its `inputId` when the input was itself a result) when that differs.
std::string keyBeamName(const Frame& frame, int keyIndex);

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
      Aabb bounds = frame_geometry::boxBounds(bodies_.back()[0]);
      for (const OrientedBox& box : bodies_.back()) frame_geometry::include(bounds, frame_geometry::boxBounds(box));
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

}  // namespace desia::frame_design
