// SPDX-License-Identifier: GPL-3.0-or-later
// The frame designer's options, progress and result as JSON, for the WebAssembly module (the
// package's designFrame); the same shapes as the plate planner's (plate_design_io.h).
#pragma once

#include <string>

#include "desia/document.h"
#include "desia/frame_design.h"
#include "desia/frame_format.h"

namespace desia {

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

}  // namespace desia
