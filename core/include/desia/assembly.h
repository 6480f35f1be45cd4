// SPDX-License-Identifier: GPL-3.0-or-later
// The assembly model shared by voxel, plate and frame assemblies (paper Section 3.1): rigid parts
// and planar contacts between them, each contact with its normal. Blocking relations per
// translation direction are derived from the contacts (see blocking_graph.h).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "desia/tolerances.h"

namespace desia {

using Vec3 = std::array<double, 3>;

struct Part {
  int id = 0;             // the id the user sees (as in the file); parts are indexed 0..n-1 internally
  std::string name;       // optional label
};

// A planar contact interface between parts `a` and `b` (internal indices). `normal` is the unit
// normal of the interface pointing from a towards b, so translating a along d with d·normal > 0
// makes a penetrate b (paper Section 3.2, n_ij). `area` weights nothing in the tests; it is kept
// for reports and for ranking in the design framework.
struct Contact {
  int a = 0;
  int b = 0;
  Vec3 normal{0, 0, 0};
  double area = 1.0;
};

struct Assembly {
  std::vector<Part> parts;
  std::vector<Contact> contacts;

  int partCount() const { return static_cast<int>(parts.size()); }
  // Internal index of the part with the given user id, or -1.
  int indexOfId(int id) const;
};

// The unit vector along `normal`, computed without overflow or underflow at any scale (it is
// divided by its largest component first), with residue components (below tolerance::kComponentNoise
// of the largest: computed geometry leaves them where a component should vanish) set to zero.
// Empty for the zero vector or a non-finite component. Every contact normal passes through this
// once, when it is read or computed from geometry.
std::optional<Vec3> cleanedNormal(const Vec3& normal);

// True when every contact normal is already what cleanedNormal makes of it (no copy needed).
bool hasCleanNormals(const Assembly& assembly);

// The assembly with every contact normal passed through cleanedNormal; contacts whose normal is
// the zero vector constrain nothing and are left out.
Assembly withCleanedNormals(const Assembly& assembly);

// True when every contact normal is parallel to a coordinate axis, the case where the DBG test is
// exact (paper Section 3.2, supplementary proof).
bool hasOnlyAxisAlignedContacts(const Assembly& assembly);

}  // namespace desia
