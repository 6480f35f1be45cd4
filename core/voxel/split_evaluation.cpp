// SPDX-License-Identifier: GPL-3.0-or-later
#include "voxel/split_evaluation.h"

#include <algorithm>

#include "desia/voxel.h"
#include "voxel/candidate_checks.h"
#include "voxel/voxel_removal.h"

namespace desia::design {

// ---- IncrementalAccessibility ----

IncrementalAccessibility::IncrementalAccessibility(const VoxelGrid& grid, int label)
    : grid_(grid),
      label_(label),
      steps_(grid),
      taken_(static_cast<size_t>(grid.voxelCount()), 0),
      zoneDistance_(static_cast<size_t>(grid.voxelCount()), 0) {
  const size_t n = static_cast<size_t>(grid.voxelCount());
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    if (grid.labelAt(i) == label) voxels_.push_back(i);
  }
  for (auto& pass : passes_) pass.assign(n, 0.0);
  for (auto& pass : changed_) pass.assign(n, 0.0);
  // The passes of accessibility() (Song et al. 2012, original-code-notes B4), kept one by one: the
  // same operations in the same order, so the same values.
  for (int64_t v : voxels_) {
    int count = 0;
    for (int step = 0; step < 6; ++step) {
      const int64_t w = steps_.neighbour(v, step);
      count += w >= 0 && grid.labelAt(w) == label ? 1 : 0;
    }
    passes_[0][v] = count;
  }
  double weight = 1.0;
  for (int pass = 1; pass <= 3; ++pass) {
    weight *= 0.1;  // beta^pass with beta = 0.1
    for (int64_t v : voxels_) {
      double sum = 0;
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(v, step);
        if (w >= 0 && grid.labelAt(w) == label) sum += passes_[pass - 1][w];
      }
      passes_[pass][v] = passes_[pass - 1][v] + weight * sum;
    }
  }
}

// The voxels of R \ P within 4 steps of P (through R \ P), by growing distance: a_k changes only
// within k + 1 steps (a_0 counts neighbours, each pass adds the neighbours' previous values).
void IncrementalAccessibility::collectZone(const std::vector<int64_t>& part) {
  zone_.clear();
  auto reach = [&](int64_t from, uint8_t distance) {
    for (int step = 0; step < 6; ++step) {
      const int64_t w = steps_.neighbour(from, step);
      if (w < 0 || zoneDistance_[w] != 0 || !inRest(w)) continue;
      zoneDistance_[w] = distance;
      zone_.push_back(w);
    }
  };
  for (int64_t p : part) reach(p, 1);
  size_t layerStart = 0;
  for (uint8_t distance = 2; distance <= 4; ++distance) {
    const size_t layerEnd = zone_.size();
    for (size_t k = layerStart; k < layerEnd; ++k) reach(zone_[k], distance);
    layerStart = layerEnd;
  }
}

// New a_0 .. a_3 for the zone: a value of the previous pass comes from changed_ where it changed
// (within `pass` steps of P), from R's own passes elsewhere.
void IncrementalAccessibility::recomputeZone() {
  auto previous = [&](int pass, int64_t v) {
    const uint8_t d = zoneDistance_[v];
    return d != 0 && d <= pass ? changed_[pass - 1][v] : passes_[pass - 1][v];
  };
  for (int64_t v : zone_) {
    if (zoneDistance_[v] > 1) break;  // zone_ is ordered by distance
    int count = 0;
    for (int step = 0; step < 6; ++step) {
      const int64_t w = steps_.neighbour(v, step);
      count += w >= 0 && inRest(w) ? 1 : 0;
    }
    changed_[0][v] = count;
  }
  double weight = 1.0;
  for (int pass = 1; pass <= 3; ++pass) {
    weight *= 0.1;
    for (int64_t v : zone_) {
      if (zoneDistance_[v] > pass + 1) break;
      double sum = 0;
      for (int step = 0; step < 6; ++step) {
        const int64_t w = steps_.neighbour(v, step);
        if (w >= 0 && inRest(w)) sum += previous(pass, w);
      }
      changed_[pass][v] = previous(pass, v) + weight * sum;
    }
  }
}

