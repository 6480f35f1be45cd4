// SPDX-License-Identifier: GPL-3.0-or-later
// DESIA's .puz voxel format, read and written exactly as the original code does:
//   "Nx Ny Nz", then Nz layers (z) of Ny rows (y) of Nx integers (x fastest), a blank line after
//   each layer; 0 = empty, k >= 1 = part k (part 1 is the key, the highest id the last remainder).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "desia/voxel_grid.h"

namespace desia {

// Parses .puz text strictly: every row on its own line with Nx values, Ny rows per layer, Nz
// layers, nothing after the grid. `source` (a file name) prefixes error locations ("a.puz:7:3").
// Also validates the parts (validateVoxelParts).
// A .puz file: the grid, and the voxel edge lengths when the file gives them (the line of three
// numbers after the header that later interlocking-puzzle research writes).
struct PuzFile {
  VoxelGrid grid;
  std::optional<std::array<double, 3>> voxelSize;
};

// Reads .puz text: "Nx Ny Nz", optionally a line of three voxel sizes, then the labels, either as
// Nz layers of Ny rows of Nx values or as one flat list (x fastest, then y, then z); lines that
// start with '#' are comments. Throws BadInput naming `source`, the line and the value.
PuzFile readPuz(const std::string& text, const std::string& source = "<input>");
VoxelGrid parsePuz(const std::string& text, const std::string& source = "<input>");

// Byte-for-byte the layout of the original writer: "v " per voxel, newline per row, an extra
// newline per layer.
std::string formatPuz(const VoxelGrid& grid);

// True when the text looks like .puz rather than JSON (first non-space character is a digit).
bool looksLikePuz(const std::string& text);

}  // namespace desia
