// SPDX-License-Identifier: GPL-3.0-or-later
// The designers' options, progress, results and sessions as JSON, shared by the CLI and the
// WebAssembly module.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"
#include "desia/search.h"
#include "desia/voxel.h"

namespace desia {

// Text forms of the voxel designer's inputs and outputs, shared by the CLI and the WebAssembly
// module: appearance groups, design options as JSON, and the design result as JSON.

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

// The result document of a plate joint plan, shared by the CLI and (later) the WebAssembly module.

// A JSON assembly document (kind "plate") for a successful plan: plates renumbered in removal
// order (part 1 = the key; each keeps its `inputId`), the joint contacts as `contacts` (so that
// `desia check` re-verifies the plan on its own), `joints` (plates, type, direction) and
// `removal` (each plate's direction, in order).
std::string plateDesignToJson(const AssemblyDocument& input, const PlateDesignResult& result, int indent = 2);

// Options as the package passes them ({seed, candidates, nodeLimit, timeLimit}); unknown names
// and values out of range are BadInput.
PlateDesignOptions parsePlateDesignOptionsJson(const std::string& text);
// {status, message, progress, puz: null, document: the plan or null, verification: its check with
// both tests or null, repair: for a cut point, {message, document} of the design with the bars
// proposeCutPointRepair adds, or null}, the shape of the voxel designer's result.
std::string plateDesignResultToJson(const AssemblyDocument& input, const PlateDesignResult& result);

// A plate design session's current node for the package: {partsPlaced (plates taken + the rest),
// targetParts, complete, steps: [{plate, direction}] (input ids), document: the verified result
// document once complete, else the input design}.
std::string plateSessionStateToJson(const AssemblyDocument& input, const PlateDesignSession& session);
// One child of a session's node: {plate, direction, joints: [{mover, other, type, direction}]} (input ids).
std::string plateStepToJson(const AssemblyDocument& input, const PlateDesignStep& step);

// The frame designer's options, progress and result as JSON, for the WebAssembly module (the
// package's designFrame); the same shapes as the plate planner's above.

// The package's designFrame options: the designer's, and the joint cube size used when reading
// the frame (0 = the file's or the default from the geometry).
struct FramePackageOptions {
  FrameDesignOptions design;
  double jointSize = 0;
};

// Options as the package passes them ({seed, candidates, nodeLimit, timeLimit, jointSize}); unknown
// names and values out of range are BadInput.
FramePackageOptions parseFrameDesignOptionsJson(const std::string& text);
// {status, message, progress, puz: null, document: the result document (frameResultToJson) or
// null, verification: its DBG check report (what `desia check RESULT.json` prints) or null}.
std::string frameDesignResultToJson(const FrameDocument& input, const FrameDesignResult& result);

// A frame design session's current node for the package: {partsPlaced (beams taken + the rest),
// targetParts, complete, message, steps: [{beam, direction}] (input ids), document: the verified
// result document once complete (frameResultToJson), else the input frame document}.
std::string frameSessionStateToJson(const FrameDocument& input, const FrameDesignSession& session);
// One child of a session's node: {beam, direction, joints: [{joint, voxels}]} (input ids; the
// free voxels the beam takes at each of its two joints, 0..26, x fastest).
std::string frameStepToJson(const FrameDocument& input, const FrameDesignStep& step);

// Is this assembly document a frame given by its geometry (a frame, or a designed one)?
bool isFrameDocument(const AssemblyDocument& document);

// One interactive design session for every kind of assembly (paper Algorithm 1 walked by hand, as
// the original tool's GUI: "Generate Next Part", "Child Index", "Go Back", then "finish
// automatically"), speaking the package's JSON: what the bindings bind once. The kind comes from
// the input: a voxel shape, a plate design (plates, no contacts) or a frame (JSON, .fpuz, OBJ).

class DesignSession {
 public:
  virtual ~DesignSession() = default;

  // {"partsPlaced", "targetParts", "complete", "document", ...}: the current node (kind-specific
  // fields beside these, see docs/javascript-api.md).
  virtual std::string stateJson() const = 0;
  virtual int childCount() = 0;                     // ranked children of the current node
  virtual std::string previewJson(int child) = 0;   // the n-th child (0 = best), without moving
  virtual void choose(int child) = 0;               // move to it; BadInput when out of range
  virtual bool next() = 0;                          // move to the best child; false when none
  virtual bool back() = 0;                          // move to the parent; false at the root
  // The designer's search below the current node (the session does not move): the same result
  // JSON as a whole design of this kind.
  virtual std::string finishJson(const DesignLimits& limits) = 0;
  virtual std::string checkJson() const = 0;        // the check report of the current node
};

// Throws BadInput when `text` is none of the three kinds or fails to parse (named by `source`).
std::unique_ptr<DesignSession> openDesignSession(const std::string& text, const std::string& optionsJson,
                                                 const std::string& source);

}  // namespace desia
