// SPDX-License-Identifier: GPL-3.0-or-later
// The children of a node of the frame designer's tree (frame_designer.h): which beam leaves next,
// along which axis, with which voxels of its two joint cubes; each child's sweep and its blocking
// graphs checked (paper Sections 4.1 and 5.3), ranked as a sweep of the frame.
#include <algorithm>
#include <cmath>
#include <limits>

#include "desia/analysis.h"
#include "desia/model.h"
#include "desia/tolerances.h"
#include "frame/frame_designer.h"

namespace desia::frame_design {
namespace {

using frame_geometry::boundsOverlap;
using frame_geometry::boxBounds;

constexpr int kOptionsPerJoint = 20;
constexpr int kPairsPerDirection = 80;

int voxelIndex(int x, int y, int z) { return x + 3 * y + 9 * z; }

// The voxel next to `voxel` along signed axis direction `direction` (face numbering), or -1.
int stepVoxel(int voxel, int direction) {
  int c[3] = {voxel % 3, voxel / 3 % 3, voxel / 9};
  c[direction / 2] += direction % 2 == 0 ? 1 : -1;
  if (c[direction / 2] < 0 || c[direction / 2] > 2) return -1;
  return voxelIndex(c[0], c[1], c[2]);
}

int popCount(Mask mask) {
  int count = 0;
  for (; mask; mask &= mask - 1) ++count;
  return count;
}

// Voxels of `within` face-connected to `seeds`.
Mask reachable(Mask seeds, Mask within) {
  Mask reached = seeds & within, frontier = reached;
  while (frontier) {
    Mask next = 0;
    for (Mask m = frontier; m; m &= m - 1) {
      const int v = __builtin_ctz(m);
      for (int d = 0; d < 6; ++d) {
        const int w = stepVoxel(v, d);
        if (w >= 0 && (within >> w & 1) && !(reached >> w & 1)) next |= Mask(1) << w;
      }
    }
    reached |= next;
    frontier = next;
  }
  return reached;
}

Mask neighbours(Mask set) {
  Mask result = 0;
  for (Mask m = set; m; m &= m - 1) {
    const int v = __builtin_ctz(m);
    for (int d = 0; d < 6; ++d) {
      const int w = stepVoxel(v, d);
      if (w >= 0) result |= Mask(1) << w;
    }
  }
  return result & ~set;
}

// `bounds` swept along the axis direction `direction` (face numbering) to infinity.
Aabb swept(const Aabb& bounds, int direction) { return frame_geometry::sweptBounds(bounds, cubeFaceNormal(direction)); }

}  // namespace

// The voxel sets beam `beam` may take at its end `end` when it leaves along `direction`, smallest
// first; empty when no set works (a voxel of a beam of R lies ahead of its face voxel).
std::vector<Mask> FrameDesigner::jointOptions(int beam, int end, int direction) {
  const int joint = frame_.beams[beam].joints[end];
  const JointLabels& labels = labels_[joint];
  const int face = faceCentreVoxel(layout_.endFace[beam][end]);
  Mask free = 0, restFaces = 0, gone = 0;
  for (int v = 0; v < kJointVoxelCount; ++v) {
    if (labels[v] == kFree)
      free |= Mask(1) << v;
    else if (labels[v] != beam && inRest(labels[v]))
      restFaces |= Mask(1) << v;
    else if (labels[v] != beam)
      gone |= Mask(1) << v;  // owned by a beam taken before
  }
  if (!restFaces) return {free};  // the last beam of R here takes every free voxel
  // Closure along the direction: everything free ahead joins; a voxel of R ahead forbids it.
  auto close = [&](Mask set, Mask* closed) {
    Mask result = set;
    for (Mask m = set | (Mask(1) << face); m; m &= m - 1) {
      for (int w = stepVoxel(__builtin_ctz(m), direction); w >= 0; w = stepVoxel(w, direction)) {
        if (restFaces >> w & 1) return false;
        if (free >> w & 1) result |= Mask(1) << w;
      }
    }
    *closed = result;
    return true;
  };
  // P_i connected to its face voxel; each piece of R's voxels here attached to a beam of R.
  auto valid = [&](Mask set) {
    const Mask mine = set | (Mask(1) << face);
    if (reachable(Mask(1) << face, mine) != mine) return false;
    const Mask rest = (free & ~set) | restFaces;
    return reachable(restFaces, rest) == rest;
  };
  std::vector<Mask> options;
  auto add = [&](Mask set) {
    if (std::find(options.begin(), options.end(), set) == options.end() && valid(set)) options.push_back(set);
  };
  Mask base = 0;
  if (!close(0, &base)) return {};
  add(base);
  // One more voxel next to P_i's voxels, each in turn; voxels touching a part taken before first
  // (they make the edges to earlier parts that close the DBG cycles).
  const Mask around = neighbours(base | (Mask(1) << face)) & free;
  std::vector<std::pair<uint64_t, Mask>> grown;
  for (Mask m = around; m; m &= m - 1) {
    const int v = __builtin_ctz(m);
    Mask set = 0;
    if (!close(base | (Mask(1) << v), &set)) continue;
    // Best: a part taken before lies ahead along the direction (P_i -> P_out, case K = 1); next:
    // one touches it at all.
    const int ahead = stepVoxel(v, direction);
    const bool blockedAhead = ahead >= 0 && (gone >> ahead & 1);
    const bool touchesEarlier = (neighbours(Mask(1) << v) & gone) != 0;
    const uint64_t rank = blockedAhead ? 0 : touchesEarlier ? 1 : 2;
    grown.push_back({(rank << 60) + (nextRandom() >> 4), set});
  }
  std::sort(grown.begin(), grown.end());
  for (const auto& [rank, set] : grown) add(set);
  // Random growth by two to eight voxels.
  for (int attempt = 0; attempt < 3 * kOptionsPerJoint && static_cast<int>(options.size()) < kOptionsPerJoint;
       ++attempt) {
    Mask set = base;
    const int extra = 2 + static_cast<int>(nextRandom() % 7);
    for (int k = 0; k < extra; ++k) {
      const Mask choices = neighbours(set | (Mask(1) << face)) & free;
      if (!choices) break;
      int pick = static_cast<int>(nextRandom() % popCount(choices));
      Mask m = choices;
      for (; pick > 0; --pick) m &= m - 1;
      Mask closed = 0;
      if (!close(set | (m & (~m + 1)), &closed)) continue;
      set = closed;
    }
    add(set);
  }
  std::stable_sort(options.begin(), options.end(), [](Mask a, Mask b) { return popCount(a) < popCount(b); });
  if (static_cast<int>(options.size()) > kOptionsPerJoint) options.resize(kOptionsPerJoint);
  return options;
}

// Everything of R in the way of `beam` leaving along `direction` with any voxels of its cubes:
// bodies of R's beams and voxels of R (free voxels of the beam's own cubes included, tagged).
std::vector<Obstacle> FrameDesigner::corridorObstacles(int beam, int direction) const {
  Aabb reach = bodyBounds_[beam];
  for (int joint : frame_.beams[beam].joints) {
    const Vec3& p = frame_.joints[joint].position;
    const double half = frame_.jointSize / 2;
    frame_geometry::include(reach, {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}});
  }
  reach = swept(reach, direction);
  std::vector<Obstacle> obstacles;
  for (size_t j = 0; j < frame_.joints.size(); ++j) {
    const Vec3& p = frame_.joints[j].position;
    const double half = frame_.jointSize / 2;
    if (!boundsOverlap(reach, {{p[0] - half, p[1] - half, p[2] - half}, {p[0] + half, p[1] + half, p[2] + half}})) continue;
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int label = labels_[j][v];
      if (label == beam || (label != kFree && !inRest(label))) continue;
      Obstacle obstacle;
      obstacle.box = jointVoxelBox(layout_, static_cast<int>(j), v);
      obstacle.bounds = boxBounds(obstacle.box);
      if (!boundsOverlap(reach, obstacle.bounds)) continue;
      if (label == kFree) {
        obstacle.joint = static_cast<int>(j);
        obstacle.voxel = v;
      }
      obstacles.push_back(obstacle);
    }
  }
  for (size_t other = 0; other < frame_.beams.size(); ++other) {
    if (static_cast<int>(other) == beam || !inRest(static_cast<int>(other)) || !boundsOverlap(reach, bodyBounds_[other]))
      continue;
    for (const OrientedBox& box : bodies_[other]) {
      const Aabb bounds = boxBounds(box);
      if (boundsOverlap(reach, bounds)) obstacles.push_back({box, bounds, -1, -1});
    }
  }
  return obstacles;
}

