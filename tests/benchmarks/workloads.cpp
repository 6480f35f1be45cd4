// SPDX-License-Identifier: GPL-3.0-or-later
#include "workloads.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <deque>
#include <random>
#include <sstream>

#include "desia/analysis.h"
#include "desia/document.h"
#include "desia/formats.h"
#include "desia/model.h"
#include "desia/voxel.h"

namespace desia::bench {
namespace {

// Paper Section 3.2: "0.5 milliseconds" for the 80-part BUNNY (DBG, construction of all blocking
// graphs included); "0.0076 and 0.1281 seconds" (DBG, inequalities) for the 1500-part CUBE.
constexpr double kPaperBunnyDbgMs = 0.5;
constexpr double kPaperCubeDbgMs = 7.6;
constexpr double kPaperCubeLpMs = 128.1;
constexpr double kNoPaperFigure = -1.0;

// The BUNNY's key is part 1, internal index 0.
constexpr int kBunnyKeyIndex = 0;

// Part indices the LP round 2 keeps fixed: the key and the reference part P_r of Eq. 2.
constexpr int kFixedKey = 0;
constexpr int kFixedReference = 1;

constexpr std::array<std::array<int, 3>, 6> kFaceSteps{
    {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};

void requireInterlockingBunny(const char* workload, const InterlockingResult& result) {
  if (result.verdict == Verdict::Interlocking && result.key == kBunnyKeyIndex) return;
  std::ostringstream message;
  message << workload << ": expected the BUNNY to be interlocking with key index " << kBunnyKeyIndex
          << " (part 1), got " << verdictName(result.verdict) << " with key index " << result.key << " ("
          << result.reason << ")";
  throw WrongVerdict(message.str());
}

// --- the generated CUBE --------------------------------------------------------------------

// Pushes the empty face neighbours of `voxel` onto a region's frontier.
void pushEmptyNeighbours(const VoxelGrid& grid, int64_t voxel, std::deque<int64_t>& frontier) {
  const Int3 c = grid.coordinates(voxel);
  for (const auto& step : kFaceSteps) {
    const int x = c.x + step[0], y = c.y + step[1], z = c.z + step[2];
    if (grid.inside(x, y, z) && grid.label(x, y, z) == 0) frontier.push_back(grid.index(x, y, z));
  }
}

// Claims the next still-empty voxel of the frontier for `label`; false once the frontier is spent.
bool growByOneVoxel(VoxelGrid& grid, std::deque<int64_t>& frontier, int label) {
  while (!frontier.empty()) {
    const int64_t voxel = frontier.front();
    frontier.pop_front();
    if (grid.labelAt(voxel) != 0) continue;  // taken by another region since it was queued
    grid.setLabelAt(voxel, label);
    pushEmptyNeighbours(grid, voxel, frontier);
    return true;
  }
  return false;
}

// --- the timed bodies ----------------------------------------------------------------------

int64_t bunnyDbg(const WorkloadInputs& inputs) {
  const Assembly assembly = assemblyFromVoxels(inputs.bunny());
  const std::vector<DirectionalBlockingGraph> graphs = buildBaseBlockingGraphs(assembly);
  const InterlockingResult result = testInterlockingByGraphs(assembly, graphs);
  requireInterlockingBunny("bunny-80 dbg", result);
  return static_cast<int64_t>(graphs.size()) + result.key;
}

int64_t bunnyLp(const WorkloadInputs& inputs) {
  const Assembly assembly = assemblyFromVoxels(inputs.bunny());
  const InterlockingResult result = testInterlockingByInequalities(assembly);
  requireInterlockingBunny("bunny-80 lp", result);
  return static_cast<int64_t>(result.keyDirections.size()) + result.key;
}

// Everything the DBG test does on an interlocking assembly, where it cannot exit early: build
// every base DBG and run Tarjan's algorithm on each (paper Section 3.2), plus the in/out-edge
// count of the components that the test computes for any DBG with more than one component.
int64_t cubeDbgFullWork(const WorkloadInputs& inputs) {
  const Assembly assembly = assemblyFromVoxels(inputs.cube());
  const std::vector<DirectionalBlockingGraph> graphs = buildBaseBlockingGraphs(assembly);
  int64_t components = 0;
  for (const DirectionalBlockingGraph& dbg : graphs) {
    const StronglyConnectedComponents scc = findStronglyConnectedComponents(dbg.graph);
    components += scc.count();
    if (scc.count() > 1) components += condensationDegrees(dbg.graph, scc).hasOutEdge.size();
  }
  return components;
}

// Inequality test round 1 (paper Section 3.2): one LP per part, with only that part free, as
// testInterlockingByInequalities runs it but without stopping at the second movable part.
int64_t lpRoundOne(const Assembly& assembly) {
  return static_cast<int64_t>(findPartsMovableAlone(assembly).parts.size());
}

// Round 2: one LP with every part free except the key and the reference part.
int64_t lpRoundTwo(const Assembly& assembly) {
  std::vector<bool> isFree(assembly.partCount(), true);
  isFree[kFixedKey] = false;
  isFree[kFixedReference] = false;
  return findFreeMotion(assembly, isFree).movable ? 1 : 0;
}

// Every linear program the inequality test solves on an interlocking assembly, where it cannot
// stop after round 1. Caveat: the round-2 program here is not the one an interlocking cube poses.
// The generated cube falls apart, so a free group settles it (a motion checked against every
// contact); on an interlocking assembly a flow along the blocking graphs settles its three
// objectives (checked by the dual bound). Both are linear in the contacts; GLPK alone took 1.6 s
// on this program (its dual simplex pivots towards a large optimum).
int64_t cubeLpFullWork(const WorkloadInputs& inputs) {
  const Assembly assembly = assemblyFromVoxels(inputs.cube());
  return lpRoundOne(assembly) + lpRoundTwo(assembly);
}

int64_t cubeLpRoundOne(const WorkloadInputs& inputs) { return lpRoundOne(assemblyFromVoxels(inputs.cube())); }

int64_t cubeContacts(const WorkloadInputs& inputs) {
  return static_cast<int64_t>(assemblyFromVoxels(inputs.cube()).contacts.size());
}

// What testInterlockingByGraphs really costs on the generated cube, early exit included.
int64_t cubeDbgCheck(const WorkloadInputs& inputs) {
  const Assembly assembly = assemblyFromVoxels(inputs.cube());
  const std::vector<DirectionalBlockingGraph> graphs = buildBaseBlockingGraphs(assembly);
  const InterlockingResult result = testInterlockingByGraphs(assembly, graphs);
  if (result.verdict != Verdict::NotInterlocking) {
    throw WrongVerdict(
        std::string("cube35-1500 dbg (check): expected the generated cube to be not-interlocking, got ") +
        verdictName(result.verdict));
  }
  return static_cast<int64_t>(result.witness.parts.size());
}

// The whole `desia check` of a contacts document with 800 distinct normals (319,600 base
// directions): verdict and disassembly plan, as the CLI runs it.
int64_t ringCheck(const WorkloadInputs& inputs, CheckMethod method, const char* name) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Contacts;
  document.assembly = inputs.ring();
  CheckOptions options;
  options.method = method;
  const CheckReport report = checkAssembly(document, options);
  if (report.result.verdict != Verdict::Deadlocked) {
    throw WrongVerdict(std::string(name) + ": expected deadlocked, got " + verdictName(report.result.verdict));
  }
  return static_cast<int64_t>(report.baseDirectionCount);
}

// The round plate read as `desia check` reads it: parsed, every outline validated (its edges
// checked for crossings), the plates snapped and their contacts computed.
int64_t plateOutlineRead(const WorkloadInputs& inputs) {
  const AssemblyDocument document = parseAssemblyText(inputs.roundPlate(), "round-table.json");
  if (document.assembly.contacts.size() != 1) {
    throw WrongVerdict("plate outline read: expected one contact, got " + std::to_string(document.assembly.contacts.size()));
  }
  return static_cast<int64_t>(document.plates[0].bottom[0].size());
}

// The complete disassembly of a puzzle whose first part comes out after 98 moves: the single-part
// plan fails, then the breadth-first search over moves of several parts.
int64_t levelPuzzleDisassembly(const WorkloadInputs& inputs) {
  const VoxelGrid& grid = inputs.levelPuzzle();
  const DisassemblyPlan plan = planVoxelDisassembly(grid, assemblyFromVoxels(grid));
  if (!plan.complete || plan.level.empty() || plan.level[0] != kLevelPuzzleLevel) {
    throw WrongVerdict("PelikanBurr disassembly: expected a complete plan of level " + std::to_string(kLevelPuzzleLevel) +
                       ", got " + (plan.level.empty() ? std::string("none") : std::to_string(plan.level[0])));
  }
  return static_cast<int64_t>(plan.moves.size());
}

}  // namespace

std::string roundPlateDocument(int vertices) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(6);
  out << "{\"kind\": \"plate\", \"plates\": [{\"id\": 1, \"name\": \"round top\", \"thickness\": 18, \"outline\": [";
  const double pi = std::acos(-1.0);
  for (int k = 0; k < vertices; ++k) {
    const double angle = 2 * pi * k / vertices;
    out << (k ? ", " : "") << "[" << 500 * std::cos(angle) << ", " << 500 * std::sin(angle) << ", 0]";
  }
  out << "]}, {\"id\": 2, \"name\": \"board\", \"thickness\": 18, \"outline\": "
         "[[-600, -600, 18], [600, -600, 18], [600, 600, 18], [-600, 600, 18]]}]}";
  return out.str();
}

