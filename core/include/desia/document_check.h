// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` for every kind: the interlocking tests on the document's contacts (checkAssembly,
// which knows only parts and contacts), and, for a plate or frame design result, its removal plan
// replayed on the real shapes by the kind's own geometry (paper Section 4.1 (iii)).
#pragma once

#include "desia/check.h"
#include "desia/document.h"

namespace desia {

// checkAssembly, plus for results that carry a removal plan:
// - plate results (read by part id, whatever the file's order): the verification the designer
//   ran before writing the result (verifyJointedPlates for cut and milled joints, verifyPlannedPlates
//   for a plan with nothing cut), the verdict reported on the contacts it judged, and the
//   fabrication plates compared with the verified ones (fabricationPlatesFailure);
// - frames with designed joints: each beam, body and joint voxels, swept along its axis misses
//   every beam still in place.
// The plan is read with the document (PlateResultPlan); a malformed plan is BadInput there.
CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options = {});

// True when the report passes on the contacts and, where it ran, on the shapes.
bool checkPassed(const CheckReport& report);

}  // namespace desia
