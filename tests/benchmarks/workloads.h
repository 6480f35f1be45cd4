// SPDX-License-Identifier: GPL-3.0-or-later
// The workloads of the interlocking-test benchmarks (paper Section 3.2), shared by the native
// Google Benchmark binary and the WebAssembly benchmark module, so that both targets time exactly
// the same code. Inputs (the parsed BUNNY, the generated CUBE) are prepared once, outside the
// timed region: the paper's figures cover the tests, not reading files.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/voxel.h"

namespace desia::bench {

// Reference puzzle of paper Fig. 12(b): 80 parts, interlocking, key = part 1 (internal index 0).
constexpr const char* kBunnyRelativePath = "tests/reference/desia/data/result_puz/bunny_15x14x11_K80.puz";

// The generated stand-in for the 1500-part CUBE of paper Fig. 12(d).
constexpr int kCubeSide = 35;
constexpr int kCubeParts = 1500;
constexpr uint32_t kCubeSeed = 20181204;  // any fixed value; this one is SIGGRAPH Asia 2018's opening day

enum class Workload {
  BunnyDbg,
  BunnyLp,
  CubeDbgFullWork,
  CubeLpFullWork,
  CubeDbgCheck,
  // Breakdown rows (no paper figure): where the cube's time goes.
  CubeContacts,
  CubeLpRoundOne,
  // Issue 14: many distinct normals (curved plate structures have hundreds).
  RingDbgCheck,
  RingLpCheck,
  // Issue 24: reading a plate with a finely drawn outline (validation, snapping, contacts).
  PlateOutlineRead,
  // Issue 27: the complete disassembler on BurrTools' level-98 PelikanBurr.
  LevelPuzzleDisassembly,
};

struct WorkloadSpec {
  Workload id;
  const char* name;      // the label printed in tables, e.g. "bunny-80 dbg"
  double paperMs;        // the paper's figure (Section 3.2), or a negative value when it gives none
  const char* measures;  // one line: what the timed region contains
  bool slow;             // seconds per run: the drivers repeat it fewer times
};

// All workloads in table order.
const std::vector<WorkloadSpec>& workloadSpecs();
// The spec with this name; throws std::invalid_argument naming the known workloads otherwise.
const WorkloadSpec& workloadByName(const std::string& name);

// A workload that did not reach the verdict it must reach (the measured code would be wrong).
class WrongVerdict : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Partitions a solid side^3 cube into `parts` face-connected parts: `parts` distinct seed voxels
// drawn from a std::mt19937 (raw outputs and modulo only: std:: distributions differ between
// libstdc++ and libc++, the raw engine does not), then all regions grow breadth-first, one voxel
// per region per round, until every voxel is taken. Deterministic on every platform.
VoxelGrid generateCubePartition(int side, int parts, uint32_t seed);

struct GridStats {
  int parts = 0;
  int64_t voxels = 0;
  int contacts = 0;          // one per (part pair, axis), as assemblyFromVoxels builds them
  int64_t smallestPart = 0;  // voxels
  int64_t largestPart = 0;
  uint32_t fingerprint = 0;  // FNV-1a of the labels: equal natively and in WebAssembly
};
GridStats gridStats(const VoxelGrid& grid);
std::string describeStats(const std::string& what, const GridStats& stats);

// A ring of `parts` parts, each touching the next with contacts of distinct random unit normals
// (`contacts` in all; a fixed linear congruential sequence, the same on every platform). With
// hundreds of normals it is deadlocked: some normal of every pair blocks each direction.
Assembly generateNormalRing(int parts, int contacts, uint64_t seed);
constexpr int kRingParts = 10;
constexpr int kRingContacts = 800;

// A round table top of this many outline vertices (radius 500 mm, 18 mm) on a square board.
constexpr int kOutlineVertices = 30000;
// The plate document of that design, as a CAD tool would write it (coordinates to 6 decimals).
std::string roundPlateDocument(int vertices);

// The prepared inputs. Construction parses the BUNNY (parsePuz also validates it) and generates
// and validates the CUBE; neither step is timed.
class WorkloadInputs {
 public:
  WorkloadInputs(const std::string& bunnyPuzText, const std::string& bunnySource, const std::string& levelPuzzleText,
                 const std::string& levelPuzzleSource);
  const VoxelGrid& bunny() const { return bunny_; }
  const VoxelGrid& cube() const { return cube_; }
  const Assembly& ring() const { return ring_; }
  const std::string& roundPlate() const { return roundPlate_; }
  const VoxelGrid& levelPuzzle() const { return levelPuzzle_; }

 private:
  VoxelGrid bunny_;
  VoxelGrid cube_;
  Assembly ring_;
  std::string roundPlate_;
  VoxelGrid levelPuzzle_;
};

// BurrTools' PelikanBurr (tests/data/burrtools): 7 parts in 8^3 voxels, level 98 (BurrTools' own).
constexpr int kLevelPuzzleLevel = 98;

// Runs one workload once. Throws WrongVerdict when the result is not the expected one. The
// returned number depends on the whole result (so no compiler can drop the work) and is otherwise
// meaningless.
int64_t runWorkload(Workload workload, const WorkloadInputs& inputs);

}  // namespace desia::bench
