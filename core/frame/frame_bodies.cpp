// SPDX-License-Identifier: GPL-3.0-or-later
// The solids of a frame (paper Section 5.3): beam bodies and joint voxels as oriented boxes, their
// swept collisions (separating axes over the motion), the removal of a beam replayed on them, and
// the meshes of beams and joint pieces for export.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/frame.h"
#include "desia/tolerances.h"
#include "desia/voxel.h"
#include "frame/geometry_internals.h"

namespace desia {
namespace {

using frame_geometry::Aabb;
using frame_geometry::beamName;
using frame_geometry::jointName;
using frame_geometry::boundsOverlap;
using frame_geometry::boxBounds;
using frame_geometry::cubeBounds;
using frame_geometry::segmentBox;
using frame_geometry::sweptBounds;

// The centreline of a beam's body: face centre, a voxel straight out (unless it goes on straight),
// the path, and the same at the other end.
std::vector<Vec3> beamCentreline(const FrameLayout& layout, int beam) {
  const Frame& frame = layout.frame;
  const FrameBeam& b = frame.beams[beam];
  std::array<Vec3, 2> face, stub;
  for (int end = 0; end < 2; ++end) {
    const Vec3 n = cubeFaceNormal(layout.endFace[beam][end]);
    face[end] = plus(frame.joints[b.joints[end]].position, scaled(n, frame.jointSize / 2));
    stub[end] = plus(face[end], scaled(n, layout.voxelSize));
  }
  std::vector<Vec3> points{face[0]};
  std::vector<Vec3> middle = b.path;
  const Vec3 firstTarget = middle.empty() ? face[1] : middle.front();
  const Vec3 lastTarget = middle.empty() ? face[0] : middle.back();
  auto straightOut = [&](int end, const Vec3& target) {
    const Vec3 n = cubeFaceNormal(layout.endFace[beam][end]);
    const Vec3 to = minus(target, face[end]);
    return norm(cross(normalized(to), n)) < tolerance::kDirection && dot(to, n) > 0;
  };
  if (!straightOut(0, firstTarget)) points.push_back(stub[0]);
  points.insert(points.end(), middle.begin(), middle.end());
  if (!straightOut(1, lastTarget)) points.push_back(stub[1]);
  points.push_back(face[1]);
  return points;
}

}  // namespace

std::vector<OrientedBox> beamBodyBoxes(const FrameLayout& layout, int beam) {
  const std::vector<Vec3> points = beamCentreline(layout, beam);
  std::vector<OrientedBox> boxes;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    if (norm(minus(points[i + 1], points[i])) > 0)
      boxes.push_back(segmentBox(points[i], points[i + 1], layout.frame.beamSection));
  }
  return boxes;
}

double beamBodyLength(const FrameLayout& layout, int beam) {
  const std::vector<Vec3> points = beamCentreline(layout, beam);
  double length = 0;
  for (size_t i = 0; i + 1 < points.size(); ++i) length += norm(minus(points[i + 1], points[i]));
  return length;
}

OrientedBox jointVoxelBox(const FrameLayout& layout, int joint, int voxel) {
  OrientedBox box;
  const Vec3& p = layout.frame.joints[joint].position;
  const int c[3] = {voxel % 3, voxel / 3 % 3, voxel / 9};
  for (int k = 0; k < 3; ++k) {
    box.centre[k] = p[k] + (c[k] - 1) * layout.voxelSize;
    box.halfExtents[k] = layout.voxelSize / 2;
  }
  return box;
}

// Separating axes over the motion: at each time t the boxes overlap iff no axis among the 15 of
// the static test separates them, so the times of overlap are the intersection over the axes of
// the (open) intervals in which the projections overlap.
bool sweptBoxesCollide(const OrientedBox& moving, const Vec3& direction, const OrientedBox& fixed) {
  std::vector<Vec3> axes;
  axes.reserve(15);
  for (const Vec3& a : moving.axes) axes.push_back(a);
  for (const Vec3& b : fixed.axes) axes.push_back(b);
  for (const Vec3& a : moving.axes) {
    for (const Vec3& b : fixed.axes) {
      const Vec3 c = cross(a, b);
      if (norm(c) > tolerance::kDirection) axes.push_back(normalized(c));
    }
  }
  const Vec3 between = minus(fixed.centre, moving.centre);
  double from = 0, to = std::numeric_limits<double>::infinity();
  for (const Vec3& axis : axes) {
    double reach = 0;
    for (int i = 0; i < 3; ++i) {
      reach += moving.halfExtents[i] * std::abs(dot(moving.axes[i], axis)) +
               fixed.halfExtents[i] * std::abs(dot(fixed.axes[i], axis));
    }
    reach -= tolerance::kRelativeRounding * reach + tolerance::kRoundingMm;  // touching is not overlapping
    const double gap = dot(between, axis);
    const double speed = dot(direction, axis);
    if (std::abs(speed) < tolerance::kZeroDivisor) {
      if (std::abs(gap) >= reach) return false;
      continue;
    }
    double t1 = (gap - reach) / speed, t2 = (gap + reach) / speed;
    if (t1 > t2) std::swap(t1, t2);
    from = std::max(from, t1);
    to = std::min(to, t2);
    if (from >= to) return false;
  }
  return from < to;
}

