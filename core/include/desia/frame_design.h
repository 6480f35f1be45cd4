// SPDX-License-Identifier: GPL-3.0-or-later
// Designing the voxel joints of an interlocking frame structure (paper Section 5.3): the key beam,
// the order in which the other beams are taken out, the axis each one leaves along, and which beam
// owns each voxel of each joint cube. Same shape as the plate planner (plate_design.h).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/design_search.h"
#include "desia/frame.h"

namespace desia {

struct FrameDesignOptions {
  uint64_t seed = 1;
  int candidates = 2;            // children kept per node (the paper's m; FrameInterlock keeps 2)
  DesignLimits limits{60, 1'000'000, {}, false};  // time, nodes, progress and cancellation
};

struct FrameDesignResult {
  DesignStatus status = DesignStatus::NotFound;
  std::string message;              // one sentence for the user
  std::vector<int> order;           // beam indices: the key first, the last beam last
  std::vector<Vec3> directions;     // axis direction order[k] leaves along (none for the last beam)
  std::vector<JointLabels> labels;  // per joint, the owning beam of each voxel (internal indices)
  Assembly assembly;                // parts = beams in `order` (part 1 = key), voxel contacts
  DesignProgress progress;
};

// One step of a frame design: the beam taken (an index), the axis direction it leaves along, and
// the free voxels it takes at its two joints (frame.beams[beam].joints[0] and [1]; voxel indices
// 0..26, x fastest) besides the face voxels it owns from the start.
struct FrameDesignStep {
  int beam = 0;
  Vec3 direction{0, 0, 0};
  std::array<std::vector<int>, 2> voxels;
};

// Step-by-step design (as the voxel and plate sessions, paper Algorithm 1 by hand): the beams
// taken so far, the ranked children of the current node (the designer's, options.candidates per
// node, more for the key), choose one, go back. A choice that completes the design is accepted
// only if it verifies (frameDesignFailure). Deterministic for a seed and a sequence of calls.
class FrameDesignSession {
 public:
  // Throws BadInput for a frame no joints can make interlocking (a cut-point beam, named; fewer
  // than 3 beams).
  FrameDesignSession(FrameLayout layout, const FrameDesignOptions& options);
  ~FrameDesignSession();
  FrameDesignSession(const FrameDesignSession&) = delete;
  FrameDesignSession& operator=(const FrameDesignSession&) = delete;

  const std::vector<FrameDesignStep>& steps() const;  // the key first
  int targetBeams() const;
  bool complete() const;  // every beam placed and the design verified
  // The verified result once complete (status Success), else NotFound saying how far it got.
  const FrameDesignResult& result() const;

  int childCount();                     // ranked children of the current node (generated on first call)
  FrameDesignStep childPreview(int n);  // the n-th child (0 = best ranked), without moving
  // Moves to the n-th child. Throws BadInput when n is out of range, or when that child completes
  // a design that fails verification (the child is dropped from the list; the message says why).
  void chooseChild(int n);
  bool next();  // moves to the best child that works; false when none does (then go back)
  bool back();  // moves to the parent; false at the root
  // "Finish automatically from here": designFrame's restarted search run below the current node,
  // so the beams taken so far stay, first in the order with their directions and voxels; restarts
  // re-seed below this node. A success is verified like any design. The session does not move.
  // Deterministic: the same path and seed give the same result.
  FrameDesignResult finish(const DesignLimits& limits);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Designs the joints of a frame whose parts-graph has no cut point (otherwise: status CutPoint,
// naming the beam). Deterministic for a seed. A success has been verified (frameDesignFailure).
FrameDesignResult designFrame(const FrameLayout& layout, const FrameDesignOptions& options = {});

// Why a complete design fails, or "" when it passes: the assembly of the joint voxels is
// interlocking by the DBG test with order[0] as the only movable part, and each beam, with its
// body and voxels, leaves the beams after it along its direction without hitting any of their
// bodies or voxels (swept), in order.
std::string frameDesignFailure(const FrameLayout& layout, const std::vector<JointLabels>& labels,
                               const std::vector<int>& order, const std::vector<Vec3>& directions);

}  // namespace desia
