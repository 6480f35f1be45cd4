// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/analysis.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <map>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

// Snaps components that are numerically zero or one, so that axis directions get exact values
// and the same labels natively and in WebAssembly.
Vec3 cleaned(Vec3 v) {
  for (double& c : v) {
    if (std::abs(c) < tolerance::kComponentNoise) c = 0.0;
    if (std::abs(std::abs(c) - 1.0) < tolerance::kComponentNoise) c = c > 0 ? 1.0 : -1.0;
  }
  return v;
}

// Unit vectors on one point of a 2^-30 grid (about tolerance::kDirection) stand for one
// direction: far below any angle a geometry means, far above the rounding of the cross products
// that produce them.
using DirectionKey = std::array<int64_t, 3>;
DirectionKey keyOf(const Vec3& unit) {
  constexpr double kGrid = 1073741824.0;  // 2^30
  return {std::llround(unit[0] * kGrid), std::llround(unit[1] * kGrid), std::llround(unit[2] * kGrid)};
}

// One representative per key (the first in input order), in descending key order, which is the
// descending order of the vectors themselves. Few distinct directions (voxel assemblies: three
// lines among thousands of contacts) are found by a scan of those seen so far; past a few dozen,
// sorting keeps this O(L log L) where the scan would be O(L^2) (O(L^4) for the O(L^2) crossings
// of L normals).
std::vector<Vec3> uniqueDirections(const std::vector<Vec3>& directions) {
  constexpr size_t kScanLimit = 32;
  std::vector<std::pair<DirectionKey, size_t>> seen;
  bool scanned = true;
  for (size_t i = 0; i < directions.size() && scanned; ++i) {
    const DirectionKey key = keyOf(directions[i]);
    bool known = false;
    for (const auto& entry : seen) known = known || entry.first == key;
    if (known) continue;
    if (seen.size() == kScanLimit) {
      scanned = false;
    } else {
      seen.push_back({key, i});
    }
  }
  if (!scanned) {
    seen.clear();
    seen.reserve(directions.size());
    for (size_t i = 0; i < directions.size(); ++i) seen.push_back({keyOf(directions[i]), i});
    std::sort(seen.begin(), seen.end());
    // Within a run of equal keys the lowest index comes first: keep that one.
    seen.erase(std::unique(seen.begin(), seen.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), seen.end());
  }
  std::sort(seen.begin(), seen.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Vec3> unique;
  unique.reserve(seen.size());
  for (const auto& entry : seen) unique.push_back(directions[entry.second]);
  return unique;
}

// One representative per line through the origin spanned by the contact normals.
std::vector<Vec3> distinctNormalLines(const Assembly& assembly) {
  std::vector<Vec3> lines;
  lines.reserve(assembly.contacts.size());
  for (const Contact& contact : assembly.contacts) {
    Vec3 n = normalized(contact.normal);
    if (norm(n) == 0) continue;
    lines.push_back(cleaned(canonicalSign(n)));
  }
  return uniqueDirections(lines);
}

// Any unit vector orthogonal to n.
Vec3 anyPerpendicular(const Vec3& n) {
  Vec3 axis = std::abs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalized(cross(n, axis));
}

bool isAxis(const Vec3& v) {
  int ones = 0;
  for (double c : v) ones += (c == 1.0 || c == -1.0) ? 1 : 0;
  return ones == 1;
}

// Axes first in x, y, z order; then the rest in the descending order uniqueDirections left them.
void sortForReports(std::vector<Vec3>* directions) {
  auto firstOther = std::stable_partition(directions->begin(), directions->end(), isAxis);
  std::sort(directions->begin(), firstOther, [](const Vec3& a, const Vec3& b) {
    return std::abs(a[0]) > std::abs(b[0]) || (std::abs(a[0]) == std::abs(b[0]) && std::abs(a[1]) > std::abs(b[1]));
  });
}

}  // namespace

// A label is for people: components that print as 0 at the label's 4 digits are 0, so a
// direction computed 3e-9 off an axis reads "+x", not "(1,-2.766e-09,4.475e-09)".
std::string directionLabel(const Vec3& direction) {
  static const char* kAxisNames = "xyz";
  Vec3 shown = direction;
  for (double& c : shown) {
    if (std::abs(c) < tolerance::kLabelZero) c = 0.0;
  }
  for (int axis = 0; axis < 3; ++axis) {
    bool others = true;
    for (int k = 0; k < 3; ++k) {
      if (k != axis && shown[k] != 0.0) others = false;
    }
    if (others && std::abs(std::abs(shown[axis]) - 1.0) < tolerance::kLabelZero) {
      return std::string(shown[axis] > 0 ? "+" : "-") + kAxisNames[axis];
    }
  }
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g,%.4g,%.4g)", shown[0] + 0.0, shown[1] + 0.0, shown[2] + 0.0);
  return buffer;
}

