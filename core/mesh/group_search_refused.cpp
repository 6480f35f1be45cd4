// SPDX-License-Identifier: GPL-3.0-or-later
// The light WebAssembly module's side of mesh/group_search_entry.h: no off-lattice search. A mesh
// assembly that needs it is refused with ErrorCode::KindNotBuilt, which the package's worker
// (wasm/host.js) answers by loading the full module and asking it the same question.
#include "desia/error.h"
#include "mesh/group_search_entry.h"

namespace desia::mesh {

std::optional<DisassemblyPlan> planOffLatticeGroupMoves(const MeshAssembly&, const std::vector<PartGeometry>&,
                                                        std::string*, std::string*) {
  throw Error(ErrorCode::KindNotBuilt,
              "moves of several parts off a lattice are searched in the full desia module (dist/desia_wasm.wasm), "
              "not in this light one");
}

}  // namespace desia::mesh
