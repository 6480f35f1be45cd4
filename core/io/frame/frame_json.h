// SPDX-License-Identifier: GPL-3.0-or-later
// The frame sections of a JSON assembly document, for the document reader (json_document.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "desia/document.h"

namespace desia {

// A document of kind "frame" with `joints` and `beams` (at the top or inside `frame`): the frame
// validated, parts = beams, contacts = the faces between the voxels of different beams when its
// joints are designed. Throws BadInput naming `source`.
AssemblyDocument frameAssemblyDocumentFromJson(const nlohmann::json& root, const std::string& source,
                                               const std::string& name);

// The geometry sections of a frame document (jointSize, beamSection, joints, beams, and for a
// design result jointVoxels and removal), as the document writer puts them beside its header.
nlohmann::json frameSectionsJson(const FrameDocument& document);

// True when `source` names a FrameInterlock .fpuz file.
bool isFpuzSource(const std::string& source);
// The same document from a .fpuz file.
AssemblyDocument frameAssemblyDocumentFromFpuz(const std::string& text, const std::string& source);

}  // namespace desia
