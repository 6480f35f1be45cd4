// SPDX-License-Identifier: GPL-3.0-or-later
// Generation of P_i and R_i from R_(i-1) (paper Section 4.3). For each base DBG (one per axis)
// a graph design is chosen that keeps the DBG strongly connected (Fig. 7):
//   K = 2: P_i -> R_i -> P_i, an internal blocking pair in each direction;
//   K = 1: P_i -> R_i -> P_out ~> P_in -> P_i (or the mirror), one internal pair and two external
//          contacts inherited from R_(i-1), with P_out reaching P_in without passing R_(i-1);
//   K = 0: P_i -> P_out ~> P_in -> R_i -> P'_out ~> P'_in -> P_i, external contacts only.
// The removal direction of P_i rules out the internal edge that would block it, and at least one
// DBG has K < 2 (disassemblability). The design is then realized (Section 4.3 i-v): contacts and
// blocking pairs become voxels forced into P_i or R_i, P_i's voxels are joined by shortest paths,
// cleared along its removal direction and grown to size. Every realized candidate is checked
// exactly (candidate_checks.h) before it joins the construction tree.
#include <algorithm>
#include <random>
#include <set>
#include <type_traits>

#include "desia/analysis.h"
#include "voxel/candidate_checks.h"
#include "voxel/final_split.h"
#include "voxel/design_internals.h"
#include "voxel/graph_design.h"
#include "voxel/split_evaluation.h"

