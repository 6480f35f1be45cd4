// SPDX-License-Identifier: GPL-3.0-or-later
// Planning the joints of an interlocking plate structure (paper Section 5.2): the key, the order in
// which the other plates are taken out, the direction each one leaves in, and the joint each
// contact becomes. This is the paper's graph design stage; the joints' geometry (tenons, slots,
// dovetails cut into the plates) is not generated yet, so a plan's contacts are those its joints
// are defined to have (see plate_design.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/plate.h"

namespace desia {

enum class JointType {
  Halved,        // the shared edge runs along the removal direction: a slot (paper Fig. 2)
  MortiseTenon,  // the edge is within 45..135 degrees of it
  Empty,         // neither: the plates only touch
};
const char* jointTypeName(JointType type);  // "halved", "mortise-tenon", "empty"

// A joint between two touching plates (internal indices): it lets `mover` leave `other` along
// `direction` only (relative motion), the removal direction planned when `mover` was taken.
struct PlateJoint {
  int mover = 0, other = 0;
  Vec3 direction{0, 0, 0};
  JointType type = JointType::Empty;
};

struct PlateDesignProgress {
  int64_t nodes = 0;      // construction-tree nodes visited
  int depth = 0;          // plates placed in the current node
  int bestDepth = 0;
  int targetParts = 0;    // the number of plates
  double seconds = 0;
};

struct PlateDesignOptions {
  uint64_t seed = 1;
  int candidates = 30;            // children kept per node (the paper's m)
  double timeLimitSeconds = 60;
  int64_t nodeLimit = 1'000'000;
  // Called at every node of the search; return false to cancel.
  std::function<bool(const PlateDesignProgress&)> onProgress;
};

enum class PlateDesignStatus { Success, NotFound, LimitReached, Cancelled, CutPoint };

struct PlateDesignResult {
  PlateDesignStatus status = PlateDesignStatus::NotFound;
  std::string message;               // one sentence for the user
  std::vector<int> order;            // plate indices: the key first, the last plate last
  std::vector<Vec3> directions;      // removal direction of order[k] (none for the last plate)
  std::vector<PlateJoint> joints;
  Assembly jointAssembly;            // the plates with the contacts of their joints (part ids = plate ids)
  PlateDesignProgress progress;
};

// Plans the joints of a connected plate structure whose parts-graph has no cut point (otherwise:
// status CutPoint, naming it). A success has been verified: the joint assembly is interlocking
// with the key as the only movable part by both the DBG and the LP test, and the plates leave in
// the planned order along the planned directions.
PlateDesignResult designPlateJoints(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                    const PlateDesignOptions& options = {});

}  // namespace desia
