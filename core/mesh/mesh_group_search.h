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
// `level` (BurrTools' notation) has the fewest moves before each separation. groupStates: the
// positions visited, all sub-assemblies together.
// Bounds of the search (work, not time: the same plan everywhere); past one the plan says which.
struct GroupSearchLimits {
  size_t positions = 100000;     // positions of one sub-assembly
  // Sweeps of pairs of parts, all sub-assemblies together: about 0.1 ms each for parts of a few
  // hundred triangles, so about 10 s natively at most (PelikanBurr off its lattice takes 8,568).
  int64_t pairSweeps = 100000;
};
// *pairSweeps (if given): the sweeps the search made.
DisassemblyPlan searchGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                 const GroupSearchLimits& limits = {}, int64_t* pairSweeps = nullptr);

// searchGroupMoves where its plan is complete and passes sweepPlan; else nothing. *note says which
// (and the bound that stopped the search, if one did); *limit (if given) is that bound, "" if none.
std::optional<DisassemblyPlan> planByGroupMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                                std::string* note, std::string* limit = nullptr);

}  // namespace desia::mesh
