// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/voxel.h"

#include <algorithm>
#include <array>
#include <sstream>

#include "desia/error.h"

namespace desia {

VoxelGrid::VoxelGrid(int nx, int ny, int nz) : nx_(nx), ny_(ny), nz_(nz) {
  if (nx <= 0 || ny <= 0 || nz <= 0) {
    throwBadInput("", "grid size " + std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz) +
                          " is not positive");
  }
  const int64_t total = static_cast<int64_t>(nx) * ny * nz;
  if (nx > VoxelLimits::kMaxSide || ny > VoxelLimits::kMaxSide || nz > VoxelLimits::kMaxSide ||
      total > VoxelLimits::kMaxVoxels) {
    throw Error(ErrorCode::TooLarge, "grid size " + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                                         std::to_string(nz) + " is too large (at most " +
                                         std::to_string(VoxelLimits::kMaxSide) + " per side and " +
                                         std::to_string(VoxelLimits::kMaxVoxels) + " voxels)");
  }
  labels_.assign(static_cast<size_t>(total), 0);
}

Int3 VoxelGrid::coordinates(int64_t i) const {
  Int3 c;
  c.x = static_cast<int>(i % nx_);
  c.y = static_cast<int>((i / nx_) % ny_);
  c.z = static_cast<int>(i / (static_cast<int64_t>(nx_) * ny_));
  return c;
}

int VoxelGrid::maxLabel() const {
  int best = 0;
  for (int v : labels_) best = std::max(best, v);
  return best;
}

std::vector<int64_t> VoxelGrid::labelCounts() const {
  std::vector<int64_t> counts(static_cast<size_t>(maxLabel()) + 1, 0);
  for (int v : labels_) ++counts[v];
  return counts;
}

namespace {

constexpr std::array<std::array<int, 3>, 6> kFaceNeighbours{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};

std::string formatVoxel(const Int3& c) {
  return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ")";
}

// Labels each voxel with its 6-connected component within its own part; returns per part the
// first voxel of every component (in index order).
std::vector<std::vector<int64_t>> componentSeedsPerPart(const VoxelGrid& grid, int partCount) {
  std::vector<std::vector<int64_t>> seeds(static_cast<size_t>(partCount) + 1);
  std::vector<bool> visited(static_cast<size_t>(grid.voxelCount()), false);
  std::vector<int64_t> stack;
  for (int64_t start = 0; start < grid.voxelCount(); ++start) {
    const int label = grid.labelAt(start);
    if (label == 0 || visited[start]) continue;
    seeds[label].push_back(start);
    visited[start] = true;
    stack.push_back(start);
    while (!stack.empty()) {
      const Int3 c = grid.coordinates(stack.back());
      stack.pop_back();
      for (const auto& step : kFaceNeighbours) {
        const int x = c.x + step[0], y = c.y + step[1], z = c.z + step[2];
        if (!grid.inside(x, y, z)) continue;
        const int64_t next = grid.index(x, y, z);
        if (visited[next] || grid.labelAt(next) != label) continue;
        visited[next] = true;
        stack.push_back(next);
      }
    }
  }
  return seeds;
}

}  // namespace

void validateVoxelParts(const VoxelGrid& grid, const std::string& source) {
  const std::vector<int64_t> counts = grid.labelCounts();
  const int partCount = static_cast<int>(counts.size()) - 1;
  if (partCount == 0) throwBadInput(source, "the assembly is empty: every voxel is 0");
  for (int label = 1; label <= partCount; ++label) {
    if (counts[label] == 0) {
      throwBadInput(source, "part " + std::to_string(label) + " has no voxels, but part " +
                                std::to_string(partCount) + " exists: part ids must be 1.." +
                                std::to_string(partCount) + " without gaps");
    }
  }
  const auto seeds = componentSeedsPerPart(grid, partCount);
  for (int label = 1; label <= partCount; ++label) {
    if (seeds[label].size() > 1) {
      throwBadInput(source, "part " + std::to_string(label) + " is not face-connected: it has " +
                                std::to_string(seeds[label].size()) + " separate pieces (one contains voxel " +
                                formatVoxel(grid.coordinates(seeds[label][0])) + ", another voxel " +
                                formatVoxel(grid.coordinates(seeds[label][1])) + ")");
    }
  }
}

Assembly assemblyFromVoxels(const VoxelGrid& grid) {
  Assembly assembly;
  const int partCount = grid.maxLabel();
  for (int id = 1; id <= partCount; ++id) assembly.parts.push_back({id, ""});
  // Touching faces per (a, b, axis) with a on the -axis side of b: the contact normal from a to b
  // is +axis. A part has few neighbours, so a small list per part (searched linearly, sorted at
  // the end) is much faster than a map and gives the same deterministic order (a, b, axis).
  struct FaceCount {
    int other;
    int axis;
    int count;
  };
  std::vector<std::vector<FaceCount>> faces(static_cast<size_t>(partCount));
  auto countFace = [&](int a, int b, int axis) {
    for (FaceCount& entry : faces[a]) {
      if (entry.other == b && entry.axis == axis) {
        ++entry.count;
        return;
      }
    }
    faces[a].push_back({b, axis, 1});
  };
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const int a = grid.label(x, y, z);
        if (a == 0) continue;
        const int neighbours[3] = {x + 1 < grid.nx() ? grid.label(x + 1, y, z) : 0,
                                   y + 1 < grid.ny() ? grid.label(x, y + 1, z) : 0,
                                   z + 1 < grid.nz() ? grid.label(x, y, z + 1) : 0};
        for (int axis = 0; axis < 3; ++axis) {
          const int b = neighbours[axis];
          if (b != 0 && b != a) countFace(a - 1, b - 1, axis);
        }
      }
    }
  }
  for (int a = 0; a < partCount; ++a) {
    std::sort(faces[a].begin(), faces[a].end(), [](const FaceCount& l, const FaceCount& r) {
      return l.other != r.other ? l.other < r.other : l.axis < r.axis;
    });
    for (const FaceCount& entry : faces[a]) {
      Contact contact;
      contact.a = a;
      contact.b = entry.other;
      contact.normal[entry.axis] = 1.0;
      contact.area = entry.count;
      assembly.contacts.push_back(contact);
    }
  }
  return assembly;
}

}  // namespace desia
