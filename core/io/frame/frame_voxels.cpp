// SPDX-License-Identifier: GPL-3.0-or-later
// A designed frame as a voxel assembly (paper Section 5.3 builds frame joints from the
// voxels of Section 4): when every beam is straight and axis-aligned and every joint cube sits on
// one grid of the joint voxel size, each beam becomes a rod of voxels of that size (through the
// centre voxels of the two faces it enters) plus the voxels it owns in its two joint cubes. The
// rods meet the cubes exactly at the face centre voxels, so the contacts of the voxel assembly
// are the frame's joint contacts plus rod faces against nothing: the same DBGs, and the puzzle
// can be printed, opened in BurrTools and checked like any voxel puzzle.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "desia/error.h"
#include "desia/formats.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

std::string pointText(const Vec3& p) {
  std::ostringstream out;
  out << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return out.str();
}

}  // namespace

VoxelGrid frameVoxelGrid(const FrameDocument& document, const std::string& source) {
  const FrameLayout& layout = document.layout;
  const Frame& frame = layout.frame;
  if (document.labels.empty())
    throwBadInput(source, "this frame has no designed joints yet: run desia design frame first");
  const int beams = static_cast<int>(frame.beams.size());
  // Voxel labels are the part ids: a result document numbers its beams 1..n in removal order.
  std::vector<bool> idSeen(beams + 1, false);
  for (const FrameBeam& beam : frame.beams) {
    if (beam.id < 1 || beam.id > beams || idSeen[beam.id])
      throwBadInput(source, "a voxel export needs beams numbered 1 to " + std::to_string(beams) + " (beam " +
                                std::to_string(beam.id) + "); export a design result");
    idSeen[beam.id] = true;
  }
  const double v = layout.voxelSize;
  // The grid: joint cubes' lower corners a whole number of voxels from the first joint's.
  const Vec3& origin = frame.joints[0].position;
  std::vector<Int3> corner(frame.joints.size());
  std::vector<bool> onGrid(frame.joints.size(), true);
  for (size_t j = 0; j < frame.joints.size(); ++j) {
    int c[3];
    for (int k = 0; k < 3; ++k) {
      const double steps = (frame.joints[j].position[k] - origin[k]) / v;
      const double whole = std::round(steps);
      // Positions are read from decimal text: whole numbers of voxels come out within rounding.
      const bool offGrid = std::abs(steps - whole) > tolerance::kOnGridVoxels;
      if (offGrid || std::abs(whole) > VoxelLimits::kMaxSide) onGrid[j] = false;
      c[k] = onGrid[j] ? static_cast<int>(whole) - 1 : 0;  // the cube spans centre -1 .. +1
    }
    corner[j] = {c[0], c[1], c[2]};
  }
  // Every beam straight along one axis, between joints on the grid; named in id order.
  std::vector<int> byId(beams + 1, -1);
  for (int b = 0; b < beams; ++b) byId[frame.beams[b].id] = b;
  for (int id = 1; id <= beams; ++id) {
    const FrameBeam& beam = frame.beams[byId[id]];
    const Vec3& a = frame.joints[beam.joints[0]].position;
    const Vec3& b = frame.joints[beam.joints[1]].position;
    const std::string name = "beam " + std::to_string(id) + " (joints " +
                             std::to_string(frame.joints[beam.joints[0]].id) + " and " +
                             std::to_string(frame.joints[beam.joints[1]].id) + ")";
    if (!beam.path.empty())
      throwBadInput(source, name + " is off the voxel grid: it is curved, and a voxel export needs straight beams "
                                   "along the axes; export stl, obj or csv");
    int differing = 0;
    for (int k = 0; k < 3; ++k) differing += std::abs(a[k] - b[k]) > tolerance::kOnGridVoxels * v ? 1 : 0;
    if (differing != 1)
      throwBadInput(source, name + " is off the voxel grid: it runs from " + pointText(a) + " to " + pointText(b) +
                                ", not along an axis");
    for (int joint : beam.joints) {
      if (!onGrid[joint]) {
        std::ostringstream size;
        size << v;
        throwBadInput(source, name + " is off the voxel grid: joint " + std::to_string(frame.joints[joint].id) +
                                  " at " + pointText(frame.joints[joint].position) +
                                  " is not a whole number of voxels (" + size.str() + ") from joint " +
                                  std::to_string(frame.joints[0].id) + " at " + pointText(origin));
      }
    }
  }
  Int3 lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  Int3 hi{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  for (const Int3& c : corner) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x + 2), std::max(hi.y, c.y + 2), std::max(hi.z, c.z + 2)};
  }
  const int64_t nx = int64_t(hi.x) - lo.x + 1, ny = int64_t(hi.y) - lo.y + 1, nz = int64_t(hi.z) - lo.z + 1;
  if (nx > VoxelLimits::kMaxSide || ny > VoxelLimits::kMaxSide || nz > VoxelLimits::kMaxSide ||
      nx * ny * nz > VoxelLimits::kMaxVoxels)
    throw Error(ErrorCode::TooLarge, source + ": the frame's voxel grid would be " + std::to_string(nx) + " x " +
                                         std::to_string(ny) + " x " + std::to_string(nz) +
                                         " voxels; use a larger joint size");
  VoxelGrid grid(static_cast<int>(nx), static_cast<int>(ny), static_cast<int>(nz));
  for (size_t j = 0; j < frame.joints.size(); ++j) {
    const Int3 c{corner[j].x - lo.x, corner[j].y - lo.y, corner[j].z - lo.z};
    for (int voxel = 0; voxel < kJointVoxelCount; ++voxel) {
      const int owner = document.labels[j][voxel];
      grid.setLabel(c.x + voxel % 3, c.y + voxel / 3 % 3, c.z + voxel / 9, frame.beams[owner].id);
    }
  }
  // The rods: from the cell after the face centre voxel at joints[0] up to the one before that at
  // joints[1], along the beam's axis.
  for (int b = 0; b < beams; ++b) {
    const FrameBeam& beam = frame.beams[b];
    const int face = layout.endFace[b][0];
    const int axis = face / 2, step = face % 2 == 0 ? 1 : -1;
    const int centre = faceCentreVoxel(face);
    const Int3& c0 = corner[beam.joints[0]];
    int cell[3] = {c0.x - lo.x + centre % 3, c0.y - lo.y + centre / 3 % 3, c0.z - lo.z + centre / 9};
    const int otherCentre = faceCentreVoxel(layout.endFace[b][1]);
    const Int3& c1 = corner[beam.joints[1]];
    const int end[3] = {c1.x - lo.x + otherCentre % 3, c1.y - lo.y + otherCentre / 3 % 3, c1.z - lo.z + otherCentre / 9};
    for (int k = 0; k < 3; ++k) {
      if (k != axis && cell[k] != end[k])
        throwBadInput(source, "beam " + std::to_string(beam.id) + " is off the voxel grid: its face centre voxels "
                                                                  "are not in one row");
    }
    if ((end[axis] - cell[axis]) * step < 1)
      throwBadInput(source, "beam " + std::to_string(beam.id) + " is off the voxel grid: its joint cubes face away");
    for (cell[axis] += step; cell[axis] != end[axis]; cell[axis] += step) {
      if (grid.label(cell[0], cell[1], cell[2]) != 0)
        throwBadInput(source, "beam " + std::to_string(beam.id) + " passes through a voxel of beam " +
                                  std::to_string(grid.label(cell[0], cell[1], cell[2])) + " on the voxel grid");
      grid.setLabel(cell[0], cell[1], cell[2], beam.id);
    }
  }
  validateVoxelParts(grid, source);
  return grid;
}

AssemblyDocument frameVoxelDocument(const FrameDocument& document, const std::string& source) {
  return documentFromVoxels(frameVoxelGrid(document, source), document.name);
}

}  // namespace desia
