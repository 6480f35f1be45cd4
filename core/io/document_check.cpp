// SPDX-License-Identifier: GPL-3.0-or-later
// checkDocument: the contact check of any document, and what each kind adds (plate results
// verified again: io/plate/plate_check.cpp; designed frames swept: io/frame/frame_check.cpp; both
// through the build's table, io/kind_entries.h).
#include "desia/document.h"

#include "io/kind_entries.h"

namespace desia {

CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options) {
  if (document.kind == AssemblyKind::Plate && document.plateResult) return plateFrameEntries().checkPlateResult(document, options);
  CheckReport report = checkAssembly(document, options);
  if (document.kind == AssemblyKind::Frame && document.contactsFromGeometry) {
    report.shapeRemoval = plateFrameEntries().frameShapeRemoval(document);
  }
  return report;
}

bool checkPassed(const CheckReport& report) {
  return report.result.verdict == Verdict::Interlocking && (!report.shapeRemoval || report.shapeRemoval->failure.empty());
}

}  // namespace desia
