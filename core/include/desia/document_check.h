// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` for every kind: the interlocking tests on the document's contacts (checkAssembly,
// which knows only parts and contacts), and, for a plate or frame design result, its removal plan
// replayed on the real shapes by the kind's own geometry (paper Section 4.1 (iii)).
#pragma once

#include "desia/check.h"
#include "desia/document.h"

namespace desia {

// checkAssembly, plus for results that carry a removal plan:
// - plates whose joints were cut: the contacts recomputed from the jointed plates pass the DBG
//   and LP tests with part 1 as the only movable part, and each plate swept along its direction
//   misses every plate after it (jointedPlatesFailure);
// - frames with designed joints: each beam, body and joint voxels, swept along its axis misses
//   every beam still in place.
// The plan is read from the document's `removal`; a result with a malformed plan is BadInput.
CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options = {});

// True when the report passes on the contacts and, where it ran, on the shapes.
bool checkPassed(const CheckReport& report);

}  // namespace desia
