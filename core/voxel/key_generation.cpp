// SPDX-License-Identifier: GPL-3.0-or-later
// Key generation (paper Section 4.2, after Song et al. 2012): a seed voxel on the surface facing
// the key direction, an anchor voxel whose remainder neighbours block every other direction
// (blocking), the voxels in front of the key absorbed (mobility), then growth by columns to the
// target size (expansion). Candidates are ranked like every other level.
#include <algorithm>
#include <set>

#include "voxel/candidate_checks.h"
#include "voxel/design_internals.h"
#include "voxel/split_evaluation.h"

namespace desia::design {
namespace {

constexpr int kSeedsTried = 8;
constexpr int kAnchorsPerSeed = 12;

int axisOf(const Int3& d) { return d.x != 0 ? 0 : (d.y != 0 ? 1 : 2); }
int along(const Int3& c, const Int3& d) { return c.x * d.x + c.y * d.y + c.z * d.z; }

// Remainder voxels with nothing of the remainder right in front along d: where a key can start.
std::vector<int64_t> seedVoxels(const VoxelGrid& grid, int remainder, const Int3& d, const std::vector<double>& access) {
  std::vector<int64_t> seeds;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != remainder) continue;
    const int64_t front = neighbourIndex(grid, i, d);
    if (front < 0 || grid.labelAt(front) != remainder) seeds.push_back(i);
  }
  // Furthest along d first (the top for an upward key), then the most exposed.
  std::stable_sort(seeds.begin(), seeds.end(), [&](int64_t a, int64_t b) {
    const int pa = along(grid.coordinates(a), d), pb = along(grid.coordinates(b), d);
    return pa != pb ? pa > pb : access[a] < access[b];
  });
  if (seeds.size() > static_cast<size_t>(kSeedsTried)) seeds.resize(kSeedsTried);
  return seeds;
}

// Voxels whose neighbours across every axis but d's, and behind along -d, are in the remainder:
// with those neighbours kept in R1, the key is blocked in all directions but d.
std::vector<int64_t> anchorVoxels(const VoxelGrid& grid, int remainder, const Int3& d) {
  const int keyAxis = axisOf(d);
  std::vector<int64_t> anchors;
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) != remainder) continue;
    bool ok = true;
    for (int axis = 0; axis < 3 && ok; ++axis) {
      for (int sign : {1, -1}) {
        if (axis == keyAxis && sign * along(axisStep(axis), d) > 0) continue;  // the free side
        const Int3 step{axisStep(axis).x * sign, axisStep(axis).y * sign, axisStep(axis).z * sign};
        const int64_t j = neighbourIndex(grid, i, step);
        ok = ok && j >= 0 && grid.labelAt(j) == remainder;
      }
    }
    if (ok) anchors.push_back(i);
  }
  return anchors;
}

// Blocking pairs for a key started at `seed`: either one anchor voxel whose neighbours block every
// direction but d (compact keys, as Song et al. 2012), or, for thin shapes where no such voxel
// exists, one pair per blocked direction s: a key voxel p with p + s kept in the remainder.
bool forceBlocking(const VoxelGrid& grid, const Int3& d, int64_t anchor, PartBuilder& builder) {
  const int keyAxis = axisOf(d);
  const Int3 a = grid.coordinates(anchor);
  if (!builder.forcePart(anchor)) return false;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {1, -1}) {
      if (axis == keyAxis && sign * along(axisStep(axis), d) > 0) continue;
      const Int3 step{axisStep(axis).x * sign, axisStep(axis).y * sign, axisStep(axis).z * sign};
      if (!builder.forceRemainder(grid.index(a.x + step.x, a.y + step.y, a.z + step.z))) return false;
    }
  }
  return true;
}