// The beam's body and voxels (face voxels and `taken`) swept along `direction` miss R.
bool FrameDesigner::sweepClear(int beam, int direction, const std::array<Mask, 2>& taken,
                               const std::vector<Obstacle>& obstacles) const {
  const Vec3 d = cubeFaceNormal(direction);
  const std::array<int, 2>& joints = frame_.beams[beam].joints;
  std::vector<OrientedBox> moving = bodies_[beam];
  for (int end = 0; end < 2; ++end) {
    Mask mine = taken[end];
    for (int v = 0; v < kJointVoxelCount; ++v) {
      if (labels_[joints[end]][v] == beam) mine |= Mask(1) << v;
    }
    for (Mask m = mine; m; m &= m - 1) moving.push_back(jointVoxelBox(layout_, joints[end], __builtin_ctz(m)));
  }
  std::vector<Aabb> movingBounds;
  for (const OrientedBox& box : moving) movingBounds.push_back(swept(boxBounds(box), direction));
  for (const Obstacle& obstacle : obstacles) {
    if (obstacle.joint >= 0) {
      const int end = obstacle.joint == joints[0] ? 0 : obstacle.joint == joints[1] ? 1 : -1;
      if (end >= 0 && (taken[end] >> obstacle.voxel & 1)) continue;  // it moves with the beam
    }
    for (size_t m = 0; m < moving.size(); ++m) {
      if (boundsOverlap(movingBounds[m], obstacle.bounds) && sweptBoxesCollide(moving[m], d, obstacle.box)) return false;
    }
  }
  return true;
}

