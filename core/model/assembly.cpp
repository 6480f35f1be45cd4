// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/assembly.h"

#include <cmath>

namespace desia {

int Assembly::indexOfId(int id) const {
  for (int i = 0; i < partCount(); ++i) {
    if (parts[i].id == id) return i;
  }
  return -1;
}

bool hasOnlyAxisAlignedContacts(const Assembly& assembly) {
  for (const Contact& contact : assembly.contacts) {
    int nonZero = 0;
    for (double c : contact.normal) nonZero += std::abs(c) > 1e-12 ? 1 : 0;
    if (nonZero != 1) return false;
  }
  return true;
}

}  // namespace desia
