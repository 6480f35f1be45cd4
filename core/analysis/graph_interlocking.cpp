// SPDX-License-Identifier: GPL-3.0-or-later
// DBG-based interlocking test (paper Section 3.2).
#include <algorithm>
#include <optional>
#include <sstream>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/analysis.h"

namespace desia {
namespace {

// A component with no outgoing edge in G(d) can translate along d; one with no incoming edge can
// translate along -d (paper Section 3.1).
struct FreeGroup {
  int component = -1;
  bool alongPositive = true;
};

// The free components of one DBG, sinks (along +d) before sources (along -d), each list in
// component order.
std::vector<FreeGroup> freeGroups(const StronglyConnectedComponents& scc, const CondensationDegrees& degrees) {
  std::vector<FreeGroup> groups;
  for (int c = 0; c < scc.count(); ++c) {
    if (!degrees.hasOutEdge[c]) groups.push_back({c, true});
  }
  for (int c = 0; c < scc.count(); ++c) {
    if (!degrees.hasInEdge[c]) groups.push_back({c, false});
  }
  return groups;
}

Witness witnessOf(const std::vector<int>& parts, const Vec3& direction) {
  Witness witness;
  witness.parts = parts;
  witness.velocities.assign(parts.size(), direction);
  witness.direction = directionLabel(direction);
  return witness;
}

std::string partList(const Assembly& assembly, const std::vector<int>& parts) {
  std::ostringstream out;
  for (size_t i = 0; i < parts.size(); ++i) out << (i ? ", " : "") << assembly.parts[parts[i]].id;
  return out.str();
}

InterlockingResult notInterlocking(const Assembly& assembly, const std::vector<int>& parts,
                                   const Vec3& direction, const std::string& why) {
  InterlockingResult result;
  result.verdict = Verdict::NotInterlocking;
  result.hasWitness = true;
  result.witness = witnessOf(parts, direction);
  std::ostringstream reason;
  reason << why << ": part" << (parts.size() > 1 ? "s " : " ") << partList(assembly, parts)
         << " can move along " << result.witness.direction;
  result.reason = reason.str();
  return result;
}

}  // namespace

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Interlocking: return "interlocking";
    case Verdict::Deadlocked: return "deadlocked";
    case Verdict::NotInterlocking: return "not-interlocking";
  }
  return "not-interlocking";
}

namespace {

// The test over `count` base DBGs, `graphAt(i)` giving the i-th (built on demand by the caller
// when there are many, so they need not all be held at once).
template <typename GraphAt>
InterlockingResult testGraphs(const Assembly& assembly, size_t count, GraphAt&& graphAt) {
  const int n = assembly.partCount();
  if (n < 3) {
    InterlockingResult result;
    result.reason = "an interlocking assembly needs at least three parts; this one has " + std::to_string(n);
    return result;
  }
  int key = -1;
  std::vector<Vec3> keyDirections;
  for (size_t index = 0; index < count; ++index) {
    const auto& dbg = graphAt(index);
    // Nearly every graph of a passing test is strongly connected (the ICOSAHEDRON's joint plans:
    // ~2,300 base directions per test, the key free along a few): decided on bit masks first.
    if (isStronglyConnectedSmall(dbg.graph) == std::optional<bool>(true)) continue;  // as scc.count() == 1
    const StronglyConnectedComponents scc = findStronglyConnectedComponents(dbg.graph);
    if (scc.count() == 1) continue;  // strongly connected: nothing moves along ±d
    const CondensationDegrees degrees = condensationDegrees(dbg.graph, scc);
    const std::vector<FreeGroup> groups = freeGroups(scc, degrees);
    const Vec3& d = dbg.direction.vector;
    auto directionOf = [&](const FreeGroup& g) { return g.alongPositive ? d : negated(d); };
    if (scc.count() > 2) {
      // Some free component other than a lone key must exist; report the smallest free group.
      const FreeGroup* best = nullptr;
      for (const FreeGroup& g : groups) {
        const auto& members = scc.components[g.component];
        if (members.size() == 1 && (key < 0 || members[0] == key)) continue;
        if (!best || members.size() < scc.components[best->component].size()) best = &g;
      }
      if (!best) best = &groups.front();
      return notInterlocking(assembly, scc.components[best->component], directionOf(*best),
                             "the blocking graph along " + dbg.direction.label() + " has " +
                                 std::to_string(scc.count()) + " strongly connected components");
    }
    // Exactly two components: one of them must be a single part, the same in every DBG.
    const auto& first = scc.components[0];
    const auto& second = scc.components[1];
    int single = first.size() == 1 ? first[0] : (second.size() == 1 ? second[0] : -1);
    if (single < 0 || (key >= 0 && single != key)) {
      const FreeGroup* pick = &groups.front();
      for (const FreeGroup& g : groups) {
        const auto& members = scc.components[g.component];
        if (!(members.size() == 1 && members[0] == key)) { pick = &g; break; }
      }
      std::string why = single < 0 ? "no single part separates in the blocking graph along " + dbg.direction.label()
                                   : "two different parts (" + std::to_string(assembly.parts[key].id) + " and " +
                                         std::to_string(assembly.parts[single].id) + ") can move";
      return notInterlocking(assembly, scc.components[pick->component], directionOf(*pick), why);
    }
    key = single;
    const int keyComponent = scc.componentOf[key];
    if (!degrees.hasOutEdge[keyComponent]) keyDirections.push_back(d);
    if (!degrees.hasInEdge[keyComponent]) keyDirections.push_back(negated(d));
  }
  if (key < 0) return deadlockedResult("every base blocking graph is strongly connected: no part or part group can move");
  return interlockingResult(assembly, key, keyDirections);
}

}  // namespace

InterlockingResult testInterlockingByGraphs(const Assembly& assembly,
                                            const std::vector<DirectionalBlockingGraph>& graphs) {
  return testGraphs(assembly, graphs.size(), [&](size_t i) -> const DirectionalBlockingGraph& { return graphs[i]; });
}

InterlockingResult testInterlockingByGraphs(const Assembly& assembly, const std::vector<BaseDirection>& directions) {
  const BlockingGraphBuilder builder(assembly, directions.size());
  DirectionalBlockingGraph current;
  current.graph = DirectedGraph(assembly.partCount());
  return testGraphs(assembly, directions.size(), [&](size_t i) -> const DirectionalBlockingGraph& {
    builder.buildInto(directions[i], &current);
    return current;
  });
}

}  // namespace desia
