// SPDX-License-Identifier: GPL-3.0-or-later
// Voxel puzzles (paper Section 5.1): the grid, the designer, the disassembly planners, surfaces
// and voxelization.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "desia/analysis.h"
#include "desia/model.h"
#include "desia/search.h"

namespace desia {

// A labelled voxel grid: the representation of voxel puzzles (and of the 3x3x3 joints of frames).
// Label 0 is empty; label k >= 1 is part k. Index order x + nx*(y + ny*z), as in DESIA's .puz.

// Limits checked before allocating a grid (a hostile header must not exhaust memory).
struct VoxelLimits {
  static constexpr int64_t kMaxSide = 1024;
  static constexpr int64_t kMaxVoxels = 1 << 24;  // 16.7 M voxels (256^3): 64 MiB of labels
};

struct Int3 {
  int x = 0, y = 0, z = 0;
  bool operator==(const Int3& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const Int3& o) const { return !(*this == o); }
};

class VoxelGrid {
 public:
  VoxelGrid() = default;
  // Throws TooLarge / BadInput for sizes outside VoxelLimits.
  VoxelGrid(int nx, int ny, int nz);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  int64_t voxelCount() const { return static_cast<int64_t>(labels_.size()); }

  bool inside(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx_ && y < ny_ && z < nz_;
  }
  int64_t index(int x, int y, int z) const {
    return x + static_cast<int64_t>(nx_) * (y + static_cast<int64_t>(ny_) * z);
  }
  Int3 coordinates(int64_t index) const;
  int label(int x, int y, int z) const { return labels_[index(x, y, z)]; }
  int labelAt(int64_t i) const { return labels_[i]; }
  void setLabel(int x, int y, int z, int value) { labels_[index(x, y, z)] = value; }
  void setLabelAt(int64_t i, int value) { labels_[i] = value; }
  const std::vector<int>& labels() const { return labels_; }

  int maxLabel() const;
  // Voxel count per label, indexed 0..maxLabel() (entry 0 counts empty voxels).
  std::vector<int64_t> labelCounts() const;

 private:
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<int> labels_;
};

// Checks that labels are 1..K with no gap, that there is at least one part, and that each part is
// face-connected (6-connected). Throws BadInput naming the offending part; `source` names the file.
void validateVoxelParts(const VoxelGrid& grid, const std::string& source);

// Parts (ids 1..K) and one contact per (pair, axis normal) with area = number of touching faces.
Assembly assemblyFromVoxels(const VoxelGrid& grid);

// Disassembly of voxel assemblies: each part's collision-free path out, found by sweeping along the
// axes and, where no straight path exists, by a breadth-first search over unit axis steps.

struct VoxelDisassemblyOptions {
  // Bounds on the breadth-first search over unit axis steps, per attempted removal: visited
  // offsets, and voxel collision tests made (sweeps included; a test of a placement stops at its
  // first colliding voxel), so a pathological input (a part in a huge cavity) cannot keep the
  // search busy for minutes.
  int maxSearchStates = 2'000'000;
  int64_t maxVoxelTests = 200'000'000;
  // Voxel collision tests for a whole plan (all searches together), the backstop against many
  // parts each needing a long search. When it runs out the plan stops: searchLimitReached, and
  // every part still in place is listed in `stuck` without being proven stuck.
  int64_t maxTotalVoxelTests = 1'000'000'000;
  // The complete disassembler (moves of several parts at once, searched breadth-first, as
  // BurrTools does), run when the single-part plan fails or needs a bent path. Its bounds, per
  // sub-assembly searched: positions kept, and the memory they take (about 1 GiB by default).
  bool groupMoves = true;
  int64_t maxGroupStates = 2'000'000;
  int64_t maxGroupBytes = int64_t{1} << 30;
  int maxGroupParts = 1000;  // sub-assemblies of more parts are not searched (said in `limit`)
  // Operations of that search for the whole plan (part-pair tests and unions of sets): its time
  // bound, about a few seconds natively. Many parts that move independently make 2^m moves.
  int64_t maxGroupWork = 4'000'000'000;
};

// Voxel assemblies: first the single-part plan: removals are collision-free translations to
// infinity checked by sweeping; when no straight path exists, a breadth-first search over unit
// axis steps finds a bent path (as the original code does). When that plan fails or bends, the
// complete disassembler (group_disassembly.h) searches moves of several parts for the fewest
// moves (the level); a straight single-part plan is already level 1 and kept as it is. Each round removes the lowest-id part that can leave, which is complete:
// removing a part never blocks another, so greedy removal finds a sequence whenever one exists.
// A part whose search failed is searched again only when a removal could change that search
// (it removed a part the search collided with, or shrank the box of the other parts); the plan is
// the same as searching every part every round, at about one search per part and removal nearby.
DisassemblyPlan planVoxelDisassembly(const VoxelGrid& grid, const Assembly& assembly,
                                     const VoxelDisassemblyOptions& options = {});

// Can the part with `label` leave `occupancy` (every other non-zero voxel is an obstacle)? Fills
// `path` on success. `limitReached` (optional) tells whether the search stopped at its limits
// (maxSearchStates, and the smaller of maxVoxelTests and maxTotalVoxelTests).
bool findVoxelRemovalPath(const VoxelGrid& occupancy, int label, std::vector<Move>* path,
                          const VoxelDisassemblyOptions& options = {}, bool* limitReached = nullptr);

// The project's check of a voxel assembly (paper Sections 3 and 4.1 (iii)): the interlocking tests
// on the grid's contacts, and its disassembly planned on the voxels (planVoxelDisassembly).
CheckReport checkVoxelAssembly(const VoxelGrid& grid, const CheckOptions& options = {},
                               const VoxelDisassemblyOptions& disassembly = {});

// Design of N-part interlocking voxel puzzles (paper Sections 4 and 5.1): Algorithm 1's iterative
// construction [R0] -> [P1, R1] -> ... -> [P1..P(N-1), R(N-1)] with a construction tree of ranked
// candidates and automatic backtracking. Every returned puzzle passes the project's own
// interlocking test (key = part 1) and disassembles in the order 1, 2, ..., N.

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

// The surfaces of voxel parts as closed triangle meshes: what exports print, what viewers draw,
// and what frames build their joint pieces from.

// The closed surface of part `partId`: one square per voxel face that does not touch the same
// part (faces against empty space, another part or the grid's border), as outward triangles, in
// grid coordinates times `voxelSize` (voxel (x, y, z) spans [x, x+1] x [y, y+1] x [z, z+1]).
// Every edge is used by exactly two triangles, in opposite directions, even where two voxels of
// the part touch only along an edge (see the definition for how), and where two voxels touch only
// at a corner each has its own copy of it (splitPinchedVertices): a 2-manifold. Throws BadInput
// for a part without voxels.
TriangleMesh partSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize = 1.0);

