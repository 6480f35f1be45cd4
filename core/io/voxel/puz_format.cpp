// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/formats.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "desia/error.h"
#include "io/text_lines.h"

namespace desia {
namespace {

// A `#` line is a comment (the .puz files of later interlocking-puzzle research start with one).
bool isComment(const TextLine& line) { return !line.tokens.empty() && line.tokens[0].text[0] == '#'; }

// The next line that has tokens and is not a comment (blank lines separate layers); false at the
// end of the text.
bool nextLineWithData(TextLineReader& reader, TextLine& line) {
  while (reader.next(line)) {
    if (!line.tokens.empty() && !isComment(line)) return true;
  }
  return false;
}

bool isInteger(const std::string& text) {
  size_t start = text[0] == '-' || text[0] == '+' ? 1 : 0;
  if (start == text.size()) return false;
  for (size_t k = start; k < text.size(); ++k) {
    if (!std::isdigit(static_cast<unsigned char>(text[k]))) return false;
  }
  return true;
}

// The optional line after the header: three voxel edge lengths, e.g. "0.250000 0.250000 0.250000".
// Only a line of three values of which one is not an integer is read so (labels are integers).
bool isVoxelSizeLine(const TextLine& line) {
  if (line.tokens.size() != 3) return false;
  for (const Token& token : line.tokens) {
    if (!isInteger(token.text)) return true;
  }
  return false;
}

std::array<double, 3> parseVoxelSizes(const TextLine& line, const std::string& source) {
  std::array<double, 3> sizes{};
  static const char* kAxes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const Token& token = line.tokens[static_cast<size_t>(k)];
    char* end = nullptr;
    const double value = std::strtod(token.text.c_str(), &end);
    if (end != token.text.c_str() + token.text.size() || !std::isfinite(value) || !(value > 0)) {
      throwBadInput(location(source, line.number, token.column),
                    std::string("the voxel size along ") + kAxes[k] + " must be a positive number, found '" + token.text + "'");
    }
    sizes[static_cast<size_t>(k)] = value;
  }
  return sizes;
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
  bool lineStart = true, inComment = false;
  for (char c : text) {
    if (inComment) {
      if (c == '\n') inComment = false, lineStart = true;
      continue;
    }
    if (c == '\n') lineStart = true;
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (c == '#' && lineStart) {
      inComment = true;
      continue;
    }
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  }
  return false;
}

namespace {

// Labels as rows: Nz layers of Ny rows of Nx values, from `line` (the first row) on.
void readRows(TextLineReader& reader, TextLine& line, VoxelGrid& grid, const std::string& source) {
  const int64_t maxLabel = grid.voxelCount();  // labels above it cannot be contiguous part ids
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      if ((z > 0 || y > 0) && !nextLineWithData(reader, line)) {
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
}

// Labels as one flat list (x fastest, then y, then z), over as many lines as it takes.
void readFlatList(TextLineReader& reader, TextLine& line, VoxelGrid& grid, const std::string& source) {
  const int64_t count = grid.voxelCount();
  int64_t index = 0;
  do {
    for (const Token& token : line.tokens) {
      if (index == count) {
        throwBadInput(location(source, line.number, token.column),
                      "more voxel values than the grid holds (" + std::to_string(grid.nx()) + " x " +
                          std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) + " = " +
                          std::to_string(count) + ")");
      }
      grid.setLabelAt(index++, static_cast<int>(parseIntegerToken(token, source, line.number, "voxel value", 0, count)));
    }
  } while (index < count && nextLineWithData(reader, line));
  if (index < count) {
    throwBadInput(location(source, reader.lastLineWithData()),
                  "the file ends early: " + std::to_string(index) + " voxel values of " + std::to_string(count) +
                      " (grid " + std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " x " +
                      std::to_string(grid.nz()) + ")");
  }
}

}  // namespace

PuzFile readPuz(const std::string& text, const std::string& source) {
  TextLineReader reader(text, source);
  TextLine line;
  if (!nextLineWithData(reader, line)) throwBadInput(source, "the file is empty: expected the header 'Nx Ny Nz'");
  PuzFile file;
  file.grid = parseHeader(line, source);
  VoxelGrid& grid = file.grid;
  if (!nextLineWithData(reader, line)) {
    throwBadInput(location(source, reader.lastLineWithData()),
                  "the file ends early: expected row 1 of " + std::to_string(grid.ny()) + " in layer 1 of " +
                      std::to_string(grid.nz()) + " (grid " + std::to_string(grid.nx()) + " x " +
                      std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) + ")");
  }
  if (isVoxelSizeLine(line)) {
    file.voxelSize = parseVoxelSizes(line, source);
    if (!nextLineWithData(reader, line)) {
      throwBadInput(location(source, reader.lastLineWithData()), "the file ends after the voxel sizes: expected the voxel labels");
    }
  }
  // Rows of Nx values, or, when the first line holds more than a row, one flat list.
  if (static_cast<int64_t>(line.tokens.size()) > grid.nx()) {
    readFlatList(reader, line, grid, source);
  } else {
    readRows(reader, line, grid, source);
  }
  if (nextLineWithData(reader, line)) {
    throwBadInput(location(source, line.number, line.tokens[0].column),
                  "unexpected data after the last layer (the header promises " + std::to_string(grid.nz()) +
                      " layers of " + std::to_string(grid.ny()) + " rows)");
  }
  validateVoxelParts(grid, source);
  return file;
}

VoxelGrid parsePuz(const std::string& text, const std::string& source) { return readPuz(text, source).grid; }

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