std::vector<BaseDirection> computeBaseDirections(const Assembly& assembly) {
  const std::vector<Vec3> lines = distinctNormalLines(assembly);
  std::vector<Vec3> directions;
  directions.reserve(lines.size() * (lines.size() - (lines.empty() ? 0 : 1)) / 2 + 3);
  // Vertices of the arrangement: intersections of the great circles of two distinct normals.
  for (size_t i = 0; i < lines.size(); ++i) {
    for (size_t j = i + 1; j < lines.size(); ++j) {
      Vec3 d = cross(lines[i], lines[j]);
      if (norm(d) < tolerance::kDirection) continue;
      directions.push_back(cleaned(canonicalSign(normalized(d))));
    }
  }
  // Axis-aligned (voxel) assemblies always get the three axes (Section 3.1: "the base directions
  // are the three axes"), even when some axis has no contact. An extra direction never changes a
  // verdict: its DBG is a real one, and it keeps the graphs of voxel puzzles comparable.
  if (hasOnlyAxisAlignedContacts(assembly)) {
    for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) directions.push_back(axis);
  }
  directions = uniqueDirections(directions);
  if (directions.empty()) {
    // No vertex: all normals parallel (a single great circle, every direction on it is free for
    // the same groups) or no contacts at all (every direction is free). Either way the
    // directions below expose the free motions.
    if (lines.empty()) {
      directions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    } else {
      directions.push_back(cleaned(canonicalSign(anyPerpendicular(lines[0]))));
    }
  }
  sortForReports(&directions);
  std::vector<BaseDirection> result;
  result.reserve(directions.size());
  for (const Vec3& d : directions) result.push_back({d});
  return result;
}

DirectionalBlockingGraph buildBlockingGraph(const Assembly& assembly, const BaseDirection& direction) {
  return BlockingGraphBuilder(assembly, 1).build(direction);
}

BlockingGraphBuilder::BlockingGraphBuilder(const Assembly& assembly, size_t directionCount)
    : assembly_(assembly), grouped_(directionCount > 16) {
  if (!grouped_) return;
  std::map<std::pair<int, int>, size_t> pairIndex;
  for (const Contact& contact : assembly.contacts) {
    const bool flip = contact.a > contact.b;
    const std::pair<int, int> key = flip ? std::make_pair(contact.b, contact.a) : std::make_pair(contact.a, contact.b);
    auto [it, added] = pairIndex.emplace(key, pairs_.size());
    if (added) pairs_.push_back({key.first, key.second, {}});
    std::vector<Vec3>& normals = pairs_[it->second].normals;
    const Vec3 n = flip ? negated(contact.normal) : contact.normal;
    if (std::find(normals.begin(), normals.end(), n) == normals.end()) normals.push_back(n);
  }
}

DirectionalBlockingGraph BlockingGraphBuilder::build(const BaseDirection& direction) const {
  DirectionalBlockingGraph dbg{direction, DirectedGraph(assembly_.partCount())};
  buildInto(direction, &dbg);
  return dbg;
}

void BlockingGraphBuilder::buildInto(const BaseDirection& direction, DirectionalBlockingGraph* graph) const {
  DirectionalBlockingGraph& dbg = *graph;
  dbg.direction = direction;
  dbg.graph.clearEdges();
  if (!grouped_) {
    // Moving a along d pushes into b when d·n_ab > 0; moving b along d pushes into a when
    // d·n_ba = -d·n_ab > 0.
    for (const Contact& contact : assembly_.contacts) {
      const double along = dot(direction.vector, contact.normal);
      if (along > tolerance::kDirection) dbg.graph.addEdge(contact.a, contact.b);
      if (along < -tolerance::kDirection) dbg.graph.addEdge(contact.b, contact.a);
    }
    return;
  }
  for (const PairContacts& pair : pairs_) {
    bool forward = false, backward = false;  // a blocked by b along d; b blocked by a along d
    for (const Vec3& n : pair.normals) {
      const double along = dot(direction.vector, n);
      forward = forward || along > tolerance::kDirection;
      backward = backward || along < -tolerance::kDirection;
      if (forward && backward) break;
    }
    if (forward) dbg.graph.addEdge(pair.a, pair.b);
    if (backward) dbg.graph.addEdge(pair.b, pair.a);
  }
}

std::vector<DirectionalBlockingGraph> buildBaseBlockingGraphs(const Assembly& assembly) {
  const std::vector<BaseDirection> directions = computeBaseDirections(assembly);
  const BlockingGraphBuilder builder(assembly, directions.size());
  std::vector<DirectionalBlockingGraph> graphs;
  for (const BaseDirection& direction : directions) graphs.push_back(builder.build(direction));
  return graphs;
}

}  // namespace desia
