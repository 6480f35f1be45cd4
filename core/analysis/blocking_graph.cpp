// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/blocking_graph.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>

#include "analysis/vec3.h"

namespace desia {
namespace {

// Snaps components that are numerically zero or one, so that axis directions get exact values
// and the same labels natively and in WebAssembly.
Vec3 cleaned(Vec3 v) {
  for (double& c : v) {
    if (std::abs(c) < 1e-12) c = 0.0;
    if (std::abs(std::abs(c) - 1.0) < 1e-12) c = c > 0 ? 1.0 : -1.0;
  }
  return v;
}

// Unit vectors closer than about 1e-9 per component stand for one direction: far below any
// angle a geometry means, far above the rounding of the cross products that produce them.
using DirectionKey = std::array<int64_t, 3>;
DirectionKey keyOf(const Vec3& unit) {
  constexpr double kGrid = 1073741824.0;  // 2^30
  return {std::llround(unit[0] * kGrid), std::llround(unit[1] * kGrid), std::llround(unit[2] * kGrid)};
}

// One representative per key, the first in input order; sorting keeps this O(L log L) where a
// pairwise comparison was O(L^2) (L^4 for the O(L^2) crossings of L normals, issue 14).
std::vector<Vec3> uniqueDirections(const std::vector<Vec3>& directions) {
  std::vector<std::pair<DirectionKey, size_t>> keyed;
  keyed.reserve(directions.size());
  for (size_t i = 0; i < directions.size(); ++i) keyed.push_back({keyOf(directions[i]), i});
  std::sort(keyed.begin(), keyed.end());
  std::vector<size_t> kept;
  for (size_t i = 0; i < keyed.size(); ++i) {
    if (i == 0 || keyed[i].first != keyed[i - 1].first) kept.push_back(keyed[i].second);
  }
  std::sort(kept.begin(), kept.end());
  std::vector<Vec3> unique;
  unique.reserve(kept.size());
  for (size_t i : kept) unique.push_back(directions[i]);
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

bool lessLexicographic(const Vec3& a, const Vec3& b) {
  // Axes first in x, y, z order; then the rest by components, for a stable order.
  auto isAxis = [](const Vec3& v) {
    int ones = 0;
    for (double c : v) ones += (c == 1.0 || c == -1.0) ? 1 : 0;
    return ones == 1;
  };
  if (isAxis(a) != isAxis(b)) return isAxis(a);
  if (isAxis(a)) return std::abs(a[0]) > std::abs(b[0]) || (std::abs(a[0]) == std::abs(b[0]) && std::abs(a[1]) > std::abs(b[1]));
  return a > b;
}

}  // namespace

std::string directionLabel(const Vec3& direction) {
  static const char* kAxisNames = "xyz";
  for (int axis = 0; axis < 3; ++axis) {
    bool others = true;
    for (int k = 0; k < 3; ++k) {
      if (k != axis && std::abs(direction[k]) > 1e-9) others = false;
    }
    if (others && std::abs(std::abs(direction[axis]) - 1.0) < 1e-9) {
      return std::string(direction[axis] > 0 ? "+" : "-") + kAxisNames[axis];
    }
  }
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g,%.4g,%.4g)", direction[0] + 0.0, direction[1] + 0.0,
                direction[2] + 0.0);
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
      if (norm(d) < 1e-9) continue;
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
  std::sort(directions.begin(), directions.end(), lessLexicographic);
  std::vector<BaseDirection> result;
  result.reserve(directions.size());
  for (const Vec3& d : directions) result.push_back({d, directionLabel(d)});
  return result;
}

DirectionalBlockingGraph buildBlockingGraph(const Assembly& assembly, const BaseDirection& direction) {
  DirectionalBlockingGraph dbg{direction, DirectedGraph(assembly.partCount())};
  for (const Contact& contact : assembly.contacts) {
    double along = dot(direction.vector, contact.normal);
    // Moving a along d pushes into b when d·n_ab > 0; moving b along d pushes into a when
    // d·n_ba = -d·n_ab > 0.
    if (along > kDirectionTolerance) dbg.graph.addEdge(contact.a, contact.b);
    if (along < -kDirectionTolerance) dbg.graph.addEdge(contact.b, contact.a);
  }
  return dbg;
}

std::vector<DirectionalBlockingGraph> buildBaseBlockingGraphs(const Assembly& assembly) {
  std::vector<DirectionalBlockingGraph> graphs;
  for (const BaseDirection& direction : computeBaseDirections(assembly)) {
    graphs.push_back(buildBlockingGraph(assembly, direction));
  }
  return graphs;
}

}  // namespace desia
