// SPDX-License-Identifier: GPL-3.0-or-later
// Frame structures (paper Section 5.3): validation, faces of the joint cubes, beam bodies, voxel
// contacts and swept collisions.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>

#include "analysis/vec3.h"
#include "desia/cut_points.h"
#include "desia/error.h"
#include "desia/voxel_surface.h"
#include "desia/frame.h"
#include "desia/tolerances.h"
#include "desia/voxel_grid.h"

namespace desia {
namespace {


// Largest coordinate difference: two axis-aligned cubes of size s overlap or touch when it is <= s.
double chebyshevDistance(const Vec3& a, const Vec3& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

std::string pointText(const Vec3& p) { return "(" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + ")"; }

std::string beamName(const Frame& frame, int beam) { return "beam " + std::to_string(frame.beams[beam].id); }
std::string jointName(const Frame& frame, int joint) { return "joint " + std::to_string(frame.joints[joint].id); }

std::string beamList(const Frame& frame, const std::vector<int>& beams) {
  std::string text;
  for (size_t k = 0; k < beams.size(); ++k) text += (k ? ", " : "") + std::to_string(frame.beams[beams[k]].id);
  return text;
}

// The point a beam heads to when it leaves the joint at `end` (0 or 1).
Vec3 nextPointFrom(const Frame& frame, int beam, int end) {
  const FrameBeam& b = frame.beams[beam];
  if (b.path.empty()) return frame.joints[b.joints[1 - end]].position;
  return end == 0 ? b.path.front() : b.path.back();
}

struct Aabb {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

Aabb boxBounds(const OrientedBox& box) {
  Aabb bounds;
  for (int k = 0; k < 3; ++k) {
    double r = 0;
    for (int i = 0; i < 3; ++i) r += box.halfExtents[i] * std::abs(box.axes[i][k]);
    bounds.lo[k] = box.centre[k] - r;
    bounds.hi[k] = box.centre[k] + r;
  }
  return bounds;
}

bool boundsOverlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] <= b.lo[k] || b.hi[k] <= a.lo[k]) return false;
  }
  return true;
}

// `bounds` swept along an axis direction to infinity.
Aabb sweptBounds(Aabb bounds, const Vec3& direction) {
  for (int k = 0; k < 3; ++k) {
    if (direction[k] > 0) bounds.hi[k] = std::numeric_limits<double>::infinity();
    if (direction[k] < 0) bounds.lo[k] = -std::numeric_limits<double>::infinity();
  }
  return bounds;
}

Aabb cubeBounds(const FrameLayout& layout, int joint) {
  const double half = layout.frame.jointSize / 2;
  const Vec3& p = layout.frame.joints[joint].position;
  return {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}};
}

OrientedBox boxFromBounds(const Aabb& bounds) {
  OrientedBox box;
  for (int k = 0; k < 3; ++k) {
    box.centre[k] = (bounds.lo[k] + bounds.hi[k]) / 2;
    box.halfExtents[k] = (bounds.hi[k] - bounds.lo[k]) / 2;
  }
  return box;
}

// A segment's box: its axis, the section's sides on axes where possible, half a section longer at
// both ends.
OrientedBox segmentBox(const Vec3& a, const Vec3& b, double section) {
  OrientedBox box;
  const Vec3 along = minus(b, a);
  const double length = norm(along);
  box.axes[0] = scaled(along, 1.0 / length);
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(box.axes[0][k]) < std::abs(box.axes[0][least])) least = k;
  }
  Vec3 axis{0, 0, 0};
  axis[least] = 1;
  box.axes[1] = normalized(cross(box.axes[0], axis));
  box.axes[2] = cross(box.axes[0], box.axes[1]);
  box.centre = scaled(plus(a, b), 0.5);
  box.halfExtents = {length / 2 + section / 2, section / 2, section / 2};
  return box;
}

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

// Overlap with positive depth of two boxes at rest.
bool boxesOverlap(const OrientedBox& a, const OrientedBox& b) { return sweptBoxesCollide(a, {0, 0, 0}, b); }