double IncrementalAccessibility::sumWithout(const std::vector<int64_t>& part) {
  for (int64_t p : part) taken_[p] = 1;
  collectZone(part);
  recomputeZone();
  double sum = 0;
  for (int64_t v : voxels_) {
    if (taken_[v]) continue;
    sum += zoneDistance_[v] != 0 ? changed_[3][v] : passes_[3][v];
  }
  for (int64_t p : part) taken_[p] = 0;
  for (int64_t v : zone_) zoneDistance_[v] = 0;
  return sum;
}

// ---- SplitAssembly ----

SplitAssembly::SplitAssembly(const VoxelGrid& grid, int remainderLabel)
    : grid_(grid), remainder_(remainderLabel), steps_(grid), partMark_(static_cast<size_t>(grid.voxelCount()), 0) {
  const Assembly before = assemblyFromVoxels(grid);
  const int earlier = std::max(0, remainderLabel - 1);
  keptEnd_.assign(static_cast<size_t>(earlier), 0);
  belowRemainder_.assign(static_cast<size_t>(earlier), Faces{});
  aboveRemainder_.assign(static_cast<size_t>(earlier), Faces{});
  belowPart_.assign(static_cast<size_t>(earlier), Faces{});
  abovePart_.assign(static_cast<size_t>(earlier), Faces{});
  const int r = remainderLabel - 1;  // R's internal index
  for (const Contact& contact : before.contacts) {
    const int axis = contact.normal[0] != 0 ? 0 : (contact.normal[1] != 0 ? 1 : 2);
    if (contact.a >= earlier && contact.a != r) continue;  // labels above R: not a local node
    if (contact.b == r) {
      belowRemainder_[contact.a][axis] = static_cast<int>(contact.area);
    } else if (contact.a == r) {
      if (contact.b < earlier) aboveRemainder_[contact.b][axis] = static_cast<int>(contact.area);
    } else if (contact.b < earlier) {
      kept_.push_back(contact);
      keptEnd_[contact.a] = kept_.size();
    }
  }
  for (int a = 1; a < earlier; ++a) keptEnd_[a] = std::max(keptEnd_[a], keptEnd_[a - 1]);
}

// P's faces with every other part: with earlier part q (P on the -axis side: belowPart_[q], on the
// +axis side: abovePart_[q]) and with R_i.
void SplitAssembly::countPartFaces(const std::vector<int64_t>& part) {
  std::fill(belowPart_.begin(), belowPart_.end(), Faces{});
  std::fill(abovePart_.begin(), abovePart_.end(), Faces{});
  partBelowRest_ = Faces{};
  restBelowPart_ = Faces{};
  for (int64_t p : part) partMark_[p] = 1;
  for (int64_t p : part) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {  // side 0: the neighbour along +axis, 1: along -axis
        const int64_t w = steps_.neighbour(p, 2 * axis + side);
        if (w < 0 || partMark_[w]) continue;
        const int label = grid_.labelAt(w);
        if (label == 0) continue;
        if (label == remainder_) {
          ++(side == 0 ? partBelowRest_ : restBelowPart_)[axis];
        } else {
          ++(side == 0 ? belowPart_ : abovePart_)[label - 1][axis];
        }
      }
    }
  }
  for (int64_t p : part) partMark_[p] = 0;
}

