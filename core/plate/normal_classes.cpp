// SPDX-License-Identifier: GPL-3.0-or-later
// Contact normals snapped to the design's directions (normal_classes.h).
#include "plate/normal_classes.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

namespace {

// The distance between two unit vectors up to sign.
double apartUpToSign(const Vec3& a, const Vec3& b) { return std::min(norm(minus(a, b)), norm(plus(a, b))); }

// Union-find without recursion (the groups of parallel normals).
int rootOf(std::vector<int>* parent, int k) {
  while ((*parent)[k] != k) {
    (*parent)[k] = (*parent)[(*parent)[k]];
    k = (*parent)[k];
  }
  return k;
}

// Groups of parallel normals, up to sign: each normal's group root (single linkage within the
// angle; sorted by |x| first so that only neighbours in |x| are compared).
std::vector<int> parallelGroups(const std::vector<Vec3>& normals, double angle) {
  const size_t n = normals.size();
  std::vector<int> byX(n);
  std::iota(byX.begin(), byX.end(), 0);
  std::sort(byX.begin(), byX.end(), [&](int i, int j) { return std::abs(normals[i][0]) < std::abs(normals[j][0]); });
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < n; ++i) {
    const Vec3& u = normals[byX[i]];
    for (size_t j = i + 1; j < n && std::abs(normals[byX[j]][0]) - std::abs(u[0]) <= angle; ++j) {
      if (apartUpToSign(u, normals[byX[j]]) > angle) continue;
      const int a = rootOf(&parent, byX[i]), b = rootOf(&parent, byX[j]);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<int> group(n);
  for (size_t k = 0; k < n; ++k) group[k] = rootOf(&parent, static_cast<int>(k));
  return group;
}

// One direction per group: the mean of its members turned to one side (that of the greatest
// member, lexicographically, of either sign), summed in sorted order: the same bits whatever the
// order of the input.
std::vector<Vec3> groupDirections(const std::vector<Vec3>& normals, const std::vector<int>& group,
                                  std::vector<int>* groupIndex) {
  groupIndex->assign(group.size(), -1);
  std::vector<std::vector<Vec3>> members;
  for (size_t k = 0; k < group.size(); ++k) {
    if (group[k] != static_cast<int>(k)) continue;
    (*groupIndex)[k] = static_cast<int>(members.size());
    members.emplace_back();
  }
  for (size_t k = 0; k < group.size(); ++k) {
    (*groupIndex)[k] = (*groupIndex)[group[k]];
    members[(*groupIndex)[k]].push_back(normals[k]);
  }
  std::vector<Vec3> directions;
  for (std::vector<Vec3>& vectors : members) {
    Vec3 reference = vectors.front();
    for (const Vec3& v : vectors) reference = std::max({reference, v, negated(v)});
    for (Vec3& v : vectors) v = dot(v, reference) < 0 ? negated(v) : v;
    std::sort(vectors.begin(), vectors.end());
    Vec3 sum{0, 0, 0};
    for (const Vec3& v : vectors) sum = plus(sum, v);
    directions.push_back(normalized(sum));
  }
  return directions;
}

// Pairs of directions within the angle of square made square: each pair turned towards square in
// their common plane, all pairs at once, then renormalised, until every such pair is square to
// tolerance::kSquaredCosine (a gradient step on the sum of the squared cosines). Each direction's turn is the mean of
// its pairs' half-turns: summed instead, a direction square to several nearly parallel others
// overshoots, and the rounds grow instead of settling (seen on milled joints: 13 groups, 16 pairs).
void squareNearlySquarePairs(std::vector<Vec3>* directions, double angle) {
  std::vector<std::pair<size_t, size_t>> pairs;
  std::vector<int> pairCount(directions->size(), 0);
  for (size_t i = 0; i < directions->size(); ++i) {
    for (size_t j = i + 1; j < directions->size(); ++j) {
      if (std::abs(dot((*directions)[i], (*directions)[j])) < angle) {
        pairs.push_back({i, j});
        ++pairCount[i], ++pairCount[j];
      }
    }
  }
  for (int round = 0; round < 200 && !pairs.empty(); ++round) {
    std::vector<Vec3> correction(directions->size(), Vec3{0, 0, 0});
    double worst = 0;
    for (const auto& [i, j] : pairs) {
      const double c = dot((*directions)[i], (*directions)[j]);
      worst = std::max(worst, std::abs(c));
      correction[i] = minus(correction[i], scaled((*directions)[j], c / (2 * pairCount[i])));
      correction[j] = minus(correction[j], scaled((*directions)[i], c / (2 * pairCount[j])));
    }
    if (worst < tolerance::kSquaredCosine) break;
    for (size_t k = 0; k < directions->size(); ++k) (*directions)[k] = normalized(plus((*directions)[k], correction[k]));
  }
}

}  // namespace

std::vector<Vec3> snappedDirections(const std::vector<Vec3>& normals, double angle) {
  std::vector<int> groupIndex;
  std::vector<Vec3> directions = groupDirections(normals, parallelGroups(normals, angle), &groupIndex);
  // The groups in the order of their directions, not of the input (the squaring sums in it).
  std::vector<int> byDirection(directions.size());
  std::iota(byDirection.begin(), byDirection.end(), 0);
  std::sort(byDirection.begin(), byDirection.end(), [&](int i, int j) { return directions[i] < directions[j]; });
  std::vector<int> rank(directions.size());
  for (size_t r = 0; r < byDirection.size(); ++r) rank[byDirection[r]] = static_cast<int>(r);
  std::vector<Vec3> sorted;
  for (int g : byDirection) sorted.push_back(directions[g]);
  directions = sorted;
  for (int& g : groupIndex) g = rank[g];
  squareNearlySquarePairs(&directions, angle);
  std::vector<Vec3> snapped;
  for (size_t k = 0; k < normals.size(); ++k) {
    const Vec3& d = directions[groupIndex[k]];
    snapped.push_back(dot(d, normals[k]) < 0 ? negated(d) : d);
  }
  return snapped;
}

void snapContactNormals(std::vector<PlateContact>* contacts) {
  std::vector<Vec3> normals;
  for (const PlateContact& contact : *contacts) {
    if (!contact.crossing) normals.push_back(contact.normal);
  }
  const std::vector<Vec3> snapped = snappedDirections(normals, tolerance::kComputedDirectionRad);
  size_t next = 0;
  for (PlateContact& contact : *contacts) {
    if (!contact.crossing) contact.normal = snapped[next++];
  }
}

}  // namespace desia
