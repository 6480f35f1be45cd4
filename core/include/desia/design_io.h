// SPDX-License-Identifier: GPL-3.0-or-later
// Text forms of the voxel designer's inputs and outputs, shared by the CLI and the WebAssembly
// module: appearance groups, design options as JSON, and the design result as JSON.
#pragma once

#include <string>
#include <vector>

#include "desia/voxel_design.h"

namespace desia {

// "+x", "-x", "+y", "-y", "+z" or "-z"; throws BadInput naming `what` otherwise.
Int3 parseAxisDirection(const std::string& text, const std::string& what = "key direction");

// {"groups": [[[x, y, z], ...], ...]}: voxel coordinates that must share one part. Throws BadInput
// naming `source` and the group for malformed JSON or voxels outside the shape.
std::vector<std::vector<int64_t>> parseVoxelGroupsJson(const std::string& text, const VoxelGrid& shape,
                                                       const std::string& source);

// The package's design options, e.g. {"parts": 7, "seed": 1, "candidates": 30,
// "rank": "compactness", "mode": "desia", "minPartSize": 0, "maxPartSize": 0, "evenParts": false,
// "timeLimit": 30, "nodeLimit": 0, "keyDirection": "+y", "groups": [[[x, y, z], ...]]}. Unknown
// fields are refused.
VoxelDesignOptions parseDesignOptionsJson(const std::string& text, const VoxelGrid& shape);

// The limits of a session's finish(): {"timeLimit": seconds >= 0, "nodeLimit": n >= 0} (0 or
// absent: none). Unknown fields are refused.
DesignLimits parseDesignLimitsJson(const std::string& text);

// {"status", "message", "progress": {...}, "seed": the search's seed, "partSizes": {"min", "max",
//  "mean"} or null, "puz": text or null, "document": {...} or null, "verification": check report
//  or null}.
std::string designResultToJson(const VoxelDesignResult& result, int indent = -1);
std::string designProgressToJson(const DesignProgress& progress);

}  // namespace desia
