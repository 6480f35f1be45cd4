// SPDX-License-Identifier: GPL-3.0-or-later
// What the voxel, plate and frame designers' JSON forms share (design_io.cpp, plate_design_io.cpp,
// frame_design_io.cpp): option values checked against their range, and the envelope of a design
// result and of a session's state that the package reads the same way for every kind.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "desia/model.h"
#include "desia/search.h"

namespace desia {

// An integer option from lo to hi; throws BadInput "design option 'name' must be …" otherwise.
int64_t integerOption(const nlohmann::json& value, const std::string& name, int64_t lo, int64_t hi);
// A number option from lo to hi; `unit` is appended to the range in the message (" (mm)").
double numberOption(const nlohmann::json& value, const std::string& name, double lo, double hi, const char* unit);
std::string stringOption(const nlohmann::json& value, const std::string& name);

nlohmann::json vectorJson(const Vec3& v);

// {status, message, progress: {nodesVisited, bestDepth, targetParts}, puz: null, document: null,
// verification: null}: a plate or frame design's result before its document is filled in (no
// timing: results are reproducible).
nlohmann::json designOutcomeJson(DesignStatus status, const std::string& message, const DesignProgress& progress);

// A design session's node: {partsPlaced (parts taken + the rest), targetParts, complete, message,
// steps, document}.
nlohmann::json sessionStateJson(nlohmann::json steps, int targetParts, bool complete, const std::string& message,
                                nlohmann::json document);

}  // namespace desia
