// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly planning from contacts alone (paper Section 3.3, "successively identifying the
// movable part based on the DBGs"). Without geometry no sweep is possible, so a removal is a
// local translation: the part has no blocking edge along the chosen direction.
#include "analysis/part_motion.h"
#include "desia/analysis.h"

namespace desia {
namespace {

// The part's contacts with parts still present, as an assembly of their own.
Assembly localContacts(const Assembly& assembly, const std::vector<std::vector<int>>& contactsOfPart,
                       const std::vector<bool>& present, int part) {
  Assembly local;
  local.parts = assembly.parts;
  for (int c : contactsOfPart[part]) {
    const Contact& contact = assembly.contacts[c];
    if (present[contact.a] && present[contact.b]) local.contacts.push_back(contact);
  }
  return local;
}

// A direction along which `part` is free, among the vertices of its own contacts' arrangement.
// That is enough: a non-empty cone of free directions {d : d·m <= 0 for the part's oriented
// normals m} has an extreme ray where two contact planes meet, or (normals spanning a plane or a
// line) contains the line or plane those directions also cover. Looking only at the part's own
// contacts keeps the work per part O(l^3) for l contacts, not O(L^2 C) over all base directions.
bool findFreeDirection(const Assembly& local, int part, Vec3* direction) {
  for (const BaseDirection& base : computeBaseDirections(local)) {
    for (const Vec3& d : {base.vector, negated(base.vector)}) {
      if (isPartFreeAlong(local, nullptr, part, d)) {
        *direction = d;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

DisassemblyPlan planContactDisassembly(const Assembly& assembly) {
  const int n = assembly.partCount();
  std::vector<std::vector<int>> contactsOfPart(n);
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    contactsOfPart[assembly.contacts[c].a].push_back(c);
    contactsOfPart[assembly.contacts[c].b].push_back(c);
  }
  std::vector<bool> present(n, true);
  DisassemblyPlan plan;
  for (int remaining = n; remaining > 1; --remaining) {
    bool progressed = false;
    for (int part = 0; part < n && !progressed; ++part) {
      if (!present[part]) continue;
      Vec3 direction{};
      if (!findFreeDirection(localContacts(assembly, contactsOfPart, present, part), part, &direction)) continue;
      plan.removals.push_back({part, {Move{direction, 1}}});
      present[part] = false;
      progressed = true;
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
