// SPDX-License-Identifier: GPL-3.0-or-later
// The `plates` section of a JSON assembly document (docs/json-schema.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "desia/plate.h"

namespace desia {

// Reads `plates`: each plate either { id, outline, thickness, holes? } (one face extruded along its
// right-hand normal) or { id, faces: [first, second], holes?: [[first, second], ...] } (both faces,
// vertex for vertex). A closing
// vertex equal to the first is dropped. Throws BadInput naming `source` and the field.
std::vector<Plate> parsePlates(const nlohmann::json& plates, const std::string& source);

// The plates in the `faces` form (both faces, holes as pairs): read back, they are the same plates.
nlohmann::json platesToJson(const std::vector<Plate>& plates);

}  // namespace desia