// A_1: the key is blocked by R_1 along every axis direction but its own (voxel faces in contact).
bool FrameDesigner::keyMovesAlongOnly(const Step& step) const {
  std::array<bool, 6> blocked{};
  for (int joint : frame_.beams[step.beam].joints) {
    const JointLabels& labels = labels_[joint];
    for (int v = 0; v < kJointVoxelCount; ++v) {
      if (labels[v] != step.beam) continue;
      for (int d = 0; d < 6; ++d) {
        const int w = stepVoxel(v, d);
        if (w >= 0 && labels[w] != step.beam) blocked[d] = true;
      }
    }
  }
  for (int d = 0; d < 6; ++d) {
    if (blocked[d] == (d == step.direction)) return false;
  }
  return true;
}

// A_i (i >= 2) with the candidate applied: the DBG of the key's axis is strongly connected without
// the key, the two others are strongly connected (paper Section 4.3, footnote 1), so every DBG is
// strongly connected or splits off the key alone (Section 3.2). The DBGs of +axis and -axis are
// reverses of one another: three graphs suffice.
bool FrameDesigner::restStronglyConnected(int candidate) {
  const int parts = static_cast<int>(path_.size()) + 1;  // path_ holds the candidate as its last step
  const int rest = parts - 1;
  partOfBeam_.assign(frame_.beams.size(), rest);
  for (size_t k = 0; k < path_.size(); ++k) partOfBeam_[path_[k].beam] = static_cast<int>(k);
  (void)candidate;
  // Joints where two parts meet: those of beams taken so far.
  std::vector<int> joints;
  for (const Step& step : path_) {
    for (int joint : frame_.beams[step.beam].joints) joints.push_back(joint);
  }
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
  const int keyAxis = path_[0].direction / 2;
  for (int axis = 0; axis < 3; ++axis) {
    const int stride = axis == 0 ? 1 : axis == 1 ? 3 : 9;
    const int skipped = axis == keyAxis ? 0 : -1;  // the part left out of the graph
    edges_.clear();
    for (int joint : joints) {
      const JointLabels& labels = labels_[joint];
      for (int v = 0; v < kJointVoxelCount; ++v) {
        const int c = axis == 0 ? v % 3 : axis == 1 ? v / 3 % 3 : v / 9;
        if (c == 2) continue;
        const int a = labels[v] == kFree ? rest : partOfBeam_[labels[v]];
        const int b = labels[v + stride] == kFree ? rest : partOfBeam_[labels[v + stride]];
        if (a != b && a != skipped && b != skipped) edges_.push_back({a, b});
      }
    }
    // Compressed adjacency both ways, then reach every non-key part from R forwards and backwards.
    offsets_.assign(parts + 1, 0);
    reverseOffsets_.assign(parts + 1, 0);
    for (const auto& [a, b] : edges_) {
      ++offsets_[a + 1];
      ++reverseOffsets_[b + 1];
    }
    for (int p = 0; p < parts; ++p) {
      offsets_[p + 1] += offsets_[p];
      reverseOffsets_[p + 1] += reverseOffsets_[p];
    }
    targets_.assign(edges_.size(), 0);
    reverseTargets_.assign(edges_.size(), 0);
    {
      std::vector<int> fill(offsets_.begin(), offsets_.end() - 1),
          reverseFill(reverseOffsets_.begin(), reverseOffsets_.end() - 1);
      for (const auto& [a, b] : edges_) {
        targets_[fill[a]++] = b;
        reverseTargets_[reverseFill[b]++] = a;
      }
    }
    for (int way = 0; way < 2; ++way) {
      const std::vector<int>& offsets = way == 0 ? offsets_ : reverseOffsets_;
      const std::vector<int>& targets = way == 0 ? targets_ : reverseTargets_;
      std::vector<char> seen(parts, 0);
      std::vector<int> stack{rest};
      seen[rest] = 1;
      int count = 1;
      while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        for (int e = offsets[p]; e < offsets[p + 1]; ++e) {
          if (!seen[targets[e]]) {
            seen[targets[e]] = 1;
            ++count;
            stack.push_back(targets[e]);
          }
        }
      }
      if (count != (skipped == 0 ? parts - 1 : parts)) return false;
    }
  }
  return true;
}