Assembly generateNormalRing(int parts, int contacts, uint64_t seed) {
  Assembly assembly;
  for (int id = 1; id <= parts; ++id) assembly.parts.push_back({id, ""});
  uint64_t state = seed;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2 - 1;  // [-1, 1)
  };
  for (int c = 0; c < contacts; ++c) {
    Vec3 n{};
    double length2 = 0;
    do {
      n = {next(), next(), next()};
      length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    } while (length2 > 1 || length2 < 1e-4);  // uniform directions: inside the unit ball
    const double length = std::sqrt(length2);
    assembly.contacts.push_back({c % parts, (c + 1) % parts, {n[0] / length, n[1] / length, n[2] / length}, 1.0});
  }
  return assembly;
}

const std::vector<WorkloadSpec>& workloadSpecs() {
  static const std::vector<WorkloadSpec> specs{
      {Workload::BunnyDbg, "bunny-80 dbg", kPaperBunnyDbgMs,
       "assemblyFromVoxels + buildBaseBlockingGraphs + testInterlockingByGraphs", false},
      {Workload::BunnyLp, "bunny-80 lp", kNoPaperFigure, "assemblyFromVoxels + testInterlockingByInequalities", false},
      {Workload::CubeDbgFullWork, "cube35-1500 dbg (full work)", kPaperCubeDbgMs,
       "assemblyFromVoxels + buildBaseBlockingGraphs + Tarjan (and component degrees) on every base DBG", false},
      {Workload::CubeLpFullWork, "cube35-1500 lp (full work)", kPaperCubeLpMs,
       "assemblyFromVoxels + one LP per part + one LP with two parts fixed", false},
      {Workload::CubeDbgCheck, "cube35-1500 dbg (check)", kNoPaperFigure,
       "testInterlockingByGraphs as it runs on the cube (exits at the first failing DBG)", false},
      {Workload::CubeContacts, "cube35-1500 contacts only", kNoPaperFigure,
       "assemblyFromVoxels alone: the part of every cube row spent deriving contacts from voxels", false},
      {Workload::CubeLpRoundOne, "cube35-1500 lp round 1 only", kNoPaperFigure,
       "assemblyFromVoxels + one LP per part (the full-work row minus its big round-2 LP)", false},
      {Workload::RingDbgCheck, "ring10-800 normals dbg (check)", kNoPaperFigure,
       "checkAssembly --method dbg of 10 parts with 800 distinct normals (319,600 base DBGs) and its plan; target 1000 ms", true},
      {Workload::RingLpCheck, "ring10-800 normals lp (check)", kNoPaperFigure,
       "checkAssembly --method lp of the same ring (base directions, LPs, plan); target 1000 ms", true},
      {Workload::PlateOutlineRead, "plate outline 30000 vertices (read)", kNoPaperFigure,
       "parseAssemblyText of a round top (30,000-vertex outline) on a board: validation, snapping, contacts; target 500 ms", true},
      {Workload::LevelPuzzleDisassembly, "PelikanBurr level 98 (disassembly)", kNoPaperFigure,
       "planVoxelDisassembly of BurrTools' PelikanBurr (7 parts, 8^3): single-part plan, then the search over moves of several parts; target 1 s native, 2 s wasm", false},
  };
  return specs;
}

