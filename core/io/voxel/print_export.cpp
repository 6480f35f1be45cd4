// SPDX-License-Identifier: GPL-3.0-or-later
// Print-ready voxel parts: the clearance check, one STL per part in a ZIP, and the build plate
// (every part turned to lie flat and set down on z = 0 in rows). The inset surfaces themselves are
// built in voxel_surface.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "io/export_internals.h"

namespace desia {
namespace {

using Vec = std::array<double, 3>;

// The 24 proper rotations of the grid in a fixed order: axis permutations in lexicographic order,
// each with the sign patterns (+ before -, x's sign slowest) whose determinant is +1. Identity first.
std::vector<PrintOrientation> properRotations() {
  std::vector<PrintOrientation> rotations;
  std::array<int, 3> axis{0, 1, 2};
  do {
    // The permutation's parity: the number of pairs out of order.
    const int inversions = (axis[0] > axis[1]) + (axis[0] > axis[2]) + (axis[1] > axis[2]);
    for (int signs = 0; signs < 8; ++signs) {
      const std::array<int, 3> sign{(signs & 4) ? -1 : 1, (signs & 2) ? -1 : 1, (signs & 1) ? -1 : 1};
      const int determinant = (inversions % 2 == 0 ? 1 : -1) * sign[0] * sign[1] * sign[2];
      if (determinant == 1) rotations.push_back({axis, sign});
    }
  } while (std::next_permutation(axis.begin(), axis.end()));
  return rotations;
}

int coordinate(const Int3& c, int axis) { return axis == 0 ? c.x : axis == 1 ? c.y : c.z; }

// How well a part lies with its voxels' `axis` coordinate times `sign` as height: voxels on the
// lowest layer (the area resting on the plate), and the height.
struct Footing {
  int64_t voxelsOnPlate = 0;
  int height = 0;
  bool betterThan(const Footing& other) const {
    if (voxelsOnPlate != other.voxelsOnPlate) return voxelsOnPlate > other.voxelsOnPlate;
    return height < other.height;
  }
};

Footing footing(const VoxelGrid& grid, const std::vector<int64_t>& voxels, int axis, int sign) {
  int lowest = 0, highest = 0;
  bool first = true;
  for (const int64_t i : voxels) {
    const int h = sign * coordinate(grid.coordinates(i), axis);
    lowest = first ? h : std::min(lowest, h);
    highest = first ? h : std::max(highest, h);
    first = false;
  }
  Footing result;
  result.height = highest - lowest + 1;
  for (const int64_t i : voxels) result.voxelsOnPlate += sign * coordinate(grid.coordinates(i), axis) == lowest;
  return result;
}

// Vertex v turned by `o`: component r of the result is sign[r] * v[axis[r]] (exact in doubles).
void rotate(TriangleMesh& mesh, const PrintOrientation& o) {
  for (Vec& v : mesh.vertices) {
    const Vec turned{o.sign[0] * v[o.axis[0]], o.sign[1] * v[o.axis[1]], o.sign[2] * v[o.axis[2]]};
    v = turned;
  }
}

struct Box {
  Vec low{0, 0, 0}, high{0, 0, 0};
  double width() const { return high[0] - low[0]; }
  double depth() const { return high[1] - low[1]; }
};

Box boxOf(const TriangleMesh& mesh) {
  Box box;
  box.low = box.high = mesh.vertices.at(0);
  for (const Vec& v : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) {
      box.low[axis] = std::min(box.low[axis], v[axis]);
      box.high[axis] = std::max(box.high[axis], v[axis]);
    }
  }
  return box;
}

// Translates the mesh so that the low corner of its box `box` comes to `to`; the low coordinates
// become exactly `to` (v - low is 0 there).
void moveBoxCorner(TriangleMesh& mesh, const Box& box, const Vec& to) {
  for (Vec& v : mesh.vertices) v = {v[0] - box.low[0] + to[0], v[1] - box.low[1] + to[1], v[2] - box.low[2] + to[2]};
}

// "part-01.stl": numbered with at least two digits, and as many as the largest part id needs, so
// the files sort in part order.
std::string partFileName(int partId, int partCount) {
  const size_t width = std::max<size_t>(2, std::to_string(partCount).size());
  std::string number = std::to_string(partId);
  number.insert(0, width - std::min(width, number.size()), '0');
  return "part-" + number + ".stl";
}

}  // namespace

PrintOrientation printOrientation(const VoxelGrid& grid, const std::vector<int64_t>& voxels) {
  // Only the axis that ends up vertical (and its sign) changes the footing; the first rotation in
  // the fixed order with the best vertical axis is taken.
  const std::vector<PrintOrientation> rotations = properRotations();
  PrintOrientation best = rotations.front();
  Footing bestFooting = footing(grid, voxels, best.axis[2], best.sign[2]);
  for (const PrintOrientation& rotation : rotations) {
    const Footing candidate = footing(grid, voxels, rotation.axis[2], rotation.sign[2]);
    if (candidate.betterThan(bestFooting)) {
      best = rotation;
      bestFooting = candidate;
    }
  }
  return best;
}

void layOutOnBuildPlate(std::vector<NamedMesh>& parts, double spacing) {
  std::vector<Box> boxes;
  double area = 0, widest = 0;
  for (const NamedMesh& part : parts) {
    boxes.push_back(boxOf(part.mesh));
    area += (boxes.back().width() + spacing) * (boxes.back().depth() + spacing);
    widest = std::max(widest, boxes.back().width());
  }
  // Shelves: rows about as long as the plate will be deep (a roughly square plate), filled with
  // the deepest parts first so that each row wastes little behind its shallower parts. Ties keep
  // the parts' order; the parts stay in their order in the file.
  std::vector<size_t> order(parts.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return boxes[a].depth() > boxes[b].depth(); });
  const double rowLength = std::max(widest, std::sqrt(area));
  double x = 0, y = 0, rowDepth = 0;
  for (const size_t k : order) {
    const Box& box = boxes[k];
    if (x > 0 && x + box.width() > rowLength) {
      y += rowDepth + spacing;
      x = 0;
      rowDepth = 0;
    }
    moveBoxCorner(parts[k].mesh, box, {x, y, 0});
    x += box.width() + spacing;
    rowDepth = std::max(rowDepth, box.depth());
  }
}

std::vector<uint8_t> stlZipArchive(const std::vector<NamedMesh>& parts, int partCount, const std::string& details) {
  std::vector<ZipEntry> entries;
  for (const NamedMesh& part : parts) {
    entries.push_back({partFileName(part.partId, partCount),
                       binaryStl({part}, "part " + std::to_string(part.partId) + " of " + std::to_string(partCount) +
                                             ", " + details)});
  }
  return zipStored(entries);
}

void turnFlat(std::vector<NamedMesh>& parts, const VoxelGrid& grid, const std::vector<std::vector<int64_t>>& voxels) {
  for (NamedMesh& part : parts) rotate(part.mesh, printOrientation(grid, voxels[part.partId]));
}

void setDownAtOrigin(std::vector<NamedMesh>& parts) {
  for (NamedMesh& part : parts) moveBoxCorner(part.mesh, boxOf(part.mesh), {0, 0, 0});
}

}  // namespace desia
