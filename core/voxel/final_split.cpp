// SPDX-License-Identifier: GPL-3.0-or-later
// The last split of the construction tree (Algorithm 1, paper Section 4.1, with two parts left):
// R_(N-2) becomes P_(N-1) and the last remainder R_(N-1). The graph designs of Section 4.3
// (Fig. 7) are a recipe for *some* valid splits, sampled at random; on the few voxels left at the
// deep end they often miss every split there is, and the search cannot tell "none sampled" from
// "none exists". Here the requirements themselves are searched for: every face-connected P_(N-1)
// of an allowed size is enumerated once (Wernicke's ESU scheme over bit sets, an explicit stack),
// cheap necessary conditions drop most of them, and the rest get the exact check of every other
// child (acceptsSplit). Work is counted, never timed, so the result depends on the input only.
#include <array>
#include <cstdint>
#include <vector>

#include "voxel/candidate_checks.h"
#include "voxel/design_internals.h"
#include "voxel/final_split.h"

namespace desia::design {
namespace {

using Mask = uint64_t;

Mask bit(int k) { return Mask(1) << k; }
int lowestBit(Mask m) { return __builtin_ctzll(m); }
int bitCount(Mask m) { return __builtin_popcountll(m); }

// R_(N-2) in local numbering (at most 64 voxels): adjacency, the neighbour along each of the six
// axis steps, and the voxels whose neighbour along a step is an earlier part (blocked there by it).
struct LocalRemainder {
  std::vector<int64_t> voxels;  // local -> grid index, ascending
  std::vector<Mask> adjacent;
  std::array<std::vector<int>, 6> along;  // local neighbour along kAxisSteps[s], or -1
  std::array<Mask, 6> blockedByEarlier{};
  std::vector<Mask> groups;  // appearance groups met in R_(N-2), as local masks
  Mask all = 0;
};

bool describeRemainder(const VoxelGrid& grid, int remainder, const DesignContext& context, LocalRemainder* local) {
  std::vector<int> localOf(static_cast<size_t>(grid.voxelCount()), -1);
  for (int64_t v = 0; v < grid.voxelCount(); ++v) {
    if (grid.labelAt(v) != remainder) continue;
    if (local->voxels.size() == 64) return false;
    localOf[v] = static_cast<int>(local->voxels.size());
    local->voxels.push_back(v);
  }
  const int n = static_cast<int>(local->voxels.size());
  local->all = n == 64 ? ~Mask(0) : bit(n) - 1;
  local->adjacent.assign(n, 0);
  for (int s = 0; s < 6; ++s) local->along[s].assign(n, -1);
  std::vector<Mask> groupMasks(context.groups.size(), 0);
  for (int k = 0; k < n; ++k) {
    const int64_t v = local->voxels[k];
    for (int s = 0; s < 6; ++s) {
      const int64_t w = neighbourIndex(grid, v, kAxisSteps[s]);
      const int label = w >= 0 ? grid.labelAt(w) : 0;
      if (label == remainder) {
        local->along[s][k] = localOf[w];
        local->adjacent[k] |= bit(localOf[w]);
      } else if (label > 0) {
        local->blockedByEarlier[s] |= bit(k);
      }
    }
    if (!context.groupOf.empty() && context.groupOf[v] >= 0) groupMasks[context.groupOf[v]] |= bit(k);
  }
  for (Mask g : groupMasks) {
    if (bitCount(g) > 1) local->groups.push_back(g);
  }
  return true;
}

// The voxels right in front of `set` along step s (local, inside R_(N-2)).
Mask frontOf(const LocalRemainder& local, Mask set, int s) {
  Mask front = 0;
  for (Mask m = set; m != 0; m &= m - 1) {
    const int w = local.along[s][lowestBit(m)];
    if (w >= 0) front |= bit(w);
  }
  return front & ~set;
}

bool connectedMask(const LocalRemainder& local, Mask set) {
  if (set == 0) return false;
  Mask reached = bit(lowestBit(set)), frontier = reached;
  while (frontier != 0) {
    Mask next = 0;
    for (Mask m = frontier; m != 0; m &= m - 1) next |= local.adjacent[lowestBit(m)];
    frontier = next & set & ~reached;
    reached |= frontier;
  }
  return reached == set;
}

// Necessary conditions for [.., P, R] to be interlocking with part 1 as key and P to leave [P, R]
// (Section 4.1 ii, iii), all read from the masks:
//  - neither P nor R is free alone along any of the six steps (a part free alone is a sink or a
//    source of its own in that axis's DBG, which only the key may be);
//  - P can take a first step out of [P, R] along some axis (a removal path starts with one);
//  - R is one piece, and each appearance group lies on one side.
bool passesNecessaryConditions(const LocalRemainder& local, Mask part) {
  const Mask rest = local.all & ~part;
  bool canStep = false;
  for (int s = 0; s < 6; ++s) {
    const Mask partFront = frontOf(local, part, s);
    if ((part & local.blockedByEarlier[s]) == 0 && (partFront & rest) == 0) return false;
    if ((rest & local.blockedByEarlier[s]) == 0 && (frontOf(local, rest, s) & part) == 0) return false;
    canStep = canStep || (partFront & rest) == 0;
  }
  if (!canStep) return false;
  for (Mask g : local.groups) {
    if ((g & part) != 0 && (g & part) != g) return false;
  }
  return connectedMask(local, rest);
}

// One ESU frame: the connected set grown so far and the voxels it may still take (each connected
// set is reached once: from its lowest voxel, extensions only by higher exclusive neighbours).
struct Frame {
  Mask set;
  Mask extension;
};

class SplitEnumerator {
 public:
  SplitEnumerator(const LocalRemainder& local, const SizeWindow& size, const FinalSplitLimits& limits)
      : local_(local), size_(size), limits_(limits) {}

