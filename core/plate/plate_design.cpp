// SPDX-License-Identifier: GPL-3.0-or-later
// Designing the joints of a plate structure (paper Section 5.2): the whole design and the
// step-by-step session, both driving the joint planner (plate_planner.h).
#include "desia/plate.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "desia/error.h"
#include "plate/joints/missing_joints.h"
#include "plate/plate_planner.h"
#include "plate/plate_verification.h"
#include "search/session_path.h"

namespace desia {
namespace {

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
  search::SessionPath<PlanStep, PlateDesignStep> path;
  PlateDesignResult result;

  std::vector<PlanStep>& childrenHere() {
    return path.children([&] { return planner.childrenOf(path.steps()); });
  }
  void showProgress() {
    result.status = DesignStatus::NotFound;
    result.message = std::to_string(path.depth()) + " of " + std::to_string(planner.plateCount()) +
                     " plates taken (the last one stays): choose the next";
  }
};

namespace {

PlateDesignStep publicStep(const PlanStep& step) { return {step.plate, step.direction, step.joints}; }

}  // namespace

// Step by step there is no whole design to choose among: 'auto' steps with cut joints, the first
// it tries, so that stepping a design that can be cut reaches the plan designPlateJoints finds.
PlateDesignOptions steppingOptions(PlateDesignOptions options) {
  if (options.realization == JointRealization::Auto) options.realization = JointRealization::Cut;
  return options;
}

PlateDesignSession::PlateDesignSession(std::vector<Plate> plates, std::vector<PlateContact> contacts,
                                       const PlateDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  state_ = std::make_unique<State>(std::move(plates), std::move(contacts), steppingOptions(options));
  if (std::optional<PlateDesignResult> refused = state_->planner.refusal()) throwBadInput("", refused->message);
  state_->showProgress();
}

PlateDesignSession::~PlateDesignSession() = default;

const std::vector<PlateDesignStep>& PlateDesignSession::steps() const { return state_->path.shown(); }
int PlateDesignSession::targetPlates() const { return state_->planner.plateCount(); }
bool PlateDesignSession::complete() const { return state_->result.status == DesignStatus::Success; }
const PlateDesignResult& PlateDesignSession::result() const { return state_->result; }

int PlateDesignSession::childCount() {
  return complete() ? 0 : static_cast<int>(state_->childrenHere().size());
}

PlateDesignStep PlateDesignSession::childPreview(int n) {
  if (n < 0 || n >= childCount()) search::throwNoSuchChild(n, childCount());
  return publicStep(state_->childrenHere()[static_cast<size_t>(n)]);
}

void PlateDesignSession::chooseChild(int n) {
  const PlateDesignStep preview = childPreview(n);  // checks n
  State& state = *state_;
  const PlanStep step = state.childrenHere()[static_cast<size_t>(n)];
  if (static_cast<int>(state.path.depth()) + 2 == state.planner.plateCount()) {
    // The last plate stays: this choice completes the plan, which must verify.
    PlateDesignResult result;
    result.progress.targetParts = state.planner.plateCount();
    if (!state.planner.acceptComplete(state.path.with(step), &result)) {
      state.path.drop(static_cast<size_t>(n));
      throwBadInput("", "taking plate " + std::to_string(state.plates[preview.plate].id) +
                            " completes a plan that fails: " + state.planner.lastRejection() + "; choose another");
    }
    result.message = "designed " + std::to_string(result.joints.size()) + " joints step by step";
    state.result = result;
    state.path.enter(step, preview);
  } else {
    state.path.enter(step, preview);
    state.showProgress();
  }
}

bool PlateDesignSession::next() { return search::takeFirstChild(*this); }

bool PlateDesignSession::back() {
  if (!state_->path.leave()) return false;
  state_->showProgress();
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
  PlateDesignResult result = planner.run(state.path.steps());
  requireVerified(state.plates, result, options.geometry);
  return result;
}

JointRealization parseJointRealization(const std::string& name) {
  if (name == "cut") return JointRealization::Cut;
  if (name == "milled") return JointRealization::Milled;
  if (name == "planned") return JointRealization::Planned;
  if (name == "auto") return JointRealization::Auto;
  throwBadInput("",
                "joints must be 'auto' (cut if possible, else milled, else planned), 'cut' (laser or router cuts "
                "through the plates, verified there), 'milled' (also sliding dovetails) or 'planned' (the "
                "paper's graph design alone), got '" +
                    name + "'");
}

const char* jointRealizationName(JointRealization realization) {
  switch (realization) {
    case JointRealization::Cut: return "cut";
    case JointRealization::Milled: return "milled";
    case JointRealization::Planned: return "planned";
    case JointRealization::Auto: return "auto";
  }
  return "cut";
}

namespace {

// Why an attempt found no plan, without the advice to try other joints (auto tries them).
std::string reasonOf(const PlateDesignResult& result) {
  const std::string& message = result.message;
  const size_t advice = message.find("; joints '");
  return advice == std::string::npos ? message : message.substr(0, advice);
}

// The share of the time left that an attempt of 'auto' may use (see designWithChosenJoints).
double shareOfTimeLeft(JointRealization realization) {
  switch (realization) {
    case JointRealization::Cut: return 0.5;
    case JointRealization::Milled: return 0.75;
    default: return 1.0;
  }
}

// 'auto': what a laser can cut, else what a router can mill, else the paper's plan, within one
// time budget. A made-joint search stopped by the clock proves nothing, so it may not eat the
// whole budget: the laser-cut attempt gets half of it, the milled one three quarters of what is
// left, the paper's plan the rest (what an attempt does not use passes on). Node limits apply per
// attempt.
PlateDesignResult designWithChosenJoints(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                         const PlateDesignOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string why;
  PlateDesignResult result;
  for (JointRealization realization : {JointRealization::Cut, JointRealization::Milled, JointRealization::Planned}) {
    PlateDesignOptions attempt = options;
    attempt.realization = realization;
    if (options.limits.timeLimitSeconds > 0) {
      const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (spent >= options.limits.timeLimitSeconds) break;  // the budget is spent: say what was tried
      const double left = options.limits.timeLimitSeconds - spent;
      attempt.limits.timeLimitSeconds = left * shareOfTimeLeft(realization);
    }
    result = designPlateJoints(plates, contacts, attempt);
    if (result.status == DesignStatus::Success) {
      std::string said = std::string("joints: ") + jointRealizationName(realization);
      if (realization == JointRealization::Planned) {
        said += ", nothing is cut: the paper's plan of which joint each pair needs (" + why + ")";
        const std::string lacking = jointsNothingMakesSentence(plates, contacts, result.joints, options.joints);
        if (!lacking.empty()) said += "\n" + lacking;
      } else if (!why.empty()) {
        said += " (" + why + ")";
      }
      result.message = said + "\n" + result.message;
      return result;
    }
    // A cut point, a cancelled search or a spent time budget ends the choice there.
    if (result.status == DesignStatus::CutPoint || result.status == DesignStatus::Cancelled) return result;
    // A search stopped at its limits proved nothing: say so.
    why += std::string(why.empty() ? "" : "; ") + "no " +
           (realization == JointRealization::Cut ? "laser-cut" : realization == JointRealization::Milled ? "milled" : "planned") +
           (result.status == DesignStatus::LimitReached ? " plan found within the limits: " : " plan: ") + reasonOf(result);
  }
  result.message = "no joints found (" + why + ")";
  return result;
}

}  // namespace

PlateDesignResult designPlateJoints(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                    const PlateDesignOptions& options) {
  if (options.candidates < 1) throwBadInput("", "candidates must be at least 1");
  if (options.realization == JointRealization::Auto) return designWithChosenJoints(plates, contacts, options);
  PlateJointPlanner planner(plates, contacts, options);
  PlateDesignResult result = planner.run();
  // The search accepts only what passes; checking again guards the result, never a guess.
  requireVerified(plates, result, options.geometry);
  return result;
}

}  // namespace desia
