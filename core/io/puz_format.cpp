// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/puz_format.h"

#include <cctype>

#include "desia/error.h"
#include "io/text_lines.h"

namespace desia {
namespace {

// The next line that has tokens (blank lines separate layers); false at the end of the text.
bool nextLineWithData(TextLineReader& reader, TextLine& line) {
  while (reader.next(line)) {
    if (!line.tokens.empty()) return true;
  }
  return false;
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
  TextLineReader reader(text, source);
  TextLine line;
  if (!nextLineWithData(reader, line)) throwBadInput(source, "the file is empty: expected the header 'Nx Ny Nz'");
  VoxelGrid grid = parseHeader(line, source);
  // Labels above the voxel count cannot be contiguous part ids; the bound also stops overflow.
  const int64_t maxLabel = grid.voxelCount();
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      if (!nextLineWithData(reader, line)) {
        throwBadInput(location(source, reader.lastLineWithData()),
                      "the file ends early: expected row " + std::to_string(y + 1) + " of " +
                          std::to_string(grid.ny()) + " in layer " + std::to_string(z + 1) + " of " +
                          std::to_string(grid.nz()) + " (grid " + std::to_string(grid.nx()) + " x " +
                          std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) + ")");
      }
      if (static_cast<int>(line.tokens.size()) != grid.nx()) {
        throwBadInput(location(source, line.number),
                      "row " + std::to_string(y + 1) + " of layer " + std::to_string(z + 1) + " has " +
                          std::to_string(line.tokens.size()) + " values, expected Nx = " + std::to_string(grid.nx()));
      }
      for (int x = 0; x < grid.nx(); ++x) {
        grid.setLabel(x, y, z,
                      static_cast<int>(parseIntegerToken(line.tokens[x], source, line.number, "voxel value", 0, maxLabel)));
      }
    }
  }
  if (nextLineWithData(reader, line)) {
    throwBadInput(location(source, line.number, line.tokens[0].column),
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
