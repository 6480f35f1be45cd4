// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/puz_format.h"

#include <cctype>

#include "desia/error.h"
#include "io/text_lines.h"

namespace desia {
namespace {

// The next line with tokens at or after `i`, skipping blank lines (layer separators).
size_t skipBlankLines(const std::vector<TextLine>& lines, size_t i) {
  while (i < lines.size() && lines[i].tokens.empty()) ++i;
  return i;
}

int lastLineWithData(const std::vector<TextLine>& lines) {
  for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
    if (!it->tokens.empty()) return it->number;
  }
  return 1;
}

VoxelGrid parseHeader(const TextLine& header, const std::string& source) {
  if (header.tokens.size() != 3) {
    throwBadInput(location(source, header.number),
                  "the header must be three integers 'Nx Ny Nz', found " + std::to_string(header.tokens.size()) +
                      " value" + (header.tokens.size() == 1 ? "" : "s"));
  }
  int64_t size[3];
  static const char* kNames[3] = {"Nx", "Ny", "Nz"};
  for (int k = 0; k < 3; ++k) {
    size[k] = parseIntegerToken(header.tokens[k], source, header.number, std::string("grid size ") + kNames[k], 1,
                                VoxelLimits::kMaxSide);
  }
  if (size[0] * size[1] * size[2] > VoxelLimits::kMaxVoxels) {
    throw Error(ErrorCode::TooLarge, location(source, header.number) + ": grid " + std::to_string(size[0]) + " x " +
                                         std::to_string(size[1]) + " x " + std::to_string(size[2]) +
                                         " has more than " + std::to_string(VoxelLimits::kMaxVoxels) + " voxels");
  }
  return VoxelGrid(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
}

}  // namespace

bool looksLikePuz(const std::string& text) {
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  }
  return false;
}

VoxelGrid parsePuz(const std::string& text, const std::string& source) {
  const std::vector<TextLine> lines = splitTextLines(text, source);
  size_t i = skipBlankLines(lines, 0);
  if (i == lines.size()) throwBadInput(source, "the file is empty: expected the header 'Nx Ny Nz'");
  VoxelGrid grid = parseHeader(lines[i], source);
  ++i;
  // Labels above the voxel count cannot be contiguous part ids; the bound also stops overflow.
  const int64_t maxLabel = grid.voxelCount();
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      i = skipBlankLines(lines, i);
      if (i == lines.size()) {
        throwBadInput(location(source, lastLineWithData(lines)),
                      "the file ends early: expected row " + std::to_string(y + 1) + " of " +
                          std::to_string(grid.ny()) + " in layer " + std::to_string(z + 1) + " of " +
                          std::to_string(grid.nz()) + " (grid " + std::to_string(grid.nx()) + " x " +
                          std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) + ")");
      }
      const TextLine& row = lines[i];
      if (static_cast<int>(row.tokens.size()) != grid.nx()) {
        throwBadInput(location(source, row.number),
                      "row " + std::to_string(y + 1) + " of layer " + std::to_string(z + 1) + " has " +
                          std::to_string(row.tokens.size()) + " values, expected Nx = " + std::to_string(grid.nx()));
      }
      for (int x = 0; x < grid.nx(); ++x) {
        grid.setLabel(x, y, z,
                      static_cast<int>(parseIntegerToken(row.tokens[x], source, row.number, "voxel value", 0, maxLabel)));
      }
      ++i;
    }
  }
  i = skipBlankLines(lines, i);
  if (i != lines.size()) {
    throwBadInput(location(source, lines[i].number, lines[i].tokens[0].column),
                  "unexpected data after the last layer (the header promises " + std::to_string(grid.nz()) +
                      " layers of " + std::to_string(grid.ny()) + " rows)");
  }
  validateVoxelParts(grid, source);
  return grid;
}

std::string formatPuz(const VoxelGrid& grid) {
  std::string out = std::to_string(grid.nx()) + " " + std::to_string(grid.ny()) + " " + std::to_string(grid.nz()) + "\n";
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        out += std::to_string(grid.label(x, y, z));
        out += ' ';
      }
      out += '\n';
    }
    out += '\n';
  }
  return out;
}

}  // namespace desia