int faceOfTangent(const FrameLayout& layout, int beam, int end, const std::string& source) {
  const Frame& frame = layout.frame;
  const int joint = frame.beams[beam].joints[end];
  const Vec3 tangent = minus(nextPointFrom(frame, beam, end), frame.joints[joint].position);
  const double length = norm(tangent);
  if (!(length > 0)) {
    throwBadInput(source, beamName(frame, beam) + ": its path starts at " + jointName(frame, joint) +
                              "'s position, so it has no direction there");
  }
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return std::abs(tangent[x]) > std::abs(tangent[y]); });
  const double best = std::abs(tangent[order[0]]), second = std::abs(tangent[order[1]]);
  const int face = 2 * order[0] + (tangent[order[0]] < 0 ? 1 : 0);
  if (best - second <= tolerance::kTieFraction * best) {
    const int other = 2 * order[1] + (tangent[order[1]] < 0 ? 1 : 0);
    throwBadInput(source, jointName(frame, joint) + ": " + beamName(frame, beam) + " leaves along " +
                              pointText(scaled(tangent, 1 / length)) + ", as close to the cube's " +
                              cubeFaceName(face) + " face as to its " + cubeFaceName(other) +
                              " face; tilt the beam (or add a path point) so that one face is closest");
  }
  return face;
}

// Two joints at one place: named (the default joint size would come out as 0).
void requireJointsApart(const Frame& frame, const std::string& source) {
  std::vector<int> order(frame.joints.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return frame.joints[a].position < frame.joints[b].position || (frame.joints[a].position == frame.joints[b].position && a < b);
  });
  for (size_t k = 1; k < order.size(); ++k) {
    const Vec3& p = frame.joints[order[k - 1]].position;
    if (p != frame.joints[order[k]].position) continue;
    const int first = std::min(order[k - 1], order[k]), second = std::max(order[k - 1], order[k]);
    throwBadInput(source, jointName(frame, first) + " and " + jointName(frame, second) + " are at the same place (" +
                              number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) +
                              "): merge them, or move one; a joint cube needs room between them");
  }
}

}  // namespace

const char* cubeFaceName(int face) {
  static const char* const names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

Vec3 cubeFaceNormal(int face) {
  Vec3 n{0, 0, 0};
  n[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
  return n;
}

int faceCentreVoxel(int face) {
  int c[3] = {1, 1, 1};
  c[face / 2] = face % 2 == 0 ? 2 : 0;
  return c[0] + 3 * c[1] + 9 * c[2];
}

double defaultJointSize(const Frame& frame) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const FrameBeam& beam : frame.beams) {
    shortest =
        std::min(shortest, norm(minus(frame.joints[beam.joints[0]].position, frame.joints[beam.joints[1]].position)));
  }
  // Closest pair of joints by largest coordinate difference: sweep along x.
  std::vector<int> byX(frame.joints.size());
  std::iota(byX.begin(), byX.end(), 0);
  std::sort(byX.begin(), byX.end(),
            [&](int a, int b) { return frame.joints[a].position[0] < frame.joints[b].position[0]; });
  double closest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < byX.size(); ++i) {
    for (size_t j = i + 1; j < byX.size(); ++j) {
      const Vec3& a = frame.joints[byX[i]].position;
      const Vec3& b = frame.joints[byX[j]].position;
      if (b[0] - a[0] >= closest) break;
      closest = std::min(closest, chebyshevDistance(a, b));
    }
  }
  return std::min(shortest / 5, closest / 2);
}

