// SPDX-License-Identifier: GPL-3.0-or-later
#include "voxel/gap_matrix.h"

#include <algorithm>

namespace desia {
namespace group_moves {
namespace {

int64_t columnKey(int u, int v) { return static_cast<int64_t>(u) * 4294967296LL + (static_cast<int64_t>(v) + 2147483648LL); }

// Coordinates of a voxel as (along, u, v) for an axis.
std::array<int, 3> alongAxis(const Int3& c, int axis) {
  if (axis == 0) return {c.x, c.y, c.z};
  if (axis == 1) return {c.y, c.x, c.z};
  return {c.z, c.x, c.y};
}

Columns columnsOf(const std::vector<Int3>& voxels, int axis) {
  std::vector<std::array<int, 3>> cells;
  for (const Int3& c : voxels) {
    const auto a = alongAxis(c, axis);
    cells.push_back({a[1], a[2], a[0]});
  }
  std::sort(cells.begin(), cells.end());
  Columns columns;
  for (size_t k = 0; k < cells.size(); ++k) {
    const auto& [u, v, w] = cells[k];
    if (k == 0 || cells[k - 1][0] != u || cells[k - 1][1] != v) {
      columns.keys.push_back(columnKey(u, v));
      columns.u.push_back(u);
      columns.v.push_back(v);
      columns.first.push_back(static_cast<int>(columns.along.size()));
      columns.minU = std::min(columns.minU, u);
      columns.maxU = std::max(columns.maxU, u);
      columns.minV = std::min(columns.minV, v);
      columns.maxV = std::max(columns.maxV, v);
    }
    columns.along.push_back(w);
  }
  columns.first.push_back(static_cast<int>(columns.along.size()));
  return columns;
}


AxisGaps gapsAlong(const Columns& a, const Columns& b, const std::array<int, 3>& shift) {
  AxisGaps gaps;
  const int sw = shift[0], su = shift[1], sv = shift[2];  // b's voxels sit at their coordinates + shift
  if (a.keys.empty() || b.keys.empty() || a.maxU < b.minU + su || b.maxU + su < a.minU || a.maxV < b.minV + sv ||
      b.maxV + sv < a.minV) {
    return gaps;
  }
  for (size_t c = 0; c < a.keys.size(); ++c) {
    const int64_t key = columnKey(a.u[c] - su, a.v[c] - sv);
    const auto found = std::lower_bound(b.keys.begin(), b.keys.end(), key);
    if (found == b.keys.end() || *found != key) continue;
    const size_t d = static_cast<size_t>(found - b.keys.begin());
    int p = a.first[c], q = b.first[d];
    const int pEnd = a.first[c + 1], qEnd = b.first[d + 1];
    int lastA = 0, lastB = 0;
    bool seenA = false, seenB = false;
    while (p < pEnd || q < qEnd) {
      const bool takeA = q >= qEnd || (p < pEnd && a.along[p] < b.along[q] + sw);
      if (takeA) {
        const int t = a.along[p++];
        if (seenB) gaps.secondUp = std::min(gaps.secondUp, t - lastB - 1);
        lastA = t;
        seenA = true;
      } else {
        const int s = b.along[q++] + sw;
        if (seenA) gaps.firstUp = std::min(gaps.firstUp, s - lastA - 1);
        lastB = s;
        seenB = true;
      }
    }
  }
  return gaps;
}

}  // namespace

PartGeometry::PartGeometry(const VoxelGrid& grid, int partCount) : columns_(static_cast<size_t>(partCount)) {
  std::vector<std::vector<Int3>> voxels(static_cast<size_t>(partCount));
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    const int label = grid.labelAt(i);
    if (label > 0 && label <= partCount) voxels[static_cast<size_t>(label - 1)].push_back(grid.coordinates(i));
  }
  for (int part = 0; part < partCount; ++part) {
    for (int axis = 0; axis < 3; ++axis) columns_[part][axis] = columnsOf(voxels[part], axis);
  }
}

const std::array<AxisGaps, 3>& PartGeometry::gaps(int i, int j, const Int3& relative) {
  const PairKey key{i, j, relative.x, relative.y, relative.z};
  auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  if (cache_.size() > kMaxCachedPairs) cache_.clear();
  std::array<AxisGaps, 3> result;
  for (int axis = 0; axis < 3; ++axis) {
    result[axis] = gapsAlong(columns_[i][axis], columns_[j][axis], alongAxis(relative, axis));
  }
  return cache_.emplace(key, result).first->second;
}

}  // namespace group_moves
}  // namespace desia
