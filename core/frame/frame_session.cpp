// SPDX-License-Identifier: GPL-3.0-or-later
// Step-by-step frame design (FrameDesignSession), the verification of a frame design
// (frameDesignFailure) and designFrame: the public face of the frame designer (frame_designer.h).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/error.h"
#include "desia/frame.h"
#include "desia/tolerances.h"
#include "frame/frame_designer.h"
#include "search/session_path.h"

namespace desia {

using frame_design::FrameDesigner;
using frame_design::Mask;
using frame_design::Step;


// The session keeps its own copy of the layout (the designer refers to it) and a stack of the
// ranked children of every node on its path, generated when first asked for. The designer's
// labels and path follow the session's path (take / untake).
struct FrameDesignSession::State {
  State(FrameLayout layout_, const FrameDesignOptions& options)
      : layout(std::move(layout_)), designer(layout, options), options(options) {}
  FrameLayout layout;
  FrameDesigner designer;
  FrameDesignOptions options;  // what finish() searches with (its limits replaced)
  search::SessionPath<Step, FrameDesignStep> path;
  FrameDesignResult result;

  std::vector<Step>& childrenHere() {
    return path.children([&] { return designer.sessionChildren(); });
  }
  void showProgress() {
    result = FrameDesignResult{};
    result.status = DesignStatus::NotFound;
    result.progress.targetParts = designer.beamCount();
    result.message = std::to_string(path.depth()) + " of " + std::to_string(designer.beamCount()) +
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

const std::vector<FrameDesignStep>& FrameDesignSession::steps() const { return state_->path.shown(); }
int FrameDesignSession::targetBeams() const { return state_->designer.beamCount(); }
bool FrameDesignSession::complete() const { return state_->result.status == DesignStatus::Success; }
const FrameDesignResult& FrameDesignSession::result() const { return state_->result; }

int FrameDesignSession::childCount() { return complete() ? 0 : static_cast<int>(state_->childrenHere().size()); }

FrameDesignStep FrameDesignSession::childPreview(int n) {
  if (n < 0 || n >= childCount()) search::throwNoSuchChild(n, childCount());
  return state_->publicStep(state_->childrenHere()[static_cast<size_t>(n)]);
}

void FrameDesignSession::chooseChild(int n) {
  const FrameDesignStep preview = childPreview(n);  // checks n
  State& state = *state_;
  const Step step = state.childrenHere()[static_cast<size_t>(n)];
  state.designer.take(step);
  if (static_cast<int>(state.path.depth()) + 2 == state.designer.beamCount()) {
    // The last beam stays with every free voxel: this choice completes the design, which must verify.
    FrameDesignResult result;
    result.progress.targetParts = state.designer.beamCount();
    bool verified = false;
    try {
      verified = state.designer.completeHere(&result);
    } catch (...) {
      state.designer.untake();  // the designer follows the session's path
      throw;
    }
    if (!verified) {
      state.designer.untake();
      state.path.drop(static_cast<size_t>(n));
      throwBadInput("", "taking beam " + std::to_string(state.layout.frame.beams[preview.beam].id) +
                            " completes a design that fails: " + state.designer.lastRejection() + "; choose another");
    }
    result.message = "designed the joints of " + std::to_string(state.designer.beamCount()) +
                     " beams step by step (key: " + frame_design::keyBeamName(state.layout.frame, result.order[0]) + ")";
    state.result = result;
    state.path.enter(step, preview);
  } else {
    state.path.enter(step, preview);
    state.showProgress();
  }
}

bool FrameDesignSession::next() { return search::takeFirstChild(*this); }

bool FrameDesignSession::back() {
  State& state = *state_;
  if (!state.path.leave()) return false;
  state.designer.untake();
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
  FrameDesignResult result = designer.run(state.path.steps());
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