FrameLayout layoutFrame(Frame frame, const std::string& source) {
  FrameLayout layout;
  if (frame.joints.empty() || frame.beams.empty())
    throwBadInput(source, "a frame needs joints and beams; this one has " + std::to_string(frame.joints.size()) +
                              " joints and " + std::to_string(frame.beams.size()) + " beams");
  const int jointCount = static_cast<int>(frame.joints.size());
  const int beamCount = static_cast<int>(frame.beams.size());
  // Each beam on its own: two different joints at two different places.
  for (int b = 0; b < beamCount; ++b) {
    const FrameBeam& beam = frame.beams[b];
    for (int joint : beam.joints) {
      if (joint < 0 || joint >= jointCount) throwBadInput(source, beamName(frame, b) + ": joint index out of range");
    }
    if (beam.joints[0] == beam.joints[1]) {
      throwBadInput(source, beamName(frame, b) + " starts and ends at " + jointName(frame, beam.joints[0]) +
                                ": a beam joins two different joints");
    }
    if (frame.joints[beam.joints[0]].position == frame.joints[beam.joints[1]].position) {
      throwBadInput(source, beamName(frame, b) + " has zero length: " + jointName(frame, beam.joints[0]) + " and " +
                                jointName(frame, beam.joints[1]) + " are at the same point " +
                                pointText(frame.joints[beam.joints[0]].position));
    }
  }
  {
    std::map<std::tuple<int, int, std::vector<Vec3>>, int> seen;
    for (int b = 0; b < beamCount; ++b) {
      const FrameBeam& beam = frame.beams[b];
      std::vector<Vec3> path = beam.path;
      int lo = beam.joints[0], hi = beam.joints[1];
      if (lo > hi) {
        std::swap(lo, hi);
        std::reverse(path.begin(), path.end());
      }
      const auto [it, inserted] = seen.insert({{lo, hi, path}, b});
      if (!inserted) {
        throwBadInput(source, "beams " + std::to_string(frame.beams[it->second].id) + " and " +
                                  std::to_string(beam.id) + " are the same beam: both join " + jointName(frame, lo) +
                                  " and " + jointName(frame, hi) + (path.empty() ? "" : " along the same path"));
      }
    }
  }
  // Valence, joints without beams, one frame.
  layout.beamsAtJoint.assign(jointCount, {});
  for (int b = 0; b < beamCount; ++b) {
    for (int joint : frame.beams[b].joints) layout.beamsAtJoint[joint].push_back(b);
  }
  for (int j = 0; j < jointCount; ++j) {
    const std::vector<int>& beams = layout.beamsAtJoint[j];
    if (beams.empty())
      throwBadInput(source, jointName(frame, j) + " at " + pointText(frame.joints[j].position) + " joins no beam");
    if (static_cast<int>(beams.size()) > kMaxJointValence) {
      throwBadInput(
          source, jointName(frame, j) + " joins " + std::to_string(beams.size()) + " beams (" + beamList(frame, beams) +
                      "): a joint cube has six faces, so a joint joins at most six beams (paper Section 5.3)");
    }
  }
  {
    std::vector<int> parent(jointCount);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const FrameBeam& beam : frame.beams) parent[root(beam.joints[0])] = root(beam.joints[1]);
    for (int j = 1; j < jointCount; ++j) {
      if (root(j) != root(0)) {
        throwBadInput(source, "the frame falls apart: " + jointName(frame, j) + " (with " +
                                  beamName(frame, layout.beamsAtJoint[j][0]) + ") is not connected to " +
                                  jointName(frame, 0) + " by beams");
      }
    }
  }
  // Sizes. Two joints at one place leave no room for a joint cube: named here, before the default
  // size (half the closest pair's distance) comes out as 0 and is refused as a size nobody gave.
  if (frame.jointSize == 0) {
    requireJointsApart(frame, source);
    frame.jointSize = defaultJointSize(frame);
  }
  if (!(frame.jointSize > 0) || !std::isfinite(frame.jointSize)) {
    throwBadInput(source, "the joint size must be a positive number, got " + number(frame.jointSize));
  }
  layout.voxelSize = frame.jointSize / kJointVoxelsPerSide;
  if (frame.beamSection == 0) frame.beamSection = layout.voxelSize;
  if (!(frame.beamSection > 0) || frame.beamSection > layout.voxelSize * (1 + tolerance::kRelativeRounding)) {
    throwBadInput(source, "the beam section " + number(frame.beamSection) +
                              " must be positive and at most the voxel size " + number(layout.voxelSize) +
                              " (a third of the joint size " + number(frame.jointSize) +
                              "): a beam enters the centre voxel of a cube face");
  }
  // Joint cubes apart from one another.
  {
    std::vector<int> byX(jointCount);
    std::iota(byX.begin(), byX.end(), 0);
    std::sort(byX.begin(), byX.end(),
              [&](int a, int b) { return frame.joints[a].position[0] < frame.joints[b].position[0]; });
    for (size_t i = 0; i < byX.size(); ++i) {
      for (size_t k = i + 1; k < byX.size(); ++k) {
        const Vec3& a = frame.joints[byX[i]].position;
        const Vec3& b = frame.joints[byX[k]].position;
        if (b[0] - a[0] > frame.jointSize * (1 + tolerance::kRelativeRounding)) break;
        if (chebyshevDistance(a, b) <= frame.jointSize * (1 + tolerance::kRelativeRounding)) {
          const int first = std::min(byX[i], byX[k]), second = std::max(byX[i], byX[k]);
          throwBadInput(source, "the joint cubes of " + jointName(frame, first) + " and " + jointName(frame, second) +
                                    " overlap or touch: the joints are " + number(chebyshevDistance(a, b)) +
                                    " apart along an axis and a cube is " + number(frame.jointSize) +
                                    " wide; give a smaller joint size");
        }
      }
    }
  }
  // Faces: one beam per face.
  layout.frame = std::move(frame);
  const Frame& f = layout.frame;
  layout.endFace.assign(beamCount, {0, 0});
  layout.faceBeam.assign(jointCount, {-1, -1, -1, -1, -1, -1});
  for (int b = 0; b < beamCount; ++b) {
    for (int end = 0; end < 2; ++end) {
      const int joint = f.beams[b].joints[end];
      const int face = faceOfTangent(layout, b, end, source);
      layout.endFace[b][end] = face;
      int& owner = layout.faceBeam[joint][face];
      if (owner >= 0) {
        throwBadInput(source, jointName(f, joint) + ": beams " + std::to_string(f.beams[owner].id) + " and " +
                                  std::to_string(f.beams[b].id) + " both enter its " + cubeFaceName(face) +
                                  " face; at most one beam enters each face of a joint cube (paper Section 5.3)");
      }
      owner = b;
    }
  }
  // Path points outside every cube; bodies that cross nothing.
  const double half = f.jointSize / 2;
  for (int b = 0; b < beamCount; ++b) {
    for (const Vec3& point : f.beams[b].path) {
      for (int j = 0; j < jointCount; ++j) {
        if (chebyshevDistance(point, f.joints[j].position) < half + layout.voxelSize) {
          throwBadInput(source, beamName(f, b) + ": path point " + pointText(point) +
                                    " lies in or next to the joint cube of " + jointName(f, j) +
                                    " (keep path points a voxel away from the cubes)");
        }
      }
    }
  }
  struct Piece {
    Aabb bounds;
    OrientedBox box;
    int beam;   // -1 for a joint cube
    int joint;  // the joint cube, or the joint a beam's end segment starts at (-1 otherwise)
    int otherJoint;
  };
  std::vector<Piece> pieces;
  for (int j = 0; j < jointCount; ++j) {
    const Aabb bounds = cubeBounds(layout, j);
    pieces.push_back({bounds, boxFromBounds(bounds), -1, j, -1});
  }
  for (int b = 0; b < beamCount; ++b) {
    const std::vector<OrientedBox> boxes = beamBodyBoxes(layout, b);
    for (size_t s = 0; s < boxes.size(); ++s) {
      const int startJoint = s == 0 ? f.beams[b].joints[0] : -1;
      const int endJoint = s + 1 == boxes.size() ? f.beams[b].joints[1] : -1;
      pieces.push_back({boxBounds(boxes[s]), boxes[s], b, startJoint, endJoint});
    }
  }
  std::vector<int> byX(pieces.size());
  std::iota(byX.begin(), byX.end(), 0);
  std::sort(byX.begin(), byX.end(), [&](int a, int b) { return pieces[a].bounds.lo[0] < pieces[b].bounds.lo[0]; });
  for (size_t i = 0; i < byX.size(); ++i) {
    for (size_t k = i + 1; k < byX.size(); ++k) {
      const Piece& p = pieces[byX[i]];
      const Piece& q = pieces[byX[k]];
      if (q.bounds.lo[0] >= p.bounds.hi[0]) break;
      if (p.beam < 0 && q.beam < 0) continue;  // cubes were checked above
      if (p.beam >= 0 && p.beam == q.beam) continue;
      const Piece& beamPiece = p.beam >= 0 ? p : q;
      const Piece& other = p.beam >= 0 ? q : p;
      if (other.beam < 0 && (beamPiece.joint == other.joint || beamPiece.otherJoint == other.joint))
        continue;  // its own end
      if (!boundsOverlap(p.bounds, q.bounds) || !boxesOverlap(p.box, q.box)) continue;
      if (other.beam < 0) {
        throwBadInput(source,
                      beamName(f, beamPiece.beam) + " passes through the joint cube of " + jointName(f, other.joint));
      }
      const int first = std::min(p.beam, q.beam), second = std::max(p.beam, q.beam);
      throwBadInput(source, "beams " + std::to_string(f.beams[first].id) + " and " +
                                std::to_string(f.beams[second].id) + " cross or overlap (with a section of " +
                                number(f.beamSection) + ")");
    }
  }
  for (auto& beams : layout.beamsAtJoint) std::sort(beams.begin(), beams.end());
  return layout;
}

