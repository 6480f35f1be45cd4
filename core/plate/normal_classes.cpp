// SPDX-License-Identifier: GPL-3.0-or-later
// Contact normals snapped to the design's directions (normal_classes.h).
#include "plate/normal_classes.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/median_split_tree.h"

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

// A cell of the grid parallelGroups files unit vectors in (integer coordinates, side angle / 2).
struct Cell {
  int64_t x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash {
  size_t operator()(const Cell& c) const {
    uint64_t h = static_cast<uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<uint64_t>(c.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= static_cast<uint64_t>(c.z) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

Cell cellOf(const Vec3& v, double side) {
  return {static_cast<int64_t>(std::floor(v[0] / side)), static_cast<int64_t>(std::floor(v[1] / side)),
          static_cast<int64_t>(std::floor(v[2] / side))};
}

// Groups of parallel normals, up to sign: each normal's group root, the smallest index of its group
// (single linkage: linked when apartUpToSign <= angle). The normals, turned to one sign, are filed in
// a grid of cells of side angle / 2: two in one cell are less than angle apart (the cell's diagonal
// is 0.87 angle) and are linked at once; two within angle are at most 2 cells apart on each axis, so
// only the cells around each cell, and around its mirror image through the origin (the other sign),
// are compared, pair by pair until one pair links them. Linear in the normals for a design's
// normals (many equal, few directions) where comparing all pairs was quadratic (a long table of
// 9,998 plates: 60,000 normals, 20 s).
std::vector<int> parallelGroups(const std::vector<Vec3>& normals, double angle) {
  const size_t n = normals.size();
  const double side = angle / 2;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto link = [&](int a, int b) {
    a = rootOf(&parent, a), b = rootOf(&parent, b);
    parent[std::max(a, b)] = std::min(a, b);
  };
  std::unordered_map<Cell, size_t, CellHash> cellIndex;
  std::vector<Cell> cells;
  std::vector<std::vector<int>> members;  // per cell, in the order of first appearance
  for (size_t k = 0; k < n; ++k) {
    const Cell cell = cellOf(canonicalSign(normals[k]), side);
    const auto [at, added] = cellIndex.emplace(cell, cells.size());
    if (added) {
      cells.push_back(cell);
      members.emplace_back();
    } else {
      link(members[at->second].front(), static_cast<int>(k));
    }
    members[at->second].push_back(static_cast<int>(k));
  }
  auto compareCells = [&](size_t a, size_t b) {
    if (rootOf(&parent, members[a].front()) == rootOf(&parent, members[b].front())) return;
    for (int i : members[a]) {
      for (int j : members[b]) {
        if (apartUpToSign(normals[i], normals[j]) <= angle) return link(i, j);
      }
    }
  };
  // A cell's mirror image [-x - 1, -x] on each axis, widened by 2 cells: offsets -3 .. 2 from -x.
  for (size_t a = 0; a < cells.size(); ++a) {
    const Cell& c = cells[a];
    for (int64_t dx = -3; dx <= 2; ++dx) {
      for (int64_t dy = -3; dy <= 2; ++dy) {
        for (int64_t dz = -3; dz <= 2; ++dz) {
          const bool nearSameSign = dx >= -2 && dy >= -2 && dz >= -2;
          const Cell around[2] = {{c.x + dx, c.y + dy, c.z + dz}, {-c.x + dx, -c.y + dy, -c.z + dz}};
          for (int which = nearSameSign ? 0 : 1; which < 2; ++which) {
            const auto found = cellIndex.find(around[which]);
            if (found != cellIndex.end() && found->second > a) compareCells(a, found->second);
          }
        }
      }
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

// A k-d tree over unit vectors, asked for those nearly square to a direction (|p . d| < angle, a
// slab through the origin): a box whose projection on d lies wholly outside the slab is skipped.
// Built and searched with explicit stacks; leaves of at most 8 vectors.
class DirectionTree {
 public:
  explicit DirectionTree(const std::vector<Vec3>& points) : points_(points), order_(points.size()) {
    std::iota(order_.begin(), order_.end(), 0);
    nodes_ = buildMedianSplitTree(
        order_, [&](int i) { return std::array<Vec3, 2>{points_[i], points_[i]}; },
        [&](int i, int axis) { return points_[i][axis]; });
  }

  // The indices of the points with |p . d| < angle, in increasing order.
  std::vector<int> nearlySquareTo(const Vec3& d, double angle) const {
    std::vector<int> found;
    if (nodes_.empty()) return found;
    // Rounding of a dot product of unit vectors is far below this; only whole boxes are skipped.
    const double margin = angle + tolerance::kExactCosine;
    std::vector<size_t> pending{0};
    while (!pending.empty()) {
      const SplitTreeNode& node = nodes_[pending.back()];
      pending.pop_back();
      double low = 0, high = 0;
      for (int k = 0; k < 3; ++k) {
        low += std::min(d[k] * node.lo[k], d[k] * node.hi[k]);
        high += std::max(d[k] * node.lo[k], d[k] * node.hi[k]);
      }
      if (low > margin || high < -margin) continue;
      if (node.children[0] == 0) {
        for (size_t r = node.begin; r < node.end; ++r) {
          if (std::abs(dot(points_[order_[r]], d)) < angle) found.push_back(order_[r]);
        }
        continue;
      }
      pending.push_back(node.children[0]);
      pending.push_back(node.children[1]);
    }
    std::sort(found.begin(), found.end());
    return found;
  }

 private:
  const std::vector<Vec3>& points_;
  std::vector<int> order_;
  std::vector<SplitTreeNode> nodes_;
};

// Pairs of directions within the angle of square made square: each pair turned towards square in
// their common plane, all pairs at once, then renormalised, until every such pair is square to
// tolerance::kSquaredCosine (a gradient step on the sum of the squared cosines). Each direction's turn is the mean of
// its pairs' half-turns: summed instead, a direction square to several nearly parallel others
// overshoots, and the rounds grow instead of settling (seen on milled joints: 13 groups, 16 pairs).
void squareNearlySquarePairs(std::vector<Vec3>* directions, double angle) {
  std::vector<std::pair<size_t, size_t>> pairs;
  std::vector<int> pairCount(directions->size(), 0);
  const DirectionTree tree(*directions);
  for (size_t i = 0; i < directions->size(); ++i) {
    for (int j : tree.nearlySquareTo((*directions)[i], angle)) {
      if (static_cast<size_t>(j) <= i) continue;
      pairs.push_back({i, static_cast<size_t>(j)});
      ++pairCount[i], ++pairCount[j];
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
