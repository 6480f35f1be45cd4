// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/analysis.h"

#include "desia/error.h"

namespace desia {

CheckMethod parseCheckMethod(const std::string& name) {
  if (name == "dbg") return CheckMethod::Graphs;
  if (name == "lp") return CheckMethod::Inequalities;
  if (name == "both") return CheckMethod::Both;
  throwBadInput("", "unknown method '" + name + "' (expected dbg, lp or both)");
}

const char* checkMethodName(CheckMethod method) {
  switch (method) {
    case CheckMethod::Graphs: return "dbg";
    case CheckMethod::Inequalities: return "lp";
    case CheckMethod::Both: return "both";
  }
  return "dbg";
}

namespace {

// With both tests, agreement gives that verdict. The LP test is exact for any contact normals, so
// when the DBG test (only a necessary condition for non-orthogonal contacts, Section 3.2) finds
// interlocking or deadlock but the LP finds a motion, the LP's motion is the answer. The reverse
// cannot happen (a DBG witness is a motion the LP must find) and is reported as such.
InterlockingResult combine(const InterlockingResult& graphs, const InterlockingResult& inequalities) {
  if (graphs.verdict == inequalities.verdict && graphs.key == inequalities.key) return graphs;
  if (inequalities.verdict == Verdict::NotInterlocking) {
    InterlockingResult result = inequalities;
    result.reason += " (the blocking graphs miss this motion: parts move in different directions at once)";
    return result;
  }
  InterlockingResult result = graphs.verdict == Verdict::NotInterlocking ? graphs : inequalities;
  result.verdict = Verdict::NotInterlocking;
  result.reason = "the two tests disagree (dbg: " + std::string(verdictName(graphs.verdict)) +
                  ", lp: " + verdictName(inequalities.verdict) + "); " + graphs.reason;
  return result;
}

}  // namespace

CheckReport checkContacts(const Assembly& assembly, const CheckOptions& options, const DisassemblyPlanner& planner) {
  CheckReport report;
  report.method = options.method;
  // The base directions are computed once and shared by both tests and the plan.
  const std::vector<BaseDirection> directions = computeBaseDirections(assembly);
  report.baseDirectionCount = directions.size();
  if (options.allGraphs || directions.size() <= kReportedGraphLimit) {
    const BlockingGraphBuilder builder(assembly, directions.size());
    for (const BaseDirection& direction : directions) report.graphs.push_back(builder.build(direction));
  }
  if (options.method != CheckMethod::Inequalities) {
    report.graphResult = report.graphs.empty() && !directions.empty()
                             ? testInterlockingByGraphs(assembly, directions)
                             : testInterlockingByGraphs(assembly, report.graphs);
  }
  if (options.method != CheckMethod::Graphs) {
    report.inequalityResult = testInterlockingByInequalities(assembly, directions);
  }
  if (options.method == CheckMethod::Both) {
    report.result = combine(*report.graphResult, *report.inequalityResult);
  } else {
    report.result = report.graphResult ? *report.graphResult : *report.inequalityResult;
  }
  if (options.planDisassembly) report.disassembly = planner(assembly);
  return report;
}

}  // namespace desia