std::string frameSweepObstacle(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam,
                               const Vec3& direction, const std::vector<bool>& present) {
  const Frame& frame = layout.frame;
  std::vector<OrientedBox> moving = beamBodyBoxes(layout, beam);
  for (int joint : frame.beams[beam].joints) {
    for (int v = 0; v < kJointVoxelCount; ++v) {
      if (labels[joint][v] == beam) moving.push_back(jointVoxelBox(layout, joint, v));
    }
  }
  std::vector<Aabb> movingBounds;
  Aabb all = boxBounds(moving[0]);
  for (const OrientedBox& box : moving) {
    movingBounds.push_back(sweptBounds(boxBounds(box), direction));
    const Aabb b = boxBounds(box);
    for (int k = 0; k < 3; ++k) {
      all.lo[k] = std::min(all.lo[k], b.lo[k]);
      all.hi[k] = std::max(all.hi[k], b.hi[k]);
    }
  }
  all = sweptBounds(all, direction);
  auto hits = [&](const OrientedBox& obstacle) {
    const Aabb bounds = boxBounds(obstacle);
    if (!boundsOverlap(all, bounds)) return false;
    for (size_t m = 0; m < moving.size(); ++m) {
      if (boundsOverlap(movingBounds[m], bounds) && sweptBoxesCollide(moving[m], direction, obstacle)) return true;
    }
    return false;
  };
  for (size_t j = 0; j < frame.joints.size(); ++j) {
    if (!boundsOverlap(all, cubeBounds(layout, static_cast<int>(j)))) continue;
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int label = labels[j][v];
      if (label == beam || (label >= 0 && !present[label])) continue;
      if (hits(jointVoxelBox(layout, static_cast<int>(j), v))) {
        return label >= 0 ? "a voxel of " + beamName(frame, label) + " at " + jointName(frame, static_cast<int>(j))
                          : "a voxel still to assign at " + jointName(frame, static_cast<int>(j));
      }
    }
  }
  for (size_t other = 0; other < frame.beams.size(); ++other) {
    if (static_cast<int>(other) == beam || !present[other]) continue;
    for (const OrientedBox& box : beamBodyBoxes(layout, static_cast<int>(other))) {
      if (hits(box)) return beamName(frame, static_cast<int>(other));
    }
  }
  return "";
}

namespace {

void appendBox(TriangleMesh& mesh, const OrientedBox& box) {
  const int first = static_cast<int>(mesh.vertices.size());
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 p = box.centre;
    for (int i = 0; i < 3; ++i) {
      const double sign = (corner >> i) & 1 ? 1.0 : -1.0;
      p = plus(p, scaled(box.axes[i], sign * box.halfExtents[i]));
    }
    mesh.vertices.push_back(p);
  }
  // Faces as corner quads; each triangle turned to face away from the centre (outward).
  static const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (const auto& q : quads) {
    for (const std::array<int, 3>& corners :
         {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      std::array<int, 3> t{first + corners[0], first + corners[1], first + corners[2]};
      const Vec3& a = mesh.vertices[t[0]];
      const Vec3 normal = cross(minus(mesh.vertices[t[1]], a), minus(mesh.vertices[t[2]], a));
      if (dot(normal, minus(a, box.centre)) < 0) std::swap(t[1], t[2]);
      mesh.triangles.push_back(t);
    }
  }
}

}  // namespace

TriangleMesh orientedBoxMesh(const OrientedBox& box) {
  TriangleMesh mesh;
  appendBox(mesh, box);
  return mesh;
}

TriangleMesh beamJointPieceMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam,
                                int joint) {
  TriangleMesh mesh;
  VoxelGrid grid(3, 3, 3);
  bool any = false;
  for (int v = 0; v < kJointVoxelCount; ++v) {
    if (labels[joint][v] == beam) {
      grid.setLabelAt(v, 1);
      any = true;
    }
  }
  if (!any) return mesh;
  const TriangleMesh voxels = partSurfaceMesh(grid, 1, layout.voxelSize);
  const Vec3& p = layout.frame.joints[joint].position;
  for (const auto& v : voxels.vertices) {
    mesh.vertices.push_back({v[0] + p[0] - 1.5 * layout.voxelSize, v[1] + p[1] - 1.5 * layout.voxelSize,
                             v[2] + p[2] - 1.5 * layout.voxelSize});
  }
  mesh.triangles = voxels.triangles;
  return mesh;
}