namespace desia::design {
namespace {


}  // namespace

PartReachability::PartReachability(const DirectedGraph& graph, int remainder)
    : graph_(&graph), remainder_(remainder), rows_(static_cast<size_t>(std::max(0, remainder))) {}

bool PartReachability::operator()(int from, int to) const {
  std::vector<bool>& row = rows_[from];
  if (row.empty()) {
    // Depth-first from `from` over G(+e), never entering R_(i-1) (labels are graph nodes + 1).
    row.assign(static_cast<size_t>(remainder_), false);
    std::vector<int> stack{from};
    row[from] = true;
    while (!stack.empty()) {
      const int label = stack.back();
      stack.pop_back();
      for (int next : graph_->successors(label - 1)) {
        const int nextLabel = next + 1;
        if (nextLabel == remainder_ || row[nextLabel]) continue;
        row[nextLabel] = true;
        stack.push_back(nextLabel);
      }
    }
  }
  return row[to];
}

AxisInfo describeAxis(const VoxelGrid& grid, int remainder, int axis, const DirectedGraph& graph, bool recursive) {
  AxisInfo info;
  const Int3 e = axisStep(axis), back{-e.x, -e.y, -e.z};
  for (int64_t v = 0; v < grid.voxelCount(); ++v) {
    if (grid.labelAt(v) != remainder) continue;
    const int64_t f = neighbourIndex(grid, v, e), b = neighbourIndex(grid, v, back);
    const int front = f >= 0 ? grid.labelAt(f) : 0, behind = b >= 0 ? grid.labelAt(b) : 0;
    // In recursive mode (Fig. 11) only P_(i-1) may close the cycles.
    auto usable = [&](int label) { return label > 0 && label != remainder && (!recursive || label == remainder - 1); };
    auto record = [&](auto& list, std::vector<int32_t>& index, const auto& entry) {
      if (index.empty()) index.assign(static_cast<size_t>(grid.voxelCount()), -1);
      index[v] = static_cast<int32_t>(list.size());
      list.push_back(entry);
    };
    if (usable(front)) record(info.remainderBlockedBy, info.remainderBlockedByIndex, ExternalContact{v, front});
    if (usable(behind)) record(info.blockingPart, info.blockingPartIndex, ExternalContact{v, behind});
    if (front == remainder) record(info.pairForward, info.pairForwardIndex, v);
    if (behind == remainder) record(info.pairBackward, info.pairBackwardIndex, v);
    if (front == remainder && behind == remainder) record(info.pairBoth, info.pairBothIndex, v);
  }
  info.reaches = PartReachability(graph, remainder);
  return info;
}

namespace {

// Calls visit(voxel) for every grid voxel at Manhattan distance r from `center`.
template <typename Visit>
void forEachAtDistance(const VoxelGrid& grid, const Int3& center, int r, Visit visit) {
  for (int dx = -r; dx <= r; ++dx) {
    const int x = center.x + dx;
    if (x < 0 || x >= grid.nx()) continue;
    const int restX = r - std::abs(dx);
    for (int dy = -restX; dy <= restX; ++dy) {
      const int y = center.y + dy;
      if (y < 0 || y >= grid.ny()) continue;
      const int restY = restX - std::abs(dy);
      for (int dz : {-restY, restY}) {
        const int z = center.z + dz;
        if (z >= 0 && z < grid.nz()) visit(grid.index(x, y, z));
        if (restY == 0) break;
      }
    }
  }
}

template <typename T>
int64_t entryVoxel(const T& entry) {
  if constexpr (std::is_same_v<T, ExternalContact>) {
    return entry.voxel;
  } else {
    return entry;
  }
}

// One of the `spread` entries of `list` nearest to `seed` among those `usable` accepts, chosen at
// random (ties by voxel index); null if there is none. Searches shells of growing Manhattan
// distance around the seed, so the cost follows the neighbourhood, not the list (a 35^3 cube has
// lists of tens of thousands of voxels). Once the shells have visited more voxels than the list
// holds (few or no usable entries near the seed: a small remainder late in the search, or a pick
// that no entry satisfies), the list itself is scanned instead: the three nearest are the same
// either way, so both give the same pick, but a failed pick then costs the list, not the grid.
template <typename T, typename Usable>
const T* nearestPick(const std::vector<T>& list, const std::vector<int32_t>& indexOf, const VoxelGrid& grid,
                     const Int3& seed, Usable usable, std::mt19937_64& random) {
  constexpr size_t kSpread = 3;
  if (list.empty()) return nullptr;
  std::vector<std::pair<int, int64_t>> found;  // (distance, voxel)
  const int maxRadius = grid.nx() + grid.ny() + grid.nz();
  size_t visited = 0;
  bool scanList = false;
  for (int r = 0; r <= maxRadius && found.size() < kSpread; ++r) {
    if (visited > list.size()) {
      scanList = true;
      break;
    }
    forEachAtDistance(grid, seed, r, [&](int64_t v) {
      ++visited;
      const int32_t k = indexOf[v];
      if (k >= 0 && usable(list[k])) found.push_back({r, v});
    });
  }
  if (scanList) {
    found.clear();
    for (const T& entry : list) {
      if (usable(entry)) {
        const int64_t v = entryVoxel(entry);
        found.push_back({manhattan(grid.coordinates(v), seed), v});
      }
    }
  }
  if (found.empty()) return nullptr;
  const size_t keep = std::min(kSpread, found.size());
  std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(keep), found.end());
  return &list[indexOf[found[random() % keep].second]];
}

// Two external contacts that close a cycle through earlier parts: one towards P_out (from
// `outList`, taken by the side `outSide`), one from P_in (from `inList`, taken by `inSide`), with
// P_out reaching P_in in G(+e) without passing R_(i-1).
template <typename OutUsable, typename InUsable>
bool pickCycleContacts(const AxisInfo& info, const VoxelGrid& grid, const Int3& seed, std::mt19937_64& random,
                       OutUsable outUsable, InUsable inUsable, ExternalContact* out, ExternalContact* in) {
  const ExternalContact* first = nearestPick(info.remainderBlockedBy, info.remainderBlockedByIndex, grid, seed,
                                             [&](const ExternalContact& c) { return outUsable(c.voxel); }, random);
  if (!first) return false;
  const ExternalContact* second = nearestPick(info.blockingPart, info.blockingPartIndex, grid, seed, [&](const ExternalContact& c) {
    return inUsable(c.voxel) && info.reaches(first->part, c.part);
  }, random);
  if (!second) return false;
  *out = *first;
  *in = *second;
  return true;
}

}  // namespace

// Designs allowed on axis `axis` when P_i leaves along `removal` (Section 4.3: no internal edge
// may block the removal).
std::vector<AxisDesign> allowedDesigns(int axis, const Int3& removal) {
  const int along = axis == 0 ? removal.x : (axis == 1 ? removal.y : removal.z);
  if (along > 0) return {AxisDesign::NoInternal, AxisDesign::OneInternalRemainderToPart};
  if (along < 0) return {AxisDesign::NoInternal, AxisDesign::OneInternalPartToRemainder};
  return {AxisDesign::TwoInternal, AxisDesign::OneInternalPartToRemainder, AxisDesign::OneInternalRemainderToPart,
          AxisDesign::NoInternal};
}

