// SPDX-License-Identifier: GPL-3.0-or-later
// The construction-tree search every designer runs (Algorithm 1): limits, progress, status.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace desia {

// What every designer (voxel puzzles, plate joints, frame joints) shares with its caller: the
// progress of its construction-tree search (paper Algorithm 1), the limits a caller puts on it and
// how it ended. One set of types for the three kinds, so the CLI, the bindings and the playground
// handle a search the same way whatever it designs.

class VoxelGrid;

struct DesignProgress {
  int64_t nodes = 0;    // construction-tree nodes visited
  int depth = 0;        // parts decided at the current node
  int bestDepth = 0;    // the deepest node reached so far
  int targetParts = 0;  // N: the parts of a complete assembly
  double seconds = 0;   // since the search started
  // With DesignLimits::deepestSnapshots, the deepest node so far for a live view, replaced only
  // when bestDepth grows: plates and beams list the parts taken (input indices, the key first);
  // voxel puzzles give the node's grid (parts 1..bestDepth placed, the remainder labelled
  // bestDepth + 1). Read from the search, never fed back: snapshots never change a result.
  std::vector<int> deepestPlaced;
  std::shared_ptr<const VoxelGrid> deepestGrid;
};

// How a caller bounds a search. The same meaning for every kind: 0 is no limit; the search stops
// before visiting node `nodeLimit + 1` or once `timeLimitSeconds` have passed (time makes the
// outcome depend on the machine; nodes never do).
struct DesignLimits {
  double timeLimitSeconds = 0;
  int64_t nodeLimit = 0;
  // Called after every visited node (never concurrently); return false to cancel.
  std::function<bool(const DesignProgress&)> onProgress;
  bool deepestSnapshots = false;  // fill DesignProgress's deepest node (never changes the search)
};

// How a design ended. CutPoint: the parts-graph has a cut point, so no joints can make the
// assembly interlocking (paper Section 5.2, Fig. 18; plates and frames).
enum class DesignStatus { Success, NotFound, LimitReached, Cancelled, CutPoint };
const char* designStatusName(DesignStatus status);  // "success", "not-found", "limit-reached", ...

}  // namespace desia
