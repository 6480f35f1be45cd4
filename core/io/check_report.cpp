// SPDX-License-Identifier: GPL-3.0-or-later
// Serialization of check reports: the JSON object of `desia check --json` (also returned by the
// WebAssembly module) and the terminal text.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "desia/document.h"
#include "desia/voxel.h"

namespace desia {

CheckReport checkAssembly(const AssemblyDocument& document, const CheckOptions& options) {
  if (document.kind != AssemblyKind::Voxel) return checkContacts(document.assembly, options);
  return checkContacts(document.assembly, options,
                       [&](const Assembly& assembly) { return planVoxelDisassembly(document.voxels, assembly); });
}
namespace {

using nlohmann::json;

// Rounds solver output so that last-bit differences between builds never reach the report.
double rounded(double value) {
  const double r = std::round(value * 1e6) / 1e6;
  return r == 0.0 ? 0.0 : r;
}

// A vector for the report, rounded as `rounded` (design_json.h's vectorJson writes full precision).
json roundedVectorJson(const Vec3& v) { return json::array({rounded(v[0]), rounded(v[1]), rounded(v[2])}); }

json idsJson(const Assembly& assembly, const std::vector<int>& parts) {
  json ids = json::array();
  for (int part : parts) ids.push_back(assembly.parts[part].id);
  return ids;
}

json directionLabels(const std::vector<Vec3>& directions) {
  json labels = json::array();
  for (const Vec3& d : directions) labels.push_back(directionLabel(d));
  return labels;
}

json witnessJson(const Assembly& assembly, const InterlockingResult& result) {
  if (!result.hasWitness) return nullptr;
  json velocities = json::array();
  for (const Vec3& v : result.witness.velocities) velocities.push_back(roundedVectorJson(v));
  return {{"parts", idsJson(assembly, result.witness.parts)},
          {"direction", result.witness.direction.empty() ? json(nullptr) : json(result.witness.direction)},
          {"velocities", velocities}};
}

json verdictJson(const Assembly& assembly, const InterlockingResult& result) {
  return {{"verdict", verdictName(result.verdict)},
          {"interlocking", result.verdict == Verdict::Interlocking},
          {"deadlocked", result.verdict == Verdict::Deadlocked},
          {"reason", result.reason},
          {"key", result.key >= 0 ? json(assembly.parts[result.key].id) : json(nullptr)},
          {"keyDirections", directionLabels(result.keyDirections)},
          {"witness", witnessJson(assembly, result)}};
}

json graphsJson(const Assembly& assembly, const std::vector<DirectionalBlockingGraph>& graphs) {
  json list = json::array();
  for (const DirectionalBlockingGraph& dbg : graphs) {
    json edges = json::array();
    for (int from = 0; from < dbg.graph.nodeCount(); ++from) {
      for (int to : dbg.graph.successors(from)) edges.push_back({assembly.parts[from].id, assembly.parts[to].id});
    }
    json components = json::array();
    for (const auto& component : findStronglyConnectedComponents(dbg.graph).components) {
      components.push_back(idsJson(assembly, component));
    }
    list.push_back({{"direction", dbg.direction.label()}, {"vector", roundedVectorJson(dbg.direction.vector)},
                    {"edges", edges}, {"components", components}});
  }
  return list;
}

json stepsJson(const Assembly& assembly, const std::vector<GroupMove>& moves) {
  json steps = json::array();
  for (const GroupMove& move : moves) {
    const double length = move.out ? 1.0 : move.steps;
    steps.push_back({{"parts", idsJson(assembly, move.parts)},
                     {"move", json::array({static_cast<int>(move.direction[0] * length), static_cast<int>(move.direction[1] * length),
                                           static_cast<int>(move.direction[2] * length)})},
                     {"out", move.out}});
  }
  return steps;
}

// Voxel plans carry their moves and level; plans from contacts alone do not.
void addMovesJson(const Assembly& assembly, const DisassemblyPlan& plan, json* object) {
  if (plan.level.empty() && plan.moves.empty()) return;
  (*object)["level"] = plan.level;
  (*object)["levelMinimal"] = plan.levelMinimal;
  (*object)["moves"] = plan.moves.size();
  (*object)["steps"] = stepsJson(assembly, plan.moves);
}

json disassemblyJson(const Assembly& assembly, const DisassemblyPlan& plan) {
  if (!plan.complete) return nullptr;
  json order = json::array(), paths = json::array();
  for (const Removal& removal : plan.removals) {
    order.push_back(assembly.parts[removal.part].id);
    json path = json::array();
    for (const Move& move : removal.path) {
      path.push_back({{"dir", directionLabel(move.direction)}, {"steps", move.steps}});
      if (move.length > 0) path.back()["length"] = move.length;  // a mesh plan's finite move, mm
    }
    paths.push_back(path);
  }
  json result = {{"order", order}, {"paths", plan.singlePartPaths ? paths : json(nullptr)}};
  addMovesJson(assembly, plan, &result);
  if (!plan.limit.empty()) result["limit"] = plan.limit;
  return result;
}

json disassemblyFailureJson(const Assembly& assembly, const DisassemblyPlan& plan) {
  std::vector<int> removed;
  for (const Removal& r : plan.removals) removed.push_back(r.part);
  json failure = {{"removed", idsJson(assembly, removed)},
                  {"stuck", idsJson(assembly, plan.stuck)},
                  {"searchLimitReached", plan.searchLimitReached}};
  if (!plan.unseparated.empty()) {
    json groups = json::array();
    for (const auto& together : plan.unseparated) groups.push_back(idsJson(assembly, together));
    failure["unseparated"] = groups;
    failure["level"] = plan.level;
    failure["steps"] = stepsJson(assembly, plan.moves);
  }
  if (!plan.limit.empty()) failure["limit"] = plan.limit;
  return failure;
}

std::string lengthText(double mm) {
  std::ostringstream out;
  out << mm;
  return out.str();
}

std::string pathText(const std::vector<Move>& path) {
  std::string text;
  for (const Move& move : path) {
    if (!text.empty()) text += ", ";
    text += directionLabel(move.direction) + " " +
            (move.length > 0 ? lengthText(move.length) + " mm" : std::to_string(move.steps));
  }
  return text;
}

std::string idsText(const Assembly& assembly, const std::vector<int>& parts, const char* separator) {
  std::string text;
  for (int part : parts) text += (text.empty() ? "" : separator) + std::to_string(assembly.parts[part].id);
  return text;
}

std::string levelText(const std::vector<int>& level) {
  std::string text;
  for (int moves : level) text += (text.empty() ? "" : ".") + std::to_string(moves);
  return text;
}

// "move 3: parts 2, 4  +x 1", or "+x out" for a separation.
void writeMoves(const Assembly& assembly, const std::vector<GroupMove>& moves, std::ostringstream& out) {
  for (size_t m = 0; m < moves.size(); ++m) {
    const GroupMove& move = moves[m];
    out << "\n  move " << m + 1 << ": part" << (move.parts.size() > 1 ? "s " : " ") << idsText(assembly, move.parts, ", ")
        << "  " << directionLabel(move.direction) << ' '
        << (move.out ? std::string("out") : move.length > 0 ? lengthText(move.length) + " mm" : std::to_string(move.steps));
  }
}

void writeDisassembly(const Assembly& assembly, const DisassemblyPlan& plan, std::ostringstream& out) {
  if (plan.complete) {
    out << "disassembly:";
    if (!plan.level.empty()) {
      out << " level " << levelText(plan.level) << ", " << plan.moves.size() << " move" << (plan.moves.size() == 1 ? "" : "s");
      if (!plan.levelMinimal) out << " (not proven the fewest: " << plan.limit << ")";
    }
  } else {
    out << (plan.searchLimitReached ? "disassembly: not proven; " : "disassembly: none found; ")
        << (plan.singlePartPaths ? (plan.searchLimitReached ? "removed before stopping:" : "removed before getting stuck:")
                                 : (plan.searchLimitReached ? "moves before stopping:" : "moves before getting stuck:"));
  }
  if (plan.singlePartPaths) {
    for (const Removal& removal : plan.removals) {
      out << "\n  part " << assembly.parts[removal.part].id;
      if (!removal.path.empty()) out << ": " << pathText(removal.path);
    }
  }
  if (!plan.movesFollowRemovals) {
    if (plan.singlePartPaths) out << "\n  the fewest moves, parts moved together:";
    writeMoves(assembly, plan.moves, out);
  }
  if (!plan.complete) {
    if (plan.unseparated.empty()) {
      out << (plan.searchLimitReached ? "\n  not removed:" : "\n  stuck:");
      for (int part : plan.stuck) out << ' ' << assembly.parts[part].id;
    } else {
      for (const auto& together : plan.unseparated) {
        out << (plan.searchLimitReached ? "\n  not separated: " : "\n  stuck together: ") << idsText(assembly, together, " ");
      }
    }
    if (plan.searchLimitReached) {
      out << "\n  (the search stopped short" << (plan.limit.empty() ? "" : ": " + plan.limit)
          << "; these parts are not proven stuck)";
    }
  }
  out << "\n";
}

}  // namespace

std::string checkReportToJson(const AssemblyDocument& document, const CheckReport& report, int indent) {
  const Assembly& assembly = document.assembly;
  json root = verdictJson(assembly, report.result);
  root["parts"] = assembly.partCount();
  json ids = json::array();
  for (const Part& part : assembly.parts) ids.push_back(part.id);
  root["partIds"] = ids;
  root["kind"] = assemblyKindName(document.kind);
  root["method"] = checkMethodName(report.method);
  json bases = json::array();
  for (const DirectionalBlockingGraph& dbg : report.graphs) {
    bases.push_back({{"label", dbg.direction.label()}, {"vector", roundedVectorJson(dbg.direction.vector)}});
  }
  root["baseDirections"] = bases;
  root["baseDirectionCount"] = report.baseDirectionCount;
  root["graphs"] = graphsJson(assembly, report.graphs);
  // Over kReportedGraphLimit directions the lists stay empty (`desia check --graphs` keeps them).
  root["graphsOmitted"] = report.graphs.size() < report.baseDirectionCount;
  if ((document.kind == AssemblyKind::Plate && !document.plates.empty()) ||
      (document.kind == AssemblyKind::Frame && document.frame)) {
    root["cutPoints"] = idsJson(assembly, document.plateCutPoints);
  }
  if (report.method == CheckMethod::Both) {
    root["methods"] = {{"dbg", verdictJson(assembly, *report.graphResult)},
                       {"lp", verdictJson(assembly, *report.inequalityResult)}};
  }
  if (report.disassembly) {
    root["disassembly"] = disassemblyJson(assembly, *report.disassembly);
    if (!report.disassembly->complete) root["disassemblyFailure"] = disassemblyFailureJson(assembly, *report.disassembly);
  } else {
    root["disassembly"] = nullptr;
  }
  if (report.shapeRemoval) {
    root["shapeRemoval"] = {{"checked", report.shapeRemoval->checked},
                            {"clear", report.shapeRemoval->failure.empty()},
                            {"failure", report.shapeRemoval->failure}};
  }
  return root.dump(indent);
}

std::string checkReportToText(const AssemblyDocument& document, const CheckReport& report) {
  const Assembly& assembly = document.assembly;
  const InterlockingResult& result = report.result;
  std::ostringstream out;
  out << "parts: " << assembly.partCount() << " (" << assemblyKindName(document.kind);
  if (document.kind == AssemblyKind::Voxel) {
    out << " grid " << document.voxels.nx() << "x" << document.voxels.ny() << "x" << document.voxels.nz();
  }
  out << ")\nverdict: " << verdictName(result.verdict) << " (method " << checkMethodName(report.method) << ")\n";
  out << "reason: " << result.reason << "\n";
  if (result.key >= 0) {
    out << "key: part " << assembly.parts[result.key].id << ", free along";
    for (const Vec3& d : result.keyDirections) out << ' ' << directionLabel(d);
    out << "\n";
  }
  if (result.hasWitness) {
    out << "witness: part" << (result.witness.parts.size() > 1 ? "s" : "");
    for (int part : result.witness.parts) out << ' ' << assembly.parts[part].id;
    out << " move " << (result.witness.direction.empty() ? "in different directions" : "along " + result.witness.direction) << "\n";
  }
  if (!document.plateCutPoints.empty()) {
    out << "cut points of the parts-graph: " << (document.kind == AssemblyKind::Frame ? "beam" : "plate")
        << (document.plateCutPoints.size() > 1 ? "s" : "");
    for (int part : document.plateCutPoints) out << ' ' << assembly.parts[part].id;
    out << " (no joints can make this structure interlocking: add a part that bypasses "
        << (document.plateCutPoints.size() > 1 ? "them" : "it") << ", paper Section 5.2)\n";
  }
  out << "base directions:";
  if (report.graphs.size() < report.baseDirectionCount) {
    out << ' ' << report.baseDirectionCount << " (not listed; --graphs lists them)";
  } else {
    for (const DirectionalBlockingGraph& dbg : report.graphs) out << ' ' << dbg.direction.label();
  }
  out << "\n";
  if (report.disassembly) writeDisassembly(assembly, *report.disassembly, out);
  if (report.shapeRemoval) {
    out << "removal on the shapes: "
        << (report.shapeRemoval->failure.empty() ? "clear" : "FAILS: " + report.shapeRemoval->failure) << " ("
        << report.shapeRemoval->checked << ")\n";
  }
  return out.str();
}

}  // namespace desia