// Forces the voxels that realize one axis design (Section 4.3 ii and iii). Every pick respects
// what earlier picks forced, so designs fail only when the geometry really cannot host them.
bool realizeAxis(AxisDesign design, int axis, const AxisInfo& info, const VoxelGrid& grid, const Int3& seed,
                 std::mt19937_64& random, PartBuilder& builder) {
  const Int3 e = axisStep(axis);
  auto shifted = [&](int64_t v, int sign) {
    const Int3 c = grid.coordinates(v);
    return grid.index(c.x + sign * e.x, c.y + sign * e.y, c.z + sign * e.z);
  };
  auto toPart = [&](int64_t v) { return builder.canBePart(v); };
  auto toRemainder = [&](int64_t v) { return builder.canBeRemainder(v); };
  switch (design) {
    case AxisDesign::TwoInternal: {
      const int64_t* anchor = nearestPick(info.pairBoth, info.pairBothIndex, grid, seed, [&](int64_t v) {
        return toPart(v) && toRemainder(shifted(v, 1)) && toRemainder(shifted(v, -1));
      }, random);
      return anchor && builder.forcePart(*anchor) && builder.forceRemainder(shifted(*anchor, 1)) &&
             builder.forceRemainder(shifted(*anchor, -1));
    }
    case AxisDesign::OneInternalPartToRemainder: {
      // P -> R -> P_out ~> P_in -> P: the R side takes the contact with P_out, P the one with P_in.
      const int64_t* anchor = nearestPick(info.pairForward, info.pairForwardIndex, grid, seed,
                                          [&](int64_t v) { return toPart(v) && toRemainder(shifted(v, 1)); }, random);
      if (!anchor || !builder.forcePart(*anchor) || !builder.forceRemainder(shifted(*anchor, 1))) return false;
      ExternalContact out{}, in{};
      return pickCycleContacts(info, grid, seed, random, toRemainder, toPart, &out, &in) &&
             builder.forceRemainder(out.voxel) && builder.forcePart(in.voxel);
    }
    case AxisDesign::OneInternalRemainderToPart: {
      // R -> P -> P_out ~> P_in -> R: P takes the contact with P_out, R the one with P_in.
      const int64_t* anchor = nearestPick(info.pairBackward, info.pairBackwardIndex, grid, seed,
                                          [&](int64_t v) { return toPart(v) && toRemainder(shifted(v, -1)); }, random);
      if (!anchor || !builder.forcePart(*anchor) || !builder.forceRemainder(shifted(*anchor, -1))) return false;
      ExternalContact out{}, in{};
      return pickCycleContacts(info, grid, seed, random, toPart, toRemainder, &out, &in) &&
             builder.forcePart(out.voxel) && builder.forceRemainder(in.voxel);
    }
    case AxisDesign::NoInternal: {
      // P -> P_out ~> P_in -> R -> P'_out ~> P'_in -> P
      ExternalContact out{}, in{}, out2{}, in2{};
      if (!pickCycleContacts(info, grid, seed, random, toPart, toRemainder, &out, &in) || !builder.forcePart(out.voxel) ||
          !builder.forceRemainder(in.voxel)) {
        return false;
      }
      return pickCycleContacts(info, grid, seed, random, toRemainder, toPart, &out2, &in2) &&
             builder.forceRemainder(out2.voxel) && builder.forcePart(in2.voxel);
    }
  }
  return false;
}