Assembly SplitAssembly::assemblyAfter(const std::vector<int64_t>& part) {
  countPartFaces(part);
  const int earlier = remainder_ - 1, partIndex = remainder_ - 1, restIndex = remainder_;
  Assembly assembly;
  for (int id = 1; id <= remainder_ + 1; ++id) assembly.parts.push_back({id, ""});
  assembly.contacts.reserve(kept_.size() + 6 * static_cast<size_t>(earlier) + 6);
  auto add = [&](int a, int b, int axis, int count) {
    if (count <= 0) return;
    Contact contact;
    contact.a = a;
    contact.b = b;
    contact.normal[axis] = 1.0;
    contact.area = count;
    assembly.contacts.push_back(contact);
  };
  // assemblyFromVoxels' order: by the part on the -axis side, then the other part, then the axis.
  size_t kept = 0;
  for (int a = 0; a < earlier; ++a) {
    for (; kept < keptEnd_[a]; ++kept) assembly.contacts.push_back(kept_[kept]);
    for (int axis = 0; axis < 3; ++axis) add(a, partIndex, axis, abovePart_[a][axis]);
    for (int axis = 0; axis < 3; ++axis) add(a, restIndex, axis, belowRemainder_[a][axis] - abovePart_[a][axis]);
  }
  for (int q = 0; q < earlier; ++q) {
    for (int axis = 0; axis < 3; ++axis) add(partIndex, q, axis, belowPart_[q][axis]);
  }
  for (int axis = 0; axis < 3; ++axis) add(partIndex, restIndex, axis, partBelowRest_[axis]);
  for (int q = 0; q < earlier; ++q) {
    for (int axis = 0; axis < 3; ++axis) add(restIndex, q, axis, aboveRemainder_[q][axis] - belowPart_[q][axis]);
  }
  for (int axis = 0; axis < 3; ++axis) add(restIndex, partIndex, axis, restBelowPart_[axis]);
  return assembly;
}

// ---- RemainderConnectivity ----

RemainderConnectivity::RemainderConnectivity(const VoxelGrid& grid, int label)
    : grid_(grid),
      label_(label),
      steps_(grid),
      taken_(static_cast<size_t>(grid.voxelCount()), 0),
      owner_(static_cast<size_t>(grid.voxelCount()), -1) {
  for (int64_t i = 0; i < grid.voxelCount(); ++i) size_ += grid.labelAt(i) == label ? 1 : 0;
}

int RemainderConnectivity::find(int region) {
  while (parent_[region] != region) {
    parent_[region] = parent_[parent_[region]];
    region = parent_[region];
  }
  return region;
}

void RemainderConnectivity::growRegions(const std::vector<int64_t>& part, int stopAtGrowing, size_t maxFinished,
                                        size_t* finishedVoxels) {
  for (int64_t p : part) taken_[p] = 1;
  auto inRest = [&](int64_t v) { return v >= 0 && grid_.labelAt(v) == label_ && !taken_[v]; };
  parent_.clear();
  pending_.clear();
  regionSize_.clear();
  finished_.clear();
  queue_.clear();
  for (int64_t p : part) {
    for (int step = 0; step < 6; ++step) {
      const int64_t w = steps_.neighbour(p, step);
      if (!inRest(w) || owner_[w] >= 0) continue;
      owner_[w] = static_cast<int32_t>(parent_.size());
      parent_.push_back(static_cast<int>(parent_.size()));
      pending_.push_back(1);
      regionSize_.push_back(1);
      finished_.push_back(0);
      queue_.push_back(w);
    }
  }
  growing_ = static_cast<int>(parent_.size());
  *finishedVoxels = 0;
  for (size_t head = 0; head < queue_.size() && growing_ > stopAtGrowing && *finishedVoxels <= maxFinished; ++head) {
    const int64_t v = queue_[head];
    const int region = find(owner_[v]);
    --pending_[region];
    for (int step = 0; step < 6 && growing_ > stopAtGrowing; ++step) {
      const int64_t w = steps_.neighbour(v, step);
      if (!inRest(w)) continue;
      if (owner_[w] < 0) {
        owner_[w] = region;
        ++pending_[region];
        ++regionSize_[region];
        queue_.push_back(w);
        continue;
      }
      const int other = find(owner_[w]);
      if (other == region) continue;
      parent_[other] = region;
      pending_[region] += pending_[other];
      regionSize_[region] += regionSize_[other];
      --growing_;
    }
    if (growing_ > stopAtGrowing && pending_[region] == 0) {  // a whole piece: no region reaches it any more
      --growing_;
      finished_[region] = 1;
      *finishedVoxels += static_cast<size_t>(regionSize_[region]);
    }
  }
}