const WorkloadSpec& workloadByName(const std::string& name) {
  std::string known;
  for (const WorkloadSpec& spec : workloadSpecs()) {
    if (name == spec.name) return spec;
    known += std::string(known.empty() ? "" : ", ") + "\"" + spec.name + "\"";
  }
  throw std::invalid_argument("unknown workload \"" + name + "\" (known: " + known + ")");
}

VoxelGrid generateCubePartition(int side, int parts, uint32_t seed) {
  VoxelGrid grid(side, side, side);
  if (parts < 1 || parts > grid.voxelCount()) throw std::invalid_argument("cube partition: bad part count");
  std::mt19937 engine(seed);
  std::vector<std::deque<int64_t>> frontiers(static_cast<size_t>(parts));
  for (int label = 1; label <= parts;) {
    const int64_t voxel = static_cast<int64_t>(engine() % static_cast<uint64_t>(grid.voxelCount()));
    if (grid.labelAt(voxel) != 0) continue;  // seeds must be distinct: draw again
    grid.setLabelAt(voxel, label);
    ++label;
  }
  // Frontiers are filled only after all seeds are placed, so no region queues another's seed.
  for (int64_t voxel = 0; voxel < grid.voxelCount(); ++voxel) {
    if (grid.labelAt(voxel) != 0) pushEmptyNeighbours(grid, voxel, frontiers[grid.labelAt(voxel) - 1]);
  }
  // Round robin: every region takes one voxel per round. A region stops when nothing empty
  // touches it; then no empty voxel touches any region, and the solid cube is fully assigned.
  for (bool grew = true; grew;) {
    grew = false;
    for (int label = 1; label <= parts; ++label) grew = growByOneVoxel(grid, frontiers[label - 1], label) || grew;
  }
  return grid;
}