// partSurfaceMesh with every face against another part moved in by `clearance` (0 <= clearance <
// voxelSize / 2, else BadInput): the part as it is printed. Still closed, every edge in exactly two
// triangles in opposite directions; faces against empty space stay in place (see the definition).
TriangleMesh insetPartSurfaceMesh(const VoxelGrid& grid, int partId, double voxelSize, double clearance);

// Voxel indices of each part, in index order; entry k lists part k (entry 0 stays empty).
std::vector<std::vector<int64_t>> voxelsByPart(const VoxelGrid& grid);

// partSurfaceMesh for voxels already collected (all labelled partId, in index order).
TriangleMesh surfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels, double voxelSize);
// insetPartSurfaceMesh for voxels already collected, the clearance already checked (0 = as is).
TriangleMesh insetSurfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels,
                                  double voxelSize, double clearance);

// An axis-aligned box, [lo[k], hi[k]] along each axis k.
struct AxisAlignedBox {
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
};

// The closed surface of the union of `boxes`, one solid: the boxes' face planes cut space into
// cells (coordinates closer than `sameCoordinate` are one plane), a cell is solid when some box
// holds it, and the surface is built from the solid cells as partSurfaceMesh builds it from voxels
// (so boxes that overlap or touch leave no inner walls, and every edge is in exactly two
// triangles). Exact: no face is cut at a slant. Throws BadInput for no boxes or a box of no volume,
// TooLarge above 2^24 cells.
TriangleMesh surfaceOfBoxUnion(const std::vector<AxisAlignedBox>& boxes, double sameCoordinate);

// Throws BadInput (naming `source` and the value) unless 0 <= clearance < voxelSize / 2: at half a
// voxel, a part one voxel thick between two others would vanish.
void requireValidClearance(double voxelSize, double clearance, const std::string& source);

// Solid voxelization of a closed triangle mesh: the input shape of the voxel puzzle designer.

struct VoxelizeOptions {
  // Voxels along the longest side of the bounding box (1..1024); the other sides get
  // ceil(extent / voxel size) voxels, at least 1.
  int resolution = 32;
};

// One part (label 1) made of every voxel whose centre lies inside the mesh. Voxel (0,0,0) sits at
// the bounding-box minimum; mesh axes map to grid axes unchanged (+y is up in both). Checks the
// mesh first (checkClosedMesh), refuses grids outside VoxelLimits before allocating (TooLarge),
// and fails with BadInput when the result is empty or not face-connected. Deterministic: the same
// mesh gives the same grid, bit for bit, natively and in WebAssembly.
VoxelGrid voxelizeSolid(const TriangleMesh& mesh, const VoxelizeOptions& options,
                        const std::string& source = "<input>");

}  // namespace desia
