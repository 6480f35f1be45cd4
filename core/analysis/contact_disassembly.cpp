// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning from contacts alone (paper Section 3.3, "successively identifying the
// movable part based on the DBGs"). Without geometry no sweep is possible, so a removal is a
// local translation: the part has no blocking edge along the chosen base direction.
#include "analysis/part_motion.h"
#include "desia/blocking_graph.h"
#include "desia/disassembly.h"

namespace desia {

DisassemblyPlan planContactDisassembly(const Assembly& assembly) {
  const int n = assembly.partCount();
  const std::vector<BaseDirection> directions = computeBaseDirections(assembly);
  std::vector<bool> present(n, true);
  DisassemblyPlan plan;
  for (int remaining = n; remaining > 1; --remaining) {
    bool progressed = false;
    for (int part = 0; part < n && !progressed; ++part) {
      if (!present[part]) continue;
      for (const BaseDirection& base : directions) {
        for (const Vec3& d : {base.vector, negated(base.vector)}) {
          if (progressed || !isPartFreeAlong(assembly, &present, part, d)) continue;
          plan.removals.push_back({part, {Move{d, 1}}});
          present[part] = false;
          progressed = true;
        }
      }
    }
    if (!progressed) {
      for (int part = 0; part < n; ++part) {
        if (present[part]) plan.stuck.push_back(part);
      }
      return plan;
    }
  }
  for (int part = 0; part < n; ++part) {
    if (present[part]) plan.removals.push_back({part, {}});
  }
  plan.complete = true;
  return plan;
}

}  // namespace desia
