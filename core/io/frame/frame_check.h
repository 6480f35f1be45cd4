// SPDX-License-Identifier: GPL-3.0-or-later
// The frame kind's part of checkDocument (io/document_check.cpp).
#pragma once

#include <optional>

#include "desia/document.h"

namespace desia {

// A designed frame's plan swept beam by beam (body and joint voxels along its direction, in the
// planned order); nothing for a frame without designed joints or directions.
std::optional<ShapeRemovalCheck> frameShapeRemoval(const AssemblyDocument& document);

}  // namespace desia
