// SPDX-License-Identifier: GPL-3.0-or-later
// A labelled voxel grid: the representation of voxel puzzles (and of the 3x3x3 joints of frames).
// Label 0 is empty; label k >= 1 is part k. Index order x + nx*(y + ny*z), as in DESIA's .puz.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/assembly.h"

namespace desia {

// Limits checked before allocating a grid (a hostile header must not exhaust memory).
struct VoxelLimits {
  static constexpr int64_t kMaxSide = 1024;
  static constexpr int64_t kMaxVoxels = 1 << 24;  // 16.7 M voxels (256^3): 64 MiB of labels
};

struct Int3 {
  int x = 0, y = 0, z = 0;
  bool operator==(const Int3& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const Int3& o) const { return !(*this == o); }
};

class VoxelGrid {
 public:
  VoxelGrid() = default;
  // Throws TooLarge / BadInput for sizes outside VoxelLimits.
  VoxelGrid(int nx, int ny, int nz);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  int64_t voxelCount() const { return static_cast<int64_t>(labels_.size()); }

  bool inside(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx_ && y < ny_ && z < nz_;
  }
  int64_t index(int x, int y, int z) const {
    return x + static_cast<int64_t>(nx_) * (y + static_cast<int64_t>(ny_) * z);
  }
  Int3 coordinates(int64_t index) const;
  int label(int x, int y, int z) const { return labels_[index(x, y, z)]; }
  int labelAt(int64_t i) const { return labels_[i]; }
  void setLabel(int x, int y, int z, int value) { labels_[index(x, y, z)] = value; }
  void setLabelAt(int64_t i, int value) { labels_[i] = value; }
  const std::vector<int>& labels() const { return labels_; }

  int maxLabel() const;
  // Voxel count per label, indexed 0..maxLabel() (entry 0 counts empty voxels).
  std::vector<int64_t> labelCounts() const;

 private:
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<int> labels_;
};

// Checks that labels are 1..K with no gap, that there is at least one part, and that each part is
// face-connected (6-connected). Throws BadInput naming the offending part; `source` names the file.
void validateVoxelParts(const VoxelGrid& grid, const std::string& source);

// Parts (ids 1..K) and one contact per (pair, axis normal) with area = number of touching faces.
Assembly assemblyFromVoxels(const VoxelGrid& grid);

}  // namespace desia