namespace {

// The box as an axis-aligned one, when its axes are the coordinate axes (up to sign and rounding).
bool asAxisAligned(const OrientedBox& box, AxisAlignedBox* out) {
  for (int k = 0; k < 3; ++k) {
    out->lo[k] = box.centre[k];
    out->hi[k] = box.centre[k];
  }
  for (int i = 0; i < 3; ++i) {
    int along = -1;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(std::abs(box.axes[i][k]) - 1) < tolerance::kDirection) along = k;
      else if (std::abs(box.axes[i][k]) >= tolerance::kDirection) return false;
    }
    if (along < 0) return false;
    out->lo[along] -= box.halfExtents[i];
    out->hi[along] += box.halfExtents[i];
  }
  return true;
}

}  // namespace

namespace {

// `box` with the part inside `cube` cut away, when that part is a slab across one end of the box
// along one axis (a body box reaching into a joint cube through its face); else unchanged.
AxisAlignedBox cutBackToFace(AxisAlignedBox box, const Aabb& cube) {
  int beyond = -1;
  for (int k = 0; k < 3; ++k) {
    if (box.hi[k] <= cube.lo[k] || box.lo[k] >= cube.hi[k]) return box;  // apart
    const bool inside =
        box.lo[k] >= cube.lo[k] - tolerance::kMeshWeldMm && box.hi[k] <= cube.hi[k] + tolerance::kMeshWeldMm;
    if (inside) continue;
    if (beyond >= 0) return box;  // out of the cube on two axes: not a body entering a face
    beyond = k;
  }
  if (beyond < 0) return box;  // wholly inside the cube: nothing of the body is left to cut to
  if (box.lo[beyond] < cube.lo[beyond]) box.hi[beyond] = std::min(box.hi[beyond], cube.lo[beyond]);
  else box.lo[beyond] = std::max(box.lo[beyond], cube.hi[beyond]);
  return box;
}

}  // namespace

TriangleMesh beamBodyPieceMesh(const FrameLayout& layout, int beam) {
  std::vector<AxisAlignedBox> boxes;
  for (const OrientedBox& box : beamBodyBoxes(layout, beam)) {
    AxisAlignedBox axisBox;
    if (!asAxisAligned(box, &axisBox)) {
      std::vector<JointLabels> unowned(layout.frame.joints.size());
      for (JointLabels& labels : unowned) labels.fill(-1);
      return beamPartMesh(layout, unowned, beam);  // slanted: the body boxes as they are
    }
    // Only a joint cube's face cuts (a bent beam's consecutive boxes overlap each other, which
    // the union takes care of).
    for (int joint : layout.frame.beams[beam].joints) axisBox = cutBackToFace(axisBox, cubeBounds(layout, joint));
    bool empty = false;
    for (int k = 0; k < 3; ++k) empty = empty || axisBox.hi[k] - axisBox.lo[k] <= tolerance::kMeshWeldMm;
    if (!empty) boxes.push_back(axisBox);
  }
  return surfaceOfBoxUnion(boxes, tolerance::kMeshWeldMm);
}

TriangleMesh beamPartMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam) {
  // Axis-aligned bodies (every beam of a frame on a grid): the body boxes and the beam's joint
  // voxels as one solid, their exact union (the body reaches half a section into its joint
  // pieces, and consecutive boxes overlap at bends).
  std::vector<AxisAlignedBox> boxes;
  bool aligned = true;
  for (const OrientedBox& box : beamBodyBoxes(layout, beam)) {
    AxisAlignedBox axisBox;
    aligned = aligned && asAxisAligned(box, &axisBox);
    boxes.push_back(axisBox);
  }
  if (aligned) {
    for (int joint : layout.frame.beams[beam].joints) {
      for (int v = 0; v < kJointVoxelCount; ++v) {
        if (labels[joint][v] != beam) continue;
        AxisAlignedBox voxel;
        const bool isAxisAligned = asAxisAligned(jointVoxelBox(layout, joint, v), &voxel);
        (void)isAxisAligned;  // joint voxels always are
        boxes.push_back(voxel);
      }
    }
    return surfaceOfBoxUnion(boxes, tolerance::kMeshWeldMm);
  }
  // A beam with slanted boxes (a curved beam's path): each body box and each voxel group is a
  // closed shell of its own, and the shells overlap where they meet (no exact union yet).
  TriangleMesh mesh;
  for (const OrientedBox& box : beamBodyBoxes(layout, beam)) appendBox(mesh, box);
  for (int joint : layout.frame.beams[beam].joints) {
    const TriangleMesh piece = beamJointPieceMesh(layout, labels, beam, joint);
    const int first = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const auto& t : piece.triangles) mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  return mesh;
}

}  // namespace desia