bool FrameDesigner::acceptable(const Step& step) {
  apply(step);
  const bool ok = path_.size() == 1 ? keyMovesAlongOnly(step) : restStronglyConnected(step.beam);
  undo(step);
  return ok;
}

// Up to `wanted` children for taking `beam` along `direction`: pairs of voxel sets at its two
// joints, smallest first, kept when the beam sweeps clear and A_i passes.
void FrameDesigner::childrenOfBeam(int beam, int direction, int wanted, std::vector<Step>& children) {
  ++work_;
  const std::vector<Obstacle> obstacles = corridorObstacles(beam, direction);
  // The body alone against everything that will not join the beam.
  {
    std::vector<Obstacle> fixed;
    for (const Obstacle& o : obstacles) {
      const bool ownFree =
          o.joint >= 0 && (o.joint == frame_.beams[beam].joints[0] || o.joint == frame_.beams[beam].joints[1]);
      if (!ownFree) fixed.push_back(o);
    }
    if (!sweepClear(beam, direction, {0, 0}, fixed)) return;
  }
  const std::vector<Mask> first = jointOptions(beam, 0, direction);
  const std::vector<Mask> second = jointOptions(beam, 1, direction);
  if (first.empty() || second.empty()) return;
  std::vector<std::pair<uint64_t, std::array<Mask, 2>>> pairs;
  for (Mask a : first) {
    for (Mask b : second) pairs.push_back({(uint64_t(popCount(a) + popCount(b)) << 40) + (nextRandom() >> 24), {a, b}});
  }
  std::sort(pairs.begin(), pairs.end());
  int tried = 0, found = 0;
  for (const auto& [rank, taken] : pairs) {
    if (++tried > kPairsPerDirection || found >= wanted) break;
    ++work_;
    const Step step{beam, direction, taken};
    if (!sweepClear(beam, direction, taken, obstacles)) continue;
    if (!acceptable(step)) continue;
    children.push_back(step);
    ++found;
  }
}

