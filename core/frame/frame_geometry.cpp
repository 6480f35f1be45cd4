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
#include "desia/error.h"
#include "desia/frame.h"
#include "desia/model.h"
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
using frame_geometry::boxFromBounds;
using frame_geometry::cubeBounds;


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

}  // namespace desia
