// SPDX-License-Identifier: GPL-3.0-or-later
// The path of a step-by-step design session: the construction tree of the paper's Algorithm 1,
// walked by the user one child at a time. It holds the steps taken, what the user was shown of
// each, and the ranked children of every node on the path, made when first asked for (so that
// going back shows the same children again). Plate and frame sessions share it; each kind brings
// its steps, how a node's children are made, and how a step is taken and a complete path verified.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "desia/error.h"

namespace desia::search {

template <class Step, class Shown>
class SessionPath {
 public:
  const std::vector<Step>& steps() const { return steps_; }
  const std::vector<Shown>& shown() const { return shown_; }
  size_t depth() const { return steps_.size(); }

  // The children of the node at the end of the path, made by `make()` the first time.
  template <class Make>
  std::vector<Step>& children(Make make) {
    if (!children_.back()) children_.back() = make();
    return *children_.back();
  }

  // The path with `step` after it (what a step that completes the design is verified on).
  std::vector<Step> with(const Step& step) const {
    std::vector<Step> whole = steps_;
    whole.push_back(step);
    return whole;
  }

  // Into a child: `step`, shown to the user as `shown`.
  void enter(Step step, Shown shown) {
    steps_.push_back(std::move(step));
    shown_.push_back(std::move(shown));
    children_.push_back(std::nullopt);
  }

  // Back to the parent; false at the root.
  bool leave() {
    if (steps_.empty()) return false;
    steps_.pop_back();
    shown_.pop_back();
    children_.pop_back();
    return true;
  }

  // Child n of the node at the end of the path dropped (it completed a design that failed).
  void drop(size_t n) {
    std::vector<Step>& here = *children_.back();
    here.erase(here.begin() + static_cast<std::ptrdiff_t>(n));
  }

 private:
  std::vector<Step> steps_;
  std::vector<Shown> shown_;
  std::vector<std::optional<std::vector<Step>>> children_{std::nullopt};  // per node on the path, root first
};

// A session's next(): the first child that can be taken (one that completes a design that fails
// is dropped by chooseChild, which throws, and the next is tried); false when none is left.
template <class Session>
bool takeFirstChild(Session& session) {
  for (int count = session.childCount(); count > 0; count = session.childCount()) {
    try {
      session.chooseChild(0);
      return true;
    } catch (const Error&) {
      // That child completed a design that failed and was dropped: try the next one. Any other
      // error left the children as they were: trying the same child again would loop forever.
      if (session.childCount() != count - 1) throw;
    }
  }
  return false;
}

// The error for a child number that is not one of the node's.
[[noreturn]] inline void throwNoSuchChild(int n, int count) {
  throwBadInput("", "child " + std::to_string(n) + " does not exist: this node has " + std::to_string(count));
}

}  // namespace desia::search
