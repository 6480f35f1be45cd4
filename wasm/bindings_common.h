// SPDX-License-Identifier: GPL-3.0-or-later
// What both binding files (bindings.cpp, bindings_plate_frame.cpp) share: the exception guard,
// JSON results as JS values and the designers' progress callback. No algorithm lives here.
#pragma once

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <functional>
#include <string>
#include <vector>

#include "desia/design_io.h"
#include "desia/error.h"
#include "desia/search.h"

namespace desia::bindings {

using emscripten::val;

inline val parseJsonText(const std::string& text) { return val::global("JSON").call<val>("parse", val(text)); }

// Runs `operation` and converts any exception into a thrown JS Error carrying the core's message
// and a `code`. The JS throw happens after the catch block has ended, so C++ destructors and
// exception cleanup have run (toolchain.md #8).
template <typename Operation>
auto guarded(Operation&& operation) -> decltype(operation()) {
  std::string message, code;
  try {
    return operation();
  } catch (const desia::Error& e) {
    message = e.what();
    code = desia::errorCodeName(e.code());
  } catch (const std::bad_alloc&) {
    message = "out of memory";
    code = "too-large";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
    code = "internal";
  } catch (...) {
    message = "internal error: unknown exception";
    code = "internal";
  }
  val error = val::global("Error").new_(val(message));
  error.set("code", val(code));
  error.set("name", val(std::string("DesiaError")));
  error.throw_();
}

// Live design (issue 11): the deepest node found so far rides on a progress object as `snapshot`
// only when it is deeper than the last one handed to JS, so a search of thousands of nodes a
// second copies at most one snapshot per new depth across the boundary.
class SnapshotGate {
 public:
  bool isNew(int depth) {
    if (depth <= sentDepth_) return false;
    sentDepth_ = depth;
    return true;
  }

 private:
  int sentDepth_ = -1;
};

// { depth, labels }: the deepest node's voxel labels (parts 1..depth placed, depth + 1 the remainder) as
// an Int32Array copied out of the heap, in the shape's grid order (x fastest, as documents).
inline val voxelSnapshot(const desia::DesignProgress& progress) {
  const std::vector<int>& labels = progress.deepestGrid->labels();
  val snapshot = val::object();
  snapshot.set("depth", progress.bestDepth - 1);  // parts placed, as the plates' and beams' snapshots
  snapshot.set("labels", val(emscripten::typed_memory_view(labels.size(), labels.data())).call<val>("slice"));
  return snapshot;
}

// { depth, placed }: the plates or beams (input indices, the key first) of the deepest node.
inline val placedSnapshot(const std::vector<int>& placed) {
  val snapshot = val::object();
  snapshot.set("depth", static_cast<int>(placed.size()));
  snapshot.set("placed", val::array(placed));
  return snapshot;
}

// A designer's progress (any kind) as a plain object for a JS function, which may return false to
// stop the search; the deepest node rides along as `snapshot` when it is new. Holds `onProgress` by
// reference: use it within the call that received it.
inline std::function<bool(const desia::DesignProgress&)> progressCallback(const val& onProgress) {
  return [&onProgress, gate = SnapshotGate()](const desia::DesignProgress& progress) mutable {
    val value = parseJsonText(desia::designProgressToJson(progress));
    if (progress.deepestGrid && gate.isNew(progress.bestDepth)) {
      value.set("snapshot", voxelSnapshot(progress));
    } else if (!progress.deepestGrid && !progress.deepestPlaced.empty() &&
               gate.isNew(static_cast<int>(progress.deepestPlaced.size()))) {
      value.set("snapshot", placedSnapshot(progress.deepestPlaced));
    }
    return !onProgress(value).isFalse();
  };
}

// Asks for progress (and the live view) when `onProgress` is a JS function.
inline void listen(desia::DesignLimits& limits, const val& onProgress) {
  if (onProgress.typeOf().as<std::string>() != "function") return;
  limits.onProgress = progressCallback(onProgress);
  limits.deepestSnapshots = true;  // a listener gets the live view too
}

}  // namespace desia::bindings