namespace {

// Seeds for P_i: exposed remainder voxels (low accessibility), where parts come off easily.
std::vector<int64_t> seedPool(const VoxelGrid& grid, int remainder, const std::vector<double>& access) {
  std::vector<int64_t> pool;
  for (int64_t v = 0; v < grid.voxelCount(); ++v) {
    if (grid.labelAt(v) == remainder) pool.push_back(v);
  }
  std::stable_sort(pool.begin(), pool.end(), [&](int64_t a, int64_t b) { return access[a] < access[b]; });
  pool.resize(std::max<size_t>(1, pool.size() / 3));
  return pool;
}

// Fisher-Yates with raw engine outputs: std::shuffle's algorithm differs between standard
// libraries (libstdc++ natively, libc++ in WebAssembly), which would break native/wasm equality.
template <typename T>
void shuffleDeterministically(std::vector<T>& items, std::mt19937_64& random) {
  for (size_t k = items.size(); k > 1; --k) std::swap(items[k - 1], items[random() % k]);
}

// P_i's removal direction: one along which its seed is exposed (nothing of the remainder right in
// front), chosen at random; any axis when the seed is enclosed.
Int3 removalDirectionFor(const VoxelGrid& grid, int remainder, int64_t seed, std::mt19937_64& random) {
  std::vector<Int3> exposed;
  for (const Int3& step : kAxisSteps) {
    const int64_t front = neighbourIndex(grid, seed, step);
    if (front < 0 || grid.labelAt(front) != remainder) exposed.push_back(step);
  }
  if (exposed.empty()) return kAxisSteps[random() % 6];
  return exposed[random() % exposed.size()];
}

// The largest remainder the enumeration of the deep end takes (final_split.h: a 64-bit mask).
constexpr int64_t kEnumerableVoxels = 64;

// Parts still to place (after this one, the last remainder included) up to which children are
// enumerated, not sampled: the last three splits.
constexpr int kEnumeratedPartsStillToPlace = 3;

// The deep end of Algorithm 1 (Section 4.1): for the last three splits, when the random graph
// designs of Fig. 7 found no child and R_(i-1) has at most 64 voxels, the splits are enumerated
// (final_split.h). Near the end most nodes get no child from their random attempts, and random
// attempts cannot tell bad luck from a dead node; the enumeration can: with three parts left such
// a node is mostly dead (no split leaves a remainder with a last split of its own), while with
// four parts left it finds children where the random designs found none. With three parts left a child
// also needs a last split of its own (look-ahead: a child without one is a dead branch the search
// would otherwise descend into). Returns false when the enumeration was cut short by its limits
// without a child, or did not run.
bool enumeratedChildren(const VoxelGrid& grid, int remainder, const DesignContext& context, const SizeWindow& allowed,
                        int partsStillToPlace, std::vector<Candidate>* children) {
  // Recursive mode (Fig. 11) is the baseline of cycles through P_(i-1) only, which the
  // enumeration (any interlocking split) does not respect: it keeps its random designs.
  if (partsStillToPlace > kEnumeratedPartsStillToPlace || context.options.mode == DesignMode::Recursive) return false;
  FinalSplitLimits limits;
  limits.maxSplits = context.options.candidates;
  FinalSplitStats stats;
  *children = enumerateSplits(grid, remainder, context, allowed, limits, partsStillToPlace == 2, &stats);
  if (children->empty() && !stats.exhausted) return false;
  std::stable_sort(children->begin(), children->end(),
                   [](const Candidate& x, const Candidate& y) { return x.rankKey < y.rankKey; });
  return true;
}

// A part that cuts pieces off the remainder takes them in, when they fit within `maxSize` with
// what clearing their way out adds (Section 4.1 requires R_i connected). Otherwise most candidates
// of a large shape are refused for cutting R apart, and R thins to one-voxel strands over the
// whole shape, which any part cuts (a strand's end hangs off the part). Taking such pieces in
// turns those candidates into children and eats the strands.
bool absorbPiecesCutOff(SplitEvaluator& evaluator, int maxSize, const Int3& removal, PartBuilder& builder) {
  const int room = maxSize - builder.size();
  if (room <= 0) return true;  // nothing fits: the candidate is judged as it is
  const std::vector<int64_t> pieces = evaluator.piecesCutOff(builder.sortedPartVoxels(), static_cast<size_t>(room));
  return pieces.empty() || (builder.absorb(pieces, removal) && builder.size() <= maxSize);
}

}  // namespace