std::vector<Step> FrameDesigner::childrenOfCurrent() {
  const int beams = static_cast<int>(frame_.beams.size());
  // The parts-graph of R: beams sharing a joint.
  std::vector<int> rest, index(beams, -1);
  for (int b = 0; b < beams; ++b) {
    if (inRest(b)) {
      index[b] = static_cast<int>(rest.size());
      rest.push_back(b);
    }
  }
  std::vector<std::pair<int, int>> edges;
  std::vector<bool> touchesTaken(beams, false);
  for (const std::vector<int>& atJoint : layout_.beamsAtJoint) {
    bool taken = false;
    for (int b : atJoint) taken = taken || !inRest(b);
    for (size_t x = 0; x < atJoint.size(); ++x) {
      if (!inRest(atJoint[x])) continue;
      touchesTaken[atJoint[x]] = touchesTaken[atJoint[x]] || taken;
      for (size_t y = x + 1; y < atJoint.size(); ++y) {
        if (!inRest(atJoint[y])) continue;
        edges.push_back({index[atJoint[x]], index[atJoint[y]]});
      }
    }
  }
  std::vector<bool> isCut(beams, false);
  for (int i : findCutPoints(static_cast<int>(rest.size()), edges)) isCut[rest[i]] = true;
  struct Candidate {
    int beam;
    double sweep;   // x + y + z of its two joints
    double height;  // y of its two joints
    uint64_t tie;
  };
  // The look-ahead (see the top): joints holding all but one of R's beams; taking a beam of R
  // that is not at such a joint would leave R_i a star there.
  const int restCount = static_cast<int>(rest.size());
  std::vector<int> restAtJoint(frame_.joints.size(), 0);
  for (int b : rest) {
    for (int joint : frame_.beams[b].joints) ++restAtJoint[joint];
  }
  std::vector<int> crowded;  // joints where R_i would be a star of restCount - 1 >= 3 beams
  for (size_t j = 0; j < restAtJoint.size(); ++j) {
    if (restCount - 1 >= 3 && restAtJoint[j] >= restCount - 1) crowded.push_back(static_cast<int>(j));
  }
  auto leavesStar = [&](int beam) {
    for (int joint : crowded) {
      const bool here = frame_.beams[beam].joints[0] == joint || frame_.beams[beam].joints[1] == joint;
      if (restAtJoint[joint] - (here ? 1 : 0) == restCount - 1) return true;
    }
    return false;
  };
  std::vector<Candidate> candidates;
  for (int b : rest) {
    if (isCut[b] || (!path_.empty() && !touchesTaken[b]) || leavesStar(b)) continue;
    const Vec3& p = frame_.joints[frame_.beams[b].joints[0]].position;
    const Vec3& q = frame_.joints[frame_.beams[b].joints[1]].position;
    candidates.push_back({b, (p[0] + q[0]) + (p[1] + q[1]) + (p[2] + q[2]), p[1] + q[1], nextRandom()});
  }
  // The sweep (see the top): the front of taken beams moves along the diagonal, so R_i stays a
  // compact corner block (Section 4.1's compactness of R) and ends at the corner of fewest beams
  // per joint, not as a path through crowded joints; the key, the first of the sweep, is at the
  // top (Section 4.2: it leaves upwards).
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.sweep != y.sweep) return x.sweep > y.sweep;
    if (x.height != y.height) return x.height > y.height;
    return x.tie < y.tie;
  });
  // More keys than later children: a key whose subtree dies costs little, the whole search less.
  const int wanted = path_.empty() ? 6 * width_ : width_;
  std::vector<Step> children;
  for (const Candidate& candidate : candidates) {
    // The key leaves upwards when it can (paper Section 4.2: gravity keeps it in); other
    // directions in a seeded order.
    std::array<int, 6> directions{2, 0, 1, 3, 4, 5};
    for (int k = 5; k > (path_.empty() ? 1 : 0); --k) {
      const int j = (path_.empty() ? 1 : 0) + static_cast<int>(nextRandom() % (k - (path_.empty() ? 1 : 0) + 1));
      std::swap(directions[k], directions[j]);
    }
    for (int direction : directions) {
      if (static_cast<int>(children.size()) >= wanted) return children;
      childrenOfBeam(candidate.beam, direction, 1, children);
    }
  }
  return children;
}

}  // namespace desia::frame_design
