// SPDX-License-Identifier: GPL-3.0-or-later
// Edits of OBJ text that move an exported puzzle off its lattice, shared by the mesh tests and the
// mesh benchmark (no GoogleTest here, so that the benchmark can link it).
#pragma once

#include <string>

namespace desia::testing {

// The OBJ with the vertex farthest along each of the eight diagonals (the first in the file where
// several are as far) moved `depth` back along it, in every record that has it.
std::string dentedObj(const std::string& obj, double depth);

}  // namespace desia::testing
