// SPDX-License-Identifier: GPL-3.0-or-later
// The check of an assembly known by its parts and contacts (paper Sections 3 and 4): the DBG test,
// the LP test or both, and a disassembly plan from a planner the kind of assembly supplies.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "desia/blocking_graph.h"
#include "desia/disassembly.h"
#include "desia/interlocking.h"

namespace desia {

enum class CheckMethod { Graphs, Inequalities, Both };
// Parses "dbg", "lp" or "both"; throws BadInput otherwise.
CheckMethod parseCheckMethod(const std::string& name);
const char* checkMethodName(CheckMethod method);

// Reports keep every base DBG up to this many base directions; beyond it (hundreds of distinct
// normals give hundreds of thousands) only their count, unless all graphs are asked for.
constexpr size_t kReportedGraphLimit = 128;

struct CheckOptions {
  CheckMethod method = CheckMethod::Graphs;
  bool planDisassembly = true;
  bool allGraphs = false;  // keep every base DBG in the report, however many
};

// Plate and frame results carry their removal plan; the contacts alone cannot tell whether the
// real shapes let each part out, so checkDocument (document_check.h) moves them.
struct ShapeRemovalCheck {
  std::string checked;  // what was moved, e.g. "each plate swept along its direction, in the planned order"
  std::string failure;  // why a part cannot leave ("" = every part left)
};

struct CheckReport {
  CheckMethod method = CheckMethod::Graphs;
  InterlockingResult result;                          // the combined verdict
  std::optional<InterlockingResult> graphResult;      // when the DBG test ran
  std::optional<InterlockingResult> inequalityResult; // when the LP test ran
  size_t baseDirectionCount = 0;                      // number of base directions (and DBGs)
  std::vector<DirectionalBlockingGraph> graphs;       // base DBGs of the full assembly, or none
                                                      // when over kReportedGraphLimit
  std::optional<DisassemblyPlan> disassembly;         // absent when not planned
  std::optional<ShapeRemovalCheck> shapeRemoval;      // plate and frame results (checkDocument)
};

// Plans the disassembly of an assembly: planContactDisassembly for contacts alone, or a kind's
// planner that moves the real shapes (voxels).
using DisassemblyPlanner = std::function<DisassemblyPlan(const Assembly&)>;

// The interlocking tests of `options.method` on the assembly's contacts and, when
// options.planDisassembly, the plan `planner` makes.
CheckReport checkContacts(const Assembly& assembly, const CheckOptions& options = {},
                          const DisassemblyPlanner& planner = planContactDisassembly);

}  // namespace desia
