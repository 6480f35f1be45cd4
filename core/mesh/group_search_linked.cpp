// SPDX-License-Identifier: GPL-3.0-or-later
// The build with the off-lattice search (mesh/group_search_entry.h): the CLI, the tests, the full
// WebAssembly module.
#include "mesh/group_search_entry.h"
#include "mesh/mesh_group_search.h"

namespace desia::mesh {

std::optional<DisassemblyPlan> planOffLatticeGroupMoves(const MeshAssembly& meshes,
                                                        const std::vector<PartGeometry>& geometry, std::string* note,
                                                        std::string* limit) {
  return planByGroupMoves(meshes, geometry, note, limit);
}

}  // namespace desia::mesh
