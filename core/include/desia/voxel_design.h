// SPDX-License-Identifier: GPL-3.0-or-later
// Design of N-part interlocking voxel puzzles (paper Sections 4 and 5.1): Algorithm 1's iterative
// construction [R0] -> [P1, R1] -> ... -> [P1..P(N-1), R(N-1)] with a construction tree of ranked
// candidates and automatic backtracking. Every returned puzzle passes the project's own
// interlocking test (key = part 1) and disassembles in the order 1, 2, ..., N.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "desia/contact_check.h"
#include "desia/design_search.h"
#include "desia/voxel_grid.h"

namespace desia {

// How candidates {A_(i+1)} are ranked (Section 4.1 and Fig. 15).
enum class CandidateRanking {
  Compactness,  // accessibility of R_(i+1), most compact first (Song et al. 2012, default)
  LowestX, LowestY, LowestZ,      // P_(i+1) with the smallest mean x / y / z first
  HighestX, HighestY, HighestZ,   // ... the largest first
};
CandidateRanking parseCandidateRanking(const std::string& name);  // compactness|x|y|z|-x|-y|-z
const char* candidateRankingName(CandidateRanking ranking);

enum class DesignMode {
  Desia,      // P_i and R_i immobilized by cycles through all earlier parts (Fig. 7)
  Recursive,  // only through P_(i-1), the baseline of Song et al. 2012 (Fig. 11)
};
DesignMode parseDesignMode(const std::string& name);  // desia|recursive
const char* designModeName(DesignMode mode);

struct VoxelDesignOptions {
  int parts = 0;                       // N >= 3
  uint64_t seed = 1;                   // all randomness comes from this seed
  int candidates = 30;                 // m: children kept per node (paper default 30)
  CandidateRanking ranking = CandidateRanking::Compactness;
  DesignMode mode = DesignMode::Desia;
  int minPartSize = 0;                 // 0: automatic (a quarter of the average part size, at least 2)
  int maxPartSize = 0;                 // 0: none
  // Even parts: every part within kEvenPartsTolerance of the mean size voxels / N (see
  // evenPartBounds), on top of minPartSize / maxPartSize.
  bool evenParts = false;
  Int3 keyDirection{0, 1, 0};          // the key's only free direction (default +y: gravity holds it)
  std::vector<std::vector<int64_t>> groups;  // voxel index groups that must end up in one part
  // Time and node limits, progress and cancellation. deepestSnapshots copies the grid each time
  // the best depth grows (at most N - 1 copies per design) into DesignProgress::deepestGrid.
  DesignLimits limits;
};

// Bounds on the size of every part (the key and the last remainder included), in voxels.
struct PartSizeBounds {
  int min = 1;
  int max = 0;
};

// Even parts: sizes between floor(mean) - t and ceil(mean) + t, mean = voxels / parts and
// t = max(1, floor(kEvenPartsTolerance * mean)): within about 20% of the mean.
constexpr double kEvenPartsTolerance = 0.2;
PartSizeBounds evenPartBounds(int64_t voxels, int parts);

// The sizes of a puzzle's parts: smallest, largest and mean (voxels / parts).
struct PartSizeSpread {
  int min = 0;
  int max = 0;
  double mean = 0;
};
PartSizeSpread partSizeSpread(const VoxelGrid& puzzle);

struct VoxelDesignResult {
  DesignStatus status = DesignStatus::NotFound;
  std::string message;        // one sentence: what was found, or how far the search got
  VoxelGrid puzzle;           // on success: part 1 = key, ..., part N = last remainder
  CheckReport verification;   // on success: the check that verified the puzzle
  DesignProgress progress;    // final counters
  uint64_t seed = 0;          // the seed of the search that produced this result
  PartSizeSpread partSizes;   // on success: the spread of the puzzle's part sizes
};

// Step-by-step design, as the original tool's GUI ("Generate Next Part", "Child Index", "Go Back"):
// the construction tree is walked by hand. Children of a node are generated (and ranked) when first
// asked for. Re-entrant: each session owns its state. Throws BadInput like designVoxelPuzzle.
class VoxelDesignSession {
 public:
  VoxelDesignSession(const VoxelGrid& shape, const VoxelDesignOptions& options);
  ~VoxelDesignSession();
  VoxelDesignSession(const VoxelDesignSession&) = delete;
  VoxelDesignSession& operator=(const VoxelDesignSession&) = delete;

  // The current assembly A_i: parts 1..i placed, part i+1 the remainder.
  const VoxelGrid& current() const;
  int partsPlaced() const;   // i
  int targetParts() const;   // N
  bool complete() const;     // i == N - 1: the current assembly has N parts

  // The ranked children of the current node (generated on first call); at most options.candidates.
  int childCount();
  // The assembly the n-th child (0 = best ranked) would give, without moving to it.
  VoxelGrid childPreview(int n);
  // Moves to the n-th child. Throws BadInput when n is out of range.
  void chooseChild(int n);
  // Moves to the best-ranked child; false when the node has no children (then go back).
  bool generateNextPart();
  // Moves to the parent; false at the root.
  bool goBack();
  // The project's check of the current assembly (interlocking, key, disassembly).
  CheckReport check() const;
  // "Finish automatically from here": designVoxelPuzzle's search (restarts, verification) run in
  // the subtree of the current node, so parts 1..i stay as chosen. The session does not move.
  // Deterministic: the same path gives the same result. Limits and progress come from `limits`.
  VoxelDesignResult finish(const DesignLimits& limits);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Throws BadInput for impossible requests (N < 3, N larger than the voxel count, a shape that is
// not one face-connected part, groups outside the shape or overlapping, part size bounds that no
// N parts can meet: max < min, max * N < voxels, min * N > voxels).
VoxelDesignResult designVoxelPuzzle(const VoxelGrid& shape, const VoxelDesignOptions& options);

}  // namespace desia
