// SPDX-License-Identifier: GPL-3.0-or-later
// The gap matrix of the complete disassembler (group_disassembly.cpp): for one position of a
// sub-assembly and one axis, how far each part can slide before it meets each other part (Bill
// Cutler's movement matrix, as BurrTools computes it), from each part's voxels seen as columns.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "desia/voxel.h"

namespace desia {
namespace group_moves {

constexpr int kFar = std::numeric_limits<int>::max() / 4;  // no meeting at any distance
// Directions in the order they are tried (that of the single-part planner: +y first).
constexpr std::array<std::array<int, 2>, 6> kDirections{{{1, +1}, {1, -1}, {0, +1}, {0, -1}, {2, +1}, {2, -1}}};

// One part's voxels seen along one axis: its columns (the two other coordinates) in sorted
// order, each with the sorted coordinates of its voxels along the axis.
struct Columns {
  std::vector<int64_t> keys;
  std::vector<int> u, v;
  std::vector<int> first;  // keys.size() + 1 entries into `along`
  std::vector<int> along;
  int minU = kFar, maxU = -kFar, minV = kFar, maxV = -kFar;
};

// Gaps between two parts along an axis: how far the first can slide up the axis before it meets
// the second, and how far the second can; kFar when they never meet.
struct AxisGaps {
  int firstUp = kFar, secondUp = kFar;
};

// Every part's columns along each axis, and the gaps of part pairs remembered by their relative
// position (positions repeat across a search, and across the searches of its sub-assemblies).
class PartGeometry {
 public:
  PartGeometry(const VoxelGrid& grid, int partCount);

  // Gaps of parts i < j, j placed at `relative` from i: per axis, i up then j up (remembered).
  const std::array<AxisGaps, 3>& gaps(int i, int j, const Int3& relative);

 private:
  struct PairKey {
    int i, j, x, y, z;
    bool operator==(const PairKey& o) const { return i == o.i && j == o.j && x == o.x && y == o.y && z == o.z; }
  };
  struct PairKeyHash {
    size_t operator()(const PairKey& k) const {
      uint64_t h = 1469598103934665603ULL;
      for (int value : {k.i, k.j, k.x, k.y, k.z}) {
        h ^= static_cast<uint32_t>(value);
        h *= 1099511628211ULL;
      }
      return static_cast<size_t>(h ^ (h >> 32));
    }
  };
  static constexpr size_t kMaxCachedPairs = 1 << 21;
  std::vector<std::array<Columns, 3>> columns_;
  std::unordered_map<PairKey, std::array<AxisGaps, 3>, PairKeyHash> cache_;
};

// The gaps between every two parts of a sub-assembly at one position.
class GapMatrix {
 public:
  GapMatrix(PartGeometry& geometry, const std::vector<int>& parts)
      : geometry_(geometry), parts_(parts), k_(static_cast<int>(parts.size())) {
    for (auto& axis : up_) axis.assign(static_cast<size_t>(k_) * static_cast<size_t>(k_), kFar);
  }

  // `offsets`: 3 per part, in the order of `parts`.
  template <typename Offset>
  void fill(const Offset* offsets) {
    for (int p = 0; p < k_; ++p) {
      for (int q = p + 1; q < k_; ++q) {
        const Int3 relative{offsets[3 * q] - offsets[3 * p], offsets[3 * q + 1] - offsets[3 * p + 1],
                            offsets[3 * q + 2] - offsets[3 * p + 2]};
        const auto& gaps = geometry_.gaps(parts_[p], parts_[q], relative);
        for (int axis = 0; axis < 3; ++axis) {
          up_[axis][index(p, q)] = gaps[axis].firstUp;
          up_[axis][index(q, p)] = gaps[axis].secondUp;
        }
      }
    }
  }

  // How far part p slides along `direction` before it meets part q.
  int gap(int direction, int p, int q) const {
    const int axis = kDirections[direction][0];
    return kDirections[direction][1] > 0 ? up_[axis][index(p, q)] : up_[axis][index(q, p)];
  }

 private:
  size_t index(int p, int q) const { return static_cast<size_t>(p) * static_cast<size_t>(k_) + static_cast<size_t>(q); }

  PartGeometry& geometry_;
  const std::vector<int>& parts_;
  int k_;
  std::array<std::vector<int>, 3> up_;  // up_[axis][p * k + q]: how far p slides up the axis before meeting q
};

}  // namespace group_moves
}  // namespace desia
