// SPDX-License-Identifier: GPL-3.0-or-later
// The plate sections of a JSON assembly document, for the document reader (json_document.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "desia/document.h"

namespace desia {

// The plates of `root[section]` in millimetres (its "unit": mm, cm, m or in), as written.
std::vector<Plate> readPlates(const nlohmann::json& root, const char* section, const std::string& source);
// The same, validated and regularized as computed plates: a plan's or result's plates.
std::vector<Plate> readPlanPlates(const nlohmann::json& root, const char* section, const std::string& source,
                                  const PlateOptions& options);
// A plate design's document from its `plates` (documentFromPlates).
AssemblyDocument plateDesignFromJson(const nlohmann::json& root, const PlateOptions& options,
                                     const std::string& source, const std::string& name);

}  // namespace desia