void RemainderConnectivity::clear(const std::vector<int64_t>& part) {
  for (int64_t v : queue_) owner_[v] = -1;
  for (int64_t p : part) taken_[p] = 0;
}

bool RemainderConnectivity::connectedWithout(const std::vector<int64_t>& part) {
  if (size_ - static_cast<int64_t>(part.size()) <= 0) return false;
  // Connected exactly when the regions merge into one before any of them runs out.
  size_t finished = 0;
  growRegions(part, 1, 0, &finished);
  const bool connected = growing_ <= 1 && finished == 0;
  clear(part);
  return connected;
}

std::optional<std::vector<int64_t>> RemainderConnectivity::piecesCutOff(const std::vector<int64_t>& part,
                                                                        size_t maxVoxels) {
  if (size_ - static_cast<int64_t>(part.size()) <= 0) return std::nullopt;
  size_t finished = 0;
  growRegions(part, 1, maxVoxels, &finished);
  std::optional<std::vector<int64_t>> pieces;
  if (finished > 0 && growing_ == 1) {
    std::vector<int64_t> cut;
    for (int64_t v : queue_) {
      if (finished_[find(owner_[v])]) cut.push_back(v);
    }
    if (cut.size() <= maxVoxels) pieces = std::move(cut);
  } else if (finished == 0) {
    pieces = std::vector<int64_t>{};
  }
  clear(part);
  return pieces;
}

bool isListFaceConnected(const GridSteps& steps, const std::vector<int64_t>& voxels) {
  if (voxels.empty()) return false;
  std::vector<bool> seen(voxels.size(), false);
  std::vector<size_t> stack{0};
  seen[0] = true;
  size_t reached = 0;
  while (!stack.empty()) {
    const int64_t v = voxels[stack.back()];
    stack.pop_back();
    ++reached;
    for (int step = 0; step < 6; ++step) {
      const int64_t w = steps.neighbour(v, step);
      if (w < 0) continue;
      const auto it = std::lower_bound(voxels.begin(), voxels.end(), w);
      if (it == voxels.end() || *it != w) continue;
      const size_t k = static_cast<size_t>(it - voxels.begin());
      if (seen[k]) continue;
      seen[k] = true;
      stack.push_back(k);
    }
  }
  return reached == voxels.size();
}

// ---- SplitEvaluator ----

SplitEvaluator::SplitEvaluator(const VoxelGrid& grid, int remainderLabel, const Int3& keyDirection,
                               CandidateRanking ranking)
    : grid_(grid),
      remainder_(remainderLabel),
      keyDirection_(keyDirection),
      ranking_(ranking),
      steps_(grid),
      accessibility_(grid, remainderLabel),
      assembly_(grid, remainderLabel),
      connectivity_(grid, remainderLabel),
      pair_(grid) {
  local_ = grid.maxLabel() == remainderLabel && isFaceConnected(grid, remainderLabel);
  if (!local_) work_ = grid;
  slabs_ = {std::vector<int>(static_cast<size_t>(grid.nx()), 0), std::vector<int>(static_cast<size_t>(grid.ny()), 0),
            std::vector<int>(static_cast<size_t>(grid.nz()), 0)};
  int64_t i = 0;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x, ++i) {
        const int label = pair_.labelAt(i);
        if (label < remainderLabel) pair_.setLabelAt(i, 0);
        if (label != remainderLabel) continue;
        pair_.setLabelAt(i, remainderLabel + 1);
        ++slabs_[0][x];
        ++slabs_[1][y];
        ++slabs_[2][z];
      }
    }
  }
}

