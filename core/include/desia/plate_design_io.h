// SPDX-License-Identifier: GPL-3.0-or-later
// The result document of a plate joint plan, shared by the CLI and (later) the WebAssembly module.
#pragma once

#include <string>

#include "desia/document.h"
#include "desia/plate_design.h"

namespace desia {

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

}  // namespace desia