GridStats gridStats(const VoxelGrid& grid) {
  GridStats stats;
  const std::vector<int64_t> counts = grid.labelCounts();
  stats.parts = static_cast<int>(counts.size()) - 1;
  stats.voxels = grid.voxelCount() - counts[0];
  stats.contacts = static_cast<int>(assemblyFromVoxels(grid).contacts.size());
  if (stats.parts > 0) {
    stats.smallestPart = *std::min_element(counts.begin() + 1, counts.end());
    stats.largestPart = *std::max_element(counts.begin() + 1, counts.end());
  }
  uint32_t hash = 2166136261u;
  for (int label : grid.labels()) {
    hash ^= static_cast<uint32_t>(label);
    hash *= 16777619u;
  }
  stats.fingerprint = hash;
  return stats;
}

std::string describeStats(const std::string& what, const GridStats& stats) {
  std::ostringstream out;
  out << what << ": " << stats.parts << " parts, " << stats.voxels << " voxels, " << stats.contacts
      << " contacts (part pair x axis), part sizes " << stats.smallestPart << ".." << stats.largestPart
      << " voxels, label fingerprint " << std::hex << stats.fingerprint;
  return out.str();
}

WorkloadInputs::WorkloadInputs(const std::string& bunnyPuzText, const std::string& bunnySource,
                               const std::string& levelPuzzleText, const std::string& levelPuzzleSource)
    : bunny_(parsePuz(bunnyPuzText, bunnySource)),
      cube_(generateCubePartition(kCubeSide, kCubeParts, kCubeSeed)),
      ring_(generateNormalRing(kRingParts, kRingContacts, kCubeSeed)),
      roundPlate_(roundPlateDocument(kOutlineVertices)),
      levelPuzzle_(parsePuz(levelPuzzleText, levelPuzzleSource)) {
  // Throws BadInput if a region were empty or split; the generator guarantees neither happens.
  validateVoxelParts(cube_, "generated cube");
}

int64_t runWorkload(Workload workload, const WorkloadInputs& inputs) {
  switch (workload) {
    case Workload::BunnyDbg:
      return bunnyDbg(inputs);
    case Workload::BunnyLp:
      return bunnyLp(inputs);
    case Workload::CubeDbgFullWork:
      return cubeDbgFullWork(inputs);
    case Workload::CubeLpFullWork:
      return cubeLpFullWork(inputs);
    case Workload::CubeDbgCheck:
      return cubeDbgCheck(inputs);
    case Workload::CubeContacts:
      return cubeContacts(inputs);
    case Workload::CubeLpRoundOne:
      return cubeLpRoundOne(inputs);
    case Workload::RingDbgCheck:
      return ringCheck(inputs, CheckMethod::Graphs, "ring10-800 normals dbg (check)");
    case Workload::RingLpCheck:
      return ringCheck(inputs, CheckMethod::Inequalities, "ring10-800 normals lp (check)");
    case Workload::PlateOutlineRead:
      return plateOutlineRead(inputs);
    case Workload::LevelPuzzleDisassembly:
      return levelPuzzleDisassembly(inputs);
  }
  throw std::invalid_argument("unknown workload");
}

}  // namespace desia::bench
