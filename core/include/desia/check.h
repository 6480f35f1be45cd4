// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` of a document of any kind: the contact check (contact_check.h) with the kind's
// disassembly planner, and the report as text or JSON.
#pragma once

#include <string>

#include "desia/contact_check.h"
#include "desia/document.h"

namespace desia {

// checkContacts on the document's contacts; voxel documents plan their disassembly on the voxels.
CheckReport checkAssembly(const AssemblyDocument& document, const CheckOptions& options = {});

// The report as the JSON object printed by `desia check --json` (fields documented in docs/json-schema.md).
std::string checkReportToJson(const AssemblyDocument& document, const CheckReport& report,
                              int indent = 2);
// Human-readable report for the terminal.
std::string checkReportToText(const AssemblyDocument& document, const CheckReport& report);

}  // namespace desia