  // Calls accept(mask) for each P passing the necessary conditions, in a fixed order, until it
  // returns false or a limit is reached.
  template <typename Accept>
  void run(Accept accept, FinalSplitStats* stats) {
    const int n = static_cast<int>(local_.voxels.size());
    for (int root = 0; root < n; ++root) {
      const Mask higher = root == 63 ? 0 : ~(bit(root + 1) - 1) & local_.all;  // no shift by 64
      std::vector<Frame> stack{{bit(root), local_.adjacent[root] & higher}};
      if (!visit(bit(root), accept, stats)) return;
      while (!stack.empty()) {
        Frame& top = stack.back();
        if (top.extension == 0 || bitCount(top.set) >= size_.max) {
          stack.pop_back();
          continue;
        }
        const int w = lowestBit(top.extension);
        top.extension &= top.extension - 1;
        const Mask grown = top.set | bit(w);
        const Mask exclusive = local_.adjacent[w] & ~top.set & ~neighbourhood(top.set) & higher;
        const Mask extension = top.extension | exclusive;
        if (!visit(grown, accept, stats)) return;
        stack.push_back({grown, extension});
      }
    }
  }

 private:
  Mask neighbourhood(Mask set) const {
    Mask around = 0;
    for (Mask m = set; m != 0; m &= m - 1) around |= local_.adjacent[lowestBit(m)];
    return around;
  }

  template <typename Accept>
  bool visit(Mask set, Accept& accept, FinalSplitStats* stats) {
    if (++stats->setsVisited > limits_.maxSets) {
      stats->exhausted = false;
      return false;
    }
    const int count = bitCount(set);
    if (count < size_.min || count > size_.max || !passesNecessaryConditions(local_, set)) return true;
    if (stats->exactChecks >= limits_.maxExactChecks) {
      stats->exhausted = false;
      return false;
    }
    ++stats->exactChecks;
    return accept(set);
  }

  const LocalRemainder& local_;
  const SizeWindow size_;
  const FinalSplitLimits limits_;
};

}  // namespace

namespace {

// Does R_i (label `remainder` in `grid`, just split off) admit a last split (the look-ahead when
// three parts are left)? Only a split found counts: a search cut short by its limits says no.
bool admitsFinalSplit(const VoxelGrid& grid, int remainder, const DesignContext& context, const FinalSplitLimits& limits) {
  int64_t voxels = 0;
  for (int v : grid.labels()) voxels += v == remainder ? 1 : 0;
  const SizeWindow size = partSizeWindow(voxels, 2, partSizeBounds(context.options));
  FinalSplitLimits one = limits;
  one.maxSplits = 1;
  return !enumerateSplits(grid, remainder, context, size, one, false).empty();
}

}  // namespace

std::vector<Candidate> enumerateSplits(const VoxelGrid& grid, int remainder, const DesignContext& context,
                                       const SizeWindow& size, const FinalSplitLimits& limits, bool lookAheadFinal,
                                       FinalSplitStats* stats) {
  FinalSplitStats ownStats;
  FinalSplitStats& s = stats ? *stats : ownStats;
  s = FinalSplitStats{};
  LocalRemainder local;
  std::vector<Candidate> found;
  if (size.empty() || !describeRemainder(grid, remainder, context, &local)) {
    s.exhausted = false;
    return found;
  }
  const int n = static_cast<int>(local.voxels.size());
  const SizeWindow window{size.min, std::min(size.max, n - 1)};
  VoxelGrid work = grid;
  SplitEnumerator(local, window, limits).run([&](Mask part) {
    Candidate candidate;
    for (Mask m = part; m != 0; m &= m - 1) candidate.partVoxels.push_back(local.voxels[lowestBit(m)]);
    applyCandidate(work, remainder, candidate);
    // Look-ahead (three parts left): R_(N-2) must itself split into P_(N-1) and R_(N-1).
    if (acceptsSplit(work, remainder, context.options.keyDirection) &&
        (!lookAheadFinal || admitsFinalSplit(work, remainder + 1, context, limits))) {
      candidate.rankKey = rankingKey(work, remainder, remainder + 1, context.options.ranking);
      found.push_back(std::move(candidate));
    }
    undoCandidate(work, remainder);
    return static_cast<int>(found.size()) < limits.maxSplits;
  }, &s);
  s.splitsFound = static_cast<int>(found.size());
  return found;
}

}  // namespace desia::design