bool forceBlockingPairs(const VoxelGrid& grid, int remainder, const Int3& d, const Int3& seed, std::mt19937_64& random,
                        PartBuilder& builder) {
  const int keyAxis = axisOf(d);
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {1, -1}) {
      if (axis == keyAxis && sign * along(axisStep(axis), d) > 0) continue;
      const Int3 step{axisStep(axis).x * sign, axisStep(axis).y * sign, axisStep(axis).z * sign};
      // The usable pairs nearest to the seed; pick one of the three nearest at random.
      std::vector<std::pair<int, int64_t>> pairs;
      for (int64_t v = 0; v < grid.voxelCount(); ++v) {
        if (grid.labelAt(v) != remainder || !builder.canBePart(v)) continue;
        const int64_t w = neighbourIndex(grid, v, step);
        if (w < 0 || grid.labelAt(w) != remainder || !builder.canBeRemainder(w)) continue;
        pairs.push_back({manhattan(grid.coordinates(v), seed), v});
      }
      if (pairs.empty()) return false;
      const size_t keep = std::min<size_t>(3, pairs.size());
      std::partial_sort(pairs.begin(), pairs.begin() + keep, pairs.end());
      const int64_t p = pairs[random() % keep].second;
      if (!builder.forcePart(p) || !builder.forceRemainder(neighbourIndex(grid, p, step))) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<Candidate> generateKeyCandidates(const VoxelGrid& grid, DesignContext& context, int targetSize) {
  constexpr int remainder = 1;
  const Int3 d = context.options.keyDirection;
  SplitEvaluator evaluator(grid, remainder, d, context.options.ranking);  // checks and ranking, per candidate
  const std::vector<double>& access = evaluator.access();
  // The target size up to a quarter more, within what the size bounds leave for a key whose R1
  // can still be split into the N - 1 parts to come (partSizeWindow).
  const SizeWindow allowed = partSizeWindow(context.shapeVoxels, context.options.parts, partSizeBounds(context.options));
  if (allowed.empty()) return {};
  const int heuristicMin = std::max(2, targetSize);
  const SizeWindow size = clampInto({heuristicMin, std::max(heuristicMin, targetSize + targetSize / 4)}, allowed);
  const int minSize = size.min, maxSize = size.max;
  std::vector<Candidate> candidates;
  std::set<std::vector<int64_t>> seen;
  auto consider = [&](PartBuilder& builder) {
    if (!builder.connect() || !builder.clearPathAlong(d) || !builder.growTo(minSize, maxSize, d, context.random)) return;
    Candidate candidate{builder.sortedPartVoxels(), 0};
    if (!seen.insert(candidate.partVoxels).second) return;
    if (evaluator.accepts(candidate)) {
      candidate.rankKey = evaluator.rankKey(candidate);
      candidates.push_back(std::move(candidate));
    }
  };
  const std::vector<int64_t> anchors = anchorVoxels(grid, remainder, d);
  PartBuilder builder(grid, remainder, context, access);  // reset for every attempt
  for (int64_t seed : seedVoxels(grid, remainder, d, access)) {
    const Int3 s = grid.coordinates(seed);
    std::vector<int64_t> near = anchors;
    std::stable_sort(near.begin(), near.end(), [&](int64_t a, int64_t b) {
      return manhattan(grid.coordinates(a), s) < manhattan(grid.coordinates(b), s);
    });
    if (near.size() > static_cast<size_t>(kAnchorsPerSeed)) near.resize(kAnchorsPerSeed);
    for (int64_t anchor : near) {
      builder.reset();
      if (builder.forcePart(seed) && forceBlocking(grid, d, anchor, builder)) consider(builder);
    }
    for (int variant = 0; variant < kAnchorsPerSeed / 2; ++variant) {
      builder.reset();
      if (builder.forcePart(seed) && forceBlockingPairs(grid, remainder, d, s, context.random, builder)) consider(builder);
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.rankKey < y.rankKey; });
  if (candidates.size() > static_cast<size_t>(context.options.candidates)) candidates.resize(context.options.candidates);
  return candidates;
}

}  // namespace desia::design
