// SPDX-License-Identifier: GPL-3.0-or-later
// Moves of several parts of a mesh assembly that lies on no lattice (a slanted or curved face
// somewhere): BurrTools' complete search, with the distances read from the triangles instead of
// counted in cells (mesh_group_search.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh_geometry.h"

namespace desia::mesh {

// The plan of the search for moves of several parts, as it ended: complete, or what it separated
// before it got stuck (`unseparated`) or stopped at a bound (searchLimitReached, `limit`). Every
// move is a translation along a base direction of the assembly's contacts (either sign) of a set
// of parts that the sweep lets travel that far; each sub-assembly is searched breadth-first, so
// `level` (BurrTools' notation) has the fewest moves before each separation, and levelMinimal and
// a stuck verdict are claimed only where every face is square or parallel to every direction tried
// (else `limit` says why not). groupStates: the positions visited, all sub-assemblies together.
// Bounds of the search (work, not time: the same plan everywhere); past one the plan says which.
struct GroupSearchLimits {
  size_t positions = 100000;  // positions of one sub-assembly
  // Steps of work, all sub-assemblies together: triangles of the moving parts looked at and
  // triangle pairs compared in the sweeps (most of the time), set operations. Counted in
  // triangles, so a finely meshed assembly meets the bound as soon as a coarse one: PelikanBurr
  // off its lattice takes 43.9 million (1 s natively), so the bound is about 5 s natively.
  int64_t work = 200000000;
};
// What the search did, for its note, tests and benchmarks.
struct GroupSearchStats {
  int64_t pairSweeps = 0;  // sweeps of one part past another along one direction
  int64_t work = 0;        // steps of work, as GroupSearchLimits::work counts them
  bool proves = false;     // every face square or parallel to every direction: level and stuck proven
  bool stoppedAtBound = false;  // a bound of GroupSearchLimits (or of the sets' or parts' counts)
};
DisassemblyPlan searchGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                 const GroupSearchLimits& limits = {}, GroupSearchStats* stats = nullptr);

// searchGroupMoves where its plan is complete and passes sweepPlan; else nothing. *note says which
// (and the bound that stopped the search, if one did); *limit (if given) is that bound, "" if none.
std::optional<DisassemblyPlan> planByGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                                std::string* note, std::string* limit = nullptr);

}  // namespace desia::mesh