namespace {

// The first and last index of `counts` with a non-zero count (first > last when there is none).
std::pair<int, int> occupiedRange(const std::vector<int>& counts) {
  int first = 0, last = static_cast<int>(counts.size()) - 1;
  while (first <= last && counts[first] == 0) ++first;
  while (last >= first && counts[last] == 0) --last;
  return {first, last};
}

}  // namespace

// Requirement (iii), as partLeavesRemainder (candidate_checks.cpp) on the same [P_i, R_i] grid.
// R_i's box comes from R_(i-1)'s slab counts less P's voxels, so the search scans no grid.
bool SplitEvaluator::partLeaves(const std::vector<int64_t>& part) {
  std::vector<Int3> at;
  at.reserve(part.size());
  for (int64_t p : part) at.push_back(grid_.coordinates(p));
  auto count = [&](int delta) {
    for (const Int3& c : at) {
      slabs_[0][c.x] += delta;
      slabs_[1][c.y] += delta;
      slabs_[2][c.z] += delta;
    }
  };
  count(-1);
  const auto [x0, x1] = occupiedRange(slabs_[0]);
  const auto [y0, y1] = occupiedRange(slabs_[1]);
  const auto [z0, z1] = occupiedRange(slabs_[2]);
  count(1);
  for (int64_t p : part) pair_.setLabelAt(p, remainder_);
  std::vector<Move> path;
  const bool leaves = findVoxelRemovalPathOf(pair_, remainder_, part, {x0, y0, z0}, {x1, y1, z1}, &path);
  for (int64_t p : part) pair_.setLabelAt(p, remainder_ + 1);
  return leaves;
}

bool SplitEvaluator::accepts(const Candidate& candidate) {
  if (!local_) {
    applyCandidate(*work_, remainder_, candidate);
    const bool accepted = acceptsSplit(*work_, remainder_, keyDirection_);
    undoCandidate(*work_, remainder_);
    return accepted;
  }
  const std::vector<int64_t>& part = candidate.partVoxels;
  return isListFaceConnected(steps_, part) && connectivity_.connectedWithout(part) &&
         splitInterlocks(assembly_.assemblyAfter(part), remainder_, keyDirection_) && partLeaves(part);
}

std::vector<int64_t> SplitEvaluator::piecesCutOff(const std::vector<int64_t>& part, size_t maxVoxels) {
  if (!local_) return {};
  return connectivity_.piecesCutOff(part, maxVoxels).value_or(std::vector<int64_t>{});
}

double SplitEvaluator::rankKey(const Candidate& candidate) {
  if (!local_) {
    applyCandidate(*work_, remainder_, candidate);
    const double key = rankingKey(*work_, remainder_, remainder_ + 1, ranking_);
    undoCandidate(*work_, remainder_);
    return key;
  }
  if (ranking_ == CandidateRanking::Compactness) {
    return -accessibility_.sumWithout(candidate.partVoxels) -
           kShapeSurfaceWeight * shapeSurfaceVoxelCount(grid_, steps_, candidate.partVoxels);
  }
  // The part's mean coordinate, its voxels summed in index order as rankingKey does.
  double sum = 0;
  for (int64_t v : candidate.partVoxels) {
    const Int3 c = grid_.coordinates(v);
    switch (ranking_) {
      case CandidateRanking::LowestX:
      case CandidateRanking::HighestX:
        sum += c.x;
        break;
      case CandidateRanking::LowestY:
      case CandidateRanking::HighestY:
        sum += c.y;
        break;
      default:
        sum += c.z;
        break;
    }
  }
  const size_t count = candidate.partVoxels.size();
  const double mean = count ? sum / static_cast<double>(count) : 0;
  const bool highestFirst = ranking_ == CandidateRanking::HighestX || ranking_ == CandidateRanking::HighestY ||
                            ranking_ == CandidateRanking::HighestZ;
  return highestFirst ? -mean : mean;
}

}  // namespace desia::design
