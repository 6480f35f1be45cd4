// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/model.h"

#include <algorithm>
#include <cmath>

namespace desia {

int Assembly::indexOfId(int id) const {
  for (int i = 0; i < partCount(); ++i) {
    if (parts[i].id == id) return i;
  }
  return -1;
}

std::optional<Vec3> cleanedNormal(const Vec3& normal) {
  double largest = 0;
  for (double c : normal) {
    if (!std::isfinite(c)) return std::nullopt;
    largest = std::max(largest, std::abs(c));
  }
  if (largest == 0) return std::nullopt;
  Vec3 unit{};
  double length2 = 0;
  for (int k = 0; k < 3; ++k) {
    double c = normal[k] / largest;  // in [-1, 1]: no overflow below, no underflow of the largest
    if (std::abs(c) < tolerance::kComponentNoise) c = 0.0;
    unit[k] = c;
    length2 += c * c;
  }
  const double length = std::sqrt(length2);  // in [1, sqrt(3)]
  for (double& c : unit) c /= length;
  return unit;
}

bool hasCleanNormals(const Assembly& assembly) {
  for (const Contact& contact : assembly.contacts) {
    const std::optional<Vec3> unit = cleanedNormal(contact.normal);
    if (!unit || *unit != contact.normal) return false;
  }
  return true;
}

Assembly withCleanedNormals(const Assembly& assembly) {
  Assembly clean;
  clean.parts = assembly.parts;
  clean.contacts.reserve(assembly.contacts.size());
  for (const Contact& contact : assembly.contacts) {
    const std::optional<Vec3> unit = cleanedNormal(contact.normal);
    if (!unit) continue;
    Contact copy = contact;
    copy.normal = *unit;
    clean.contacts.push_back(copy);
  }
  return clean;
}

bool hasOnlyAxisAlignedContacts(const Assembly& assembly) {
  for (const Contact& contact : assembly.contacts) {
    int nonZero = 0;
    for (double c : contact.normal) nonZero += std::abs(c) > tolerance::kComponentNoise ? 1 : 0;
    if (nonZero != 1) return false;
  }
  return true;
}

}  // namespace desia
