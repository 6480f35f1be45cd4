// SPDX-License-Identifier: GPL-3.0-or-later
// The frame designer's tree (frame_designer.h): moving along it, a complete design verified, and
// the restarted search of paper Algorithm 1 (search/construction_search.h) over it.
#include "frame/frame_designer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "desia/error.h"
#include "desia/tolerances.h"
#include "search/construction_search.h"
#include "search/restarts.h"

namespace desia::frame_design {

std::string keyBeamName(const Frame& frame, int keyIndex) {
  const FrameBeam& beam = frame.beams[keyIndex];
  const int inputId = beam.inputId ? beam.inputId : beam.id;  // as frameResultToJson writes it
  return inputId == 1 ? "beam 1" : "beam 1, input beam " + std::to_string(inputId);
}

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

// The random state of restart `attempt` for the user's seed (search/restarts.h).
uint64_t attemptSeed(uint64_t seed, int64_t attempt) {
  return restartState(seed, attempt, seed * 0x9E3779B97F4A7C15ull + 7);
}

// The budget unit of a search tree, in work (beam-direction corridors and voxel-set pairs tried,
// so a tree of slow nodes is cut as soon as one of many fast ones): a node tries about as many
// pairs as R has beams next to taken ones, and a design of n beams takes n nodes, hence n^2: seeds
// that succeed mostly do within this, and the failing ones would thrash for tens of thousands of
// nodes. The floor lets small frames of slow curved beams (FLOWER) finish their first tree.
int64_t restartUnit(int beams) { return std::max<int64_t>(int64_t(1) << 16, 3 * int64_t(beams) * beams); }

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
  result.message = "designed the joints of " + std::to_string(beams) + " beams (key: " +
                   keyBeamName(frame_, result.order[0]) + ") in " + std::to_string(progress.nodes) + " nodes";
  return result;
}

}  // namespace desia::frame_design
