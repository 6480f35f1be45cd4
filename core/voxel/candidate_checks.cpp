// SPDX-License-Identifier: GPL-3.0-or-later
#include "voxel/candidate_checks.h"

#include "analysis/part_motion.h"
#include "desia/analysis.h"
#include "desia/voxel.h"

namespace desia::design {
namespace {

Vec3 toVec3(const Int3& d) { return {double(d.x), double(d.y), double(d.z)}; }

// Requirement (ii) for the key (Section 4.2): in [P1, R1], P1 moves along the key direction only.
bool keyMovesOnlyAlong(const Assembly& assembly, const Int3& keyDirection) {
  for (const Int3& step : kAxisSteps) {
    const bool free = isPartFreeAlong(assembly, nullptr, 0, toVec3(step));
    if (free != (step == keyDirection)) return false;
  }
  return true;
}

// Requirement (ii) for i >= 2: A_i is interlocking with P1 as key, free along the key direction only.
bool interlockingWithKeyOne(const Assembly& assembly, const Int3& keyDirection) {
  const InterlockingResult result = testInterlockingByGraphs(assembly, buildBaseBlockingGraphs(assembly));
  return result.verdict == Verdict::Interlocking && result.key == 0 && result.keyDirections.size() == 1 &&
         result.keyDirections[0] == toVec3(keyDirection);
}

// Requirement (iii): the new part leaves [P_i, R_i] (earlier parts are already gone).
bool partLeavesRemainder(const VoxelGrid& grid, int partLabel) {
  VoxelGrid pair = grid;
  for (int64_t i = 0; i < pair.voxelCount(); ++i) {
    if (pair.labelAt(i) < partLabel) pair.setLabelAt(i, 0);
  }
  std::vector<Move> path;
  return findVoxelRemovalPath(pair, partLabel, &path);
}

}  // namespace

bool splitInterlocks(const Assembly& assembly, int partLabel, const Int3& keyDirection) {
  return partLabel == 1 ? keyMovesOnlyAlong(assembly, keyDirection) : interlockingWithKeyOne(assembly, keyDirection);
}

bool acceptsSplit(const VoxelGrid& grid, int partLabel, const Int3& keyDirection) {
  if (!isFaceConnected(grid, partLabel) || !isFaceConnected(grid, partLabel + 1)) return false;
  return splitInterlocks(assemblyFromVoxels(grid), partLabel, keyDirection) && partLeavesRemainder(grid, partLabel);
}

}  // namespace desia::design