std::vector<int> frameCutBeams(const FrameLayout& layout) {
  std::vector<std::pair<int, int>> edges;
  for (const std::vector<int>& beams : layout.beamsAtJoint) {
    for (size_t a = 0; a < beams.size(); ++a) {
      for (size_t b = a + 1; b < beams.size(); ++b) edges.push_back({beams[a], beams[b]});
    }
  }
  return findCutPoints(static_cast<int>(layout.frame.beams.size()), edges);
}

void validateJointLabels(const FrameLayout& layout, const std::vector<JointLabels>& labels, const std::string& source) {
  const Frame& frame = layout.frame;
  if (labels.size() != frame.joints.size()) {
    throwBadInput(source, "joint voxels: " + std::to_string(labels.size()) + " joints labelled, the frame has " +
                              std::to_string(frame.joints.size()));
  }
  for (size_t j = 0; j < labels.size(); ++j) {
    const std::vector<int>& beams = layout.beamsAtJoint[j];
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int label = labels[j][v];
      if (label < 0 || !std::binary_search(beams.begin(), beams.end(), label)) {
        throwBadInput(source, jointName(frame, static_cast<int>(j)) + ": voxel (" + std::to_string(v % 3) + ", " +
                                  std::to_string(v / 3 % 3) + ", " + std::to_string(v / 9) +
                                  ") belongs to no beam of this joint (its beams: " + beamList(frame, beams) + ")");
      }
    }
    for (int beam : beams) {
      const int end = frame.beams[beam].joints[0] == static_cast<int>(j) ? 0 : 1;
      const int face = faceCentreVoxel(layout.endFace[beam][end]);
      if (labels[j][face] != beam) {
        throwBadInput(source, jointName(frame, static_cast<int>(j)) + ": " + beamName(frame, beam) + " enters the " +
                                  cubeFaceName(layout.endFace[beam][end]) + " face, but its centre voxel belongs to " +
                                  beamName(frame, labels[j][face]));
      }
      // Face-connected from the face voxel.
      std::vector<int> stack{face};
      std::array<bool, kJointVoxelCount> seen{};
      seen[face] = true;
      int reached = 1;
      while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        const int c[3] = {v % 3, v / 3 % 3, v / 9};
        for (int k = 0; k < 3; ++k) {
          for (int step : {-1, 1}) {
            int n[3] = {c[0], c[1], c[2]};
            n[k] += step;
            if (n[k] < 0 || n[k] > 2) continue;
            const int w = n[0] + 3 * n[1] + 9 * n[2];
            if (seen[w] || labels[j][w] != beam) continue;
            seen[w] = true;
            ++reached;
            stack.push_back(w);
          }
        }
      }
      const int owned = static_cast<int>(std::count(labels[j].begin(), labels[j].end(), beam));
      if (reached != owned) {
        throwBadInput(source, jointName(frame, static_cast<int>(j)) + ": the voxels of " + beamName(frame, beam) +
                                  " are not face-connected to the voxel its beam enters");
      }
    }
  }
}

