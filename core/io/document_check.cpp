// SPDX-License-Identifier: GPL-3.0-or-later
// checkDocument: the contact check of any document, and what each kind adds (plate results
// verified again: io/plate/plate_check.cpp; designed frames swept: io/frame/frame_check.cpp).
#include "desia/document.h"

#include "io/frame/frame_check.h"
#include "io/plate/plate_check.h"

namespace desia {

CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options) {
  if (document.kind == AssemblyKind::Plate && document.plateResult) return checkPlateResult(document, options);
  CheckReport report = checkAssembly(document, options);
  if (document.kind == AssemblyKind::Frame && document.contactsFromGeometry) {
    report.shapeRemoval = frameShapeRemoval(document);
  }
  return report;
}

bool checkPassed(const CheckReport& report) {
  return report.result.verdict == Verdict::Interlocking && (!report.shapeRemoval || report.shapeRemoval->failure.empty());
}

}  // namespace desia
