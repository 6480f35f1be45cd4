// SPDX-License-Identifier: GPL-3.0-or-later
// The plate kind's part of checkDocument (io/document_check.cpp).
#pragma once

#include "desia/document.h"

namespace desia {

// A plate result (a document with `removal`): the plan verified as the designer verified it
// (verifyJointedPlates, or verifyPlannedPlates for a plan with nothing cut), the verdict reported on
// the contacts that verification judged, and fabricationPlates held within the clearance.
CheckReport checkPlateResult(const AssemblyDocument& document, const CheckOptions& options);

}  // namespace desia