std::vector<Candidate> generatePartCandidates(const VoxelGrid& grid, int remainder, DesignContext& context,
                                              int targetSize, int partsStillToPlace) {
  const VoxelDesignOptions& options = context.options;
  const bool recursive = options.mode == DesignMode::Recursive;
  const Assembly assembly = assemblyFromVoxels(grid);
  const std::vector<DirectionalBlockingGraph> graphs = buildBaseBlockingGraphs(assembly);  // +x, +y, +z
  std::vector<AxisInfo> axes;
  for (int axis = 0; axis < 3; ++axis) axes.push_back(describeAxis(grid, remainder, axis, graphs[axis].graph, recursive));
  // The checks and ranking of this node's candidates, local to each candidate's part.
  SplitEvaluator evaluator(grid, remainder, options.keyDirection, options.ranking);
  const std::vector<double>& access = evaluator.access();
  const std::vector<int64_t> seeds = seedPool(grid, remainder, access);
  int64_t remainderVoxels = 0;
  for (int64_t v = 0; v < grid.voxelCount(); ++v) remainderVoxels += grid.labelAt(v) == remainder ? 1 : 0;

  // Part sizes within a quarter of the target, which keeps the search flexible; the final split
  // (P_(N-1) and the last remainder) only needs both parts to be of a reasonable size. Both are
  // moved into the sizes the bounds allow with R_i still splittable into the parts to come
  // (partSizeWindow: a part outside it is a dead branch, refused before it is built).
  const bool finalSplit = partsStillToPlace == 1;
  const SizeWindow allowed = partSizeWindow(remainderVoxels, partsStillToPlace + 1, partSizeBounds(options));
  if (allowed.empty()) return {};
  const int heuristicMin = clampInto({finalSplit ? targetSize / 2 : targetSize - targetSize / 4, 0}, allowed).min;
  const int heuristicMax = finalSplit ? static_cast<int>(remainderVoxels) - heuristicMin : targetSize + targetSize / 4 + 1;
  const SizeWindow size = clampInto({heuristicMin, std::max(heuristicMin, heuristicMax)}, allowed);

  std::vector<Candidate> candidates;
  std::set<std::vector<int64_t>> seen;
  PartBuilder builder(grid, remainder, context, access);  // reset for every attempt
  const int attempts = 40 * options.candidates + 200;
  for (int attempt = 0; attempt < attempts && static_cast<int>(candidates.size()) < options.candidates; ++attempt) {
    const int64_t seedVoxel = seeds[context.random() % seeds.size()];
    const Int3 seed = grid.coordinates(seedVoxel);
    const Int3 removal = removalDirectionFor(grid, remainder, seedVoxel, context.random);
    builder.reset();
    // Every force settles what P_i's removal along `removal` implies (PartBuilder::propagateAlong):
    // picks then skip voxels the removal already decided, instead of failing when the path is
    // cleared after the whole design was built.
    builder.propagateAlong(removal);
    bool ok = builder.forcePart(seedVoxel);
    bool someAxisFreeOfPairs = false;
    for (int axis = 0; axis < 3 && ok; ++axis) {
      // Try the allowed designs in random order; a design that cannot be realized here is rolled
      // back before the next is tried (thin walls host only some of them).
      std::vector<AxisDesign> allowed = allowedDesigns(axis, removal);
      shuffleDeterministically(allowed, context.random);
      ok = false;
      for (AxisDesign design : allowed) {
        const PartBuilder::Snapshot before = builder.snapshot();
        // Look-ahead: a design whose forced voxels can no longer be joined into one part is
        // dead (PartBuilder::forcedPartConnectable); try the next one instead of the attempt
        // failing in connect() after all three axes.
        if (realizeAxis(design, axis, axes[axis], grid, seed, context.random, builder) &&
            builder.forcedPartConnectable()) {
          someAxisFreeOfPairs = someAxisFreeOfPairs || design != AxisDesign::TwoInternal;
          ok = true;
          break;
        }
        builder.restore(before);
      }
    }
    ok = ok && someAxisFreeOfPairs && builder.connect() && builder.clearPathAlong(removal) &&
         builder.growTo(size.min, size.max, removal, context.random) &&
         (remainderVoxels <= kEnumerableVoxels || absorbPiecesCutOff(evaluator, size.max, removal, builder));
    if (!ok) continue;
    Candidate candidate{builder.sortedPartVoxels(), 0};
    if (!seen.insert(candidate.partVoxels).second) continue;
    if (evaluator.accepts(candidate)) {
      candidate.rankKey = evaluator.rankKey(candidate);
      candidates.push_back(std::move(candidate));
    }
  }
  // The random designs found no child: at the deep end, enumerate the splits they missed (or
  // learn that there are none). Where they found children, those are the node's children as
  // before, so easy designs are searched as they were.
  // With four parts left the enumeration keeps the random designs' size window (parts of any
  // allowed size there leave remainders that are hard to finish); closer to the end any size the
  // bounds allow is fine, as the look-ahead has checked the rest.
  if (candidates.empty()) {
    const SizeWindow window = partsStillToPlace == kEnumeratedPartsStillToPlace ? size : allowed;
    enumeratedChildren(grid, remainder, context, window, partsStillToPlace, &candidates);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.rankKey < y.rankKey; });
  return candidates;
}

}  // namespace desia::design