Assembly frameAssembly(const FrameLayout& layout, const std::vector<JointLabels>& labels,
                       const std::vector<int>& partOrder) {
  const Frame& frame = layout.frame;
  Assembly assembly;
  std::vector<int> partOf(frame.beams.size(), -1);
  for (size_t k = 0; k < partOrder.size(); ++k) {
    partOf[partOrder[k]] = static_cast<int>(k);
    assembly.parts.push_back({frame.beams[partOrder[k]].id, ""});
  }
  // (lower part, higher part, signed axis 0..5 from lower to higher) -> faces.
  std::map<std::tuple<int, int, int>, int> faces;
  for (size_t j = 0; j < labels.size(); ++j) {
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int c[3] = {v % 3, v / 3 % 3, v / 9};
      for (int k = 0; k < 3; ++k) {
        if (c[k] == 2) continue;
        const int w = v + (k == 0 ? 1 : k == 1 ? 3 : 9);
        const int a = partOf[labels[j][v]], b = partOf[labels[j][w]];
        if (a == b) continue;
        // Normal +axis k from a (below) to b (above).
        if (a < b)
          ++faces[{a, b, 2 * k}];
        else
          ++faces[{b, a, 2 * k + 1}];
      }
    }
  }
  for (const auto& [key, count] : faces) {
    const auto& [a, b, face] = key;
    assembly.contacts.push_back({a, b, cubeFaceNormal(face), static_cast<double>(count)});
  }
  return assembly;
}

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

TriangleMesh beamPartMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam) {
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
