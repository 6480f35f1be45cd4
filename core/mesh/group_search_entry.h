// SPDX-License-Identifier: GPL-3.0-or-later
// The search for moves of several parts off any lattice (mesh_group_search.cpp), reached through
// this one function so that a build can leave it out: the build links one of its two definitions
// (docs/architecture.md, "Two WebAssembly modules"). mesh/group_search_linked.cpp runs the search
// (the CLI, the tests and the full WebAssembly module); mesh/group_search_refused.cpp throws
// ErrorCode::KindNotBuilt, so the light module's linker keeps none of the search (seldom needed:
// only where single moves, bent paths, group moves and the lattice reading all fail), and the
// package's worker asks the full module the same question. Chosen at link time, as io's
// kind_entries.h: nothing registers itself and nothing changes at run time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh_geometry.h"

namespace desia::mesh {

// planByGroupMoves (mesh_group_search.h) where this build has the search.
std::optional<DisassemblyPlan> planOffLatticeGroupMoves(const MeshAssembly& meshes,
                                                        const std::vector<PartGeometry>& geometry, std::string* note,
                                                        std::string* limit);

}  // namespace desia::mesh
