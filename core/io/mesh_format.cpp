// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ and STL readers (written for desia) and the closed-mesh check.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "desia/error.h"
#include "desia/formats.h"
#include "io/text_lines.h"

namespace desia {
namespace {

using Vertex = std::array<double, 3>;

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

bool endsWithIgnoringCase(const std::string& text, std::string_view suffix) {
  return text.size() >= suffix.size() &&
         equalsIgnoringCase(std::string_view(text).substr(text.size() - suffix.size()), suffix);
}

std::string quoted(std::string_view token) {
  constexpr size_t kShown = 40;
  std::string shown(token.substr(0, kShown));
  if (token.size() > kShown) shown += "...";
  return "'" + shown + "'";
}

// Whitespace-separated tokens of one line; a token starting with '#' ends the line (a comment).
// Returns false (and the offset of the byte) when the line holds a NUL byte: not a text file.
bool splitLine(std::string_view line, std::vector<std::string_view>& tokens, size_t& nulOffset) {
  tokens.clear();
  size_t i = 0;
  while (i < line.size()) {
    if (line[i] == '\0') {
      nulOffset = i;
      return false;
    }
    if (isSpace(line[i])) {
      ++i;
      continue;
    }
    if (line[i] == '#') break;
    const size_t start = i;
    while (i < line.size() && !isSpace(line[i]) && line[i] != '\0') ++i;
    tokens.push_back(line.substr(start, i - start));
  }
  return true;
}

// Calls `visit(lineView, lineNumber, lineOffset)` for each line (split at '\n').
template <typename Visit>
void forEachLine(const std::string& text, Visit&& visit) {
  size_t offset = 0;
  int number = 0;
  while (offset < text.size()) {
    size_t end = text.find('\n', offset);
    if (end == std::string::npos) end = text.size();
    ++number;
    visit(std::string_view(text).substr(offset, end - offset), number, offset);
    offset = end + 1;
  }
}

[[noreturn]] void throwNotText(const std::string& source, int line, size_t offset) {
  throwBadInput(location(source, line), "not a text file: unexpected byte 0x00 at offset " + std::to_string(offset));
}

// A decimal number as OBJ and STL writers print them: [+-] digits [. digits] [e [+-] digits].
// Rejects nan, inf, hex floats and trailing junk; "1e999" is a number but not finite.
enum class NumberStatus { Ok, NotANumber, NotFinite };

NumberStatus parseNumber(std::string_view token, double& value) {
  size_t i = 0;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  size_t digits = 0;
  while (i < token.size() && token[i] >= '0' && token[i] <= '9') ++i, ++digits;
  if (i < token.size() && token[i] == '.') {
    ++i;
    while (i < token.size() && token[i] >= '0' && token[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) return NumberStatus::NotANumber;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    size_t exponentDigits = 0;
    while (i < token.size() && token[i] >= '0' && token[i] <= '9') ++i, ++exponentDigits;
    if (exponentDigits == 0) return NumberStatus::NotANumber;
  }
  if (i != token.size()) return NumberStatus::NotANumber;
  // strtod needs a terminated string; correctly rounded in glibc and in Emscripten's musl alike.
  char buffer[512];
  std::string copy;
  const char* start = buffer;
  if (token.size() < sizeof buffer) {
    std::memcpy(buffer, token.data(), token.size());
    buffer[token.size()] = '\0';
  } else {
    copy.assign(token);
    start = copy.c_str();
  }
  value = std::strtod(start, nullptr);
  return std::isfinite(value) ? NumberStatus::Ok : NumberStatus::NotFinite;
}

double parseCoordinate(std::string_view token, const std::string& source, int line, const char* what) {
  double value = 0;
  switch (parseNumber(token, value)) {
    case NumberStatus::Ok:
      return value;
    case NumberStatus::NotANumber:
      throwBadInput(location(source, line), std::string(what) + " " + quoted(token) + " is not a number");
    case NumberStatus::NotFinite:
      throwBadInput(location(source, line), std::string(what) + " " + quoted(token) + " is not finite");
  }
  return value;
}

void addTriangle(TriangleMesh& mesh, int a, int b, int c, const std::string& source, int line) {
  if (a == b || b == c || a == c) return;  // zero area: contributes nothing to a solid
  if (static_cast<int64_t>(mesh.triangles.size()) >= MeshLimits::kMaxTriangles) {
    throw Error(ErrorCode::TooLarge, location(source, line) + ": the mesh has more than " +
                                         std::to_string(MeshLimits::kMaxTriangles) + " triangles (the limit)");
  }
  mesh.triangles.push_back({a, b, c});
}

// ---- OBJ -------------------------------------------------------------------------------------

// Resolves one face reference ("7", "7/2", "7/2/5", "7//5", "-1") to a 0-based vertex index.
int objVertexIndex(std::string_view token, int definedSoFar, int64_t totalVertices, const std::string& source,
                   int line) {
  const std::string_view reference = token.substr(0, token.find('/'));
  if (std::count(token.begin(), token.end(), '/') > 2) {
    throwBadInput(location(source, line), "face vertex " + quoted(token) + " is not 'v', 'v/vt', 'v/vt/vn' or 'v//vn'");
  }
  size_t i = 0;
  const bool negative = !reference.empty() && reference[0] == '-';
  if (!reference.empty() && (reference[0] == '-' || reference[0] == '+')) i = 1;
  int64_t value = 0;
  bool digits = i < reference.size();
  for (; i < reference.size() && digits; ++i) {
    if (reference[i] < '0' || reference[i] > '9') {
      digits = false;
    } else if (value <= (int64_t{1} << 40)) {  // larger values are out of range anyway
      value = value * 10 + (reference[i] - '0');
    }
  }
  if (!digits) throwBadInput(location(source, line), "face index " + quoted(reference) + " is not an integer");
  if (value == 0) {
    throwBadInput(location(source, line),
                  "face index 0 is invalid (OBJ indices start at 1; negative ones count back from the last vertex)");
  }
  if (negative) {
    if (value > definedSoFar) {
      throwBadInput(location(source, line), "face index " + std::string(reference) + " refers to no vertex (only " +
                                                std::to_string(definedSoFar) +
                                                " vertices are defined before this line)");
    }
    return definedSoFar - static_cast<int>(value);
  }
  if (value > totalVertices) {
    throwBadInput(location(source, line), "face index " + std::string(reference) + " out of range (mesh has " +
                                              std::to_string(totalVertices) + " vertices)");
  }
  return static_cast<int>(value - 1);
}

// ---- STL -------------------------------------------------------------------------------------

uint32_t readUint32LittleEndian(const unsigned char* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}

float readFloatLittleEndian(const unsigned char* p) {
  const uint32_t bits = readUint32LittleEndian(p);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

bool isBinaryStlSize(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  const uint64_t count = readUint32LittleEndian(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  return 84 + 50 * count == bytes.size();
}

bool startsWithSolid(const std::string& bytes) {
  size_t i = 0;
  while (i < bytes.size() && (isSpace(bytes[i]) || bytes[i] == '\n')) ++i;
  return bytes.size() - i >= 5 && equalsIgnoringCase(std::string_view(bytes).substr(i, 5), "solid") &&
         (bytes.size() - i == 5 || isSpace(bytes[i + 5]) || bytes[i + 5] == '\n');
}

// Merges vertices with identical coordinates (STL stores each triangle's corners separately) and
// numbers them in order of first appearance. Sorting with the index as the last key makes the
// result independent of the sort algorithm.
TriangleMesh weldTriangleSoup(const std::vector<Vertex>& corners, const std::string& source,
                              const std::vector<int>& cornerLines) {
  const size_t n = corners.size();
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    if (corners[a] != corners[b]) return corners[a] < corners[b];
    return a < b;
  });
  std::vector<uint32_t> representative(n);
  for (size_t k = 0; k < n;) {
    size_t end = k + 1;
    while (end < n && corners[order[end]] == corners[order[k]]) ++end;
    for (size_t m = k; m < end; ++m) representative[order[m]] = order[k];  // the smallest index
    k = end;
  }
  order.clear();
  order.shrink_to_fit();
  TriangleMesh mesh;
  std::vector<int> id(n, -1);
  for (size_t k = 0; k < n; ++k) {
    if (representative[k] == k) {
      id[k] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(corners[k]);
    } else {
      id[k] = id[representative[k]];
    }
  }
  for (size_t t = 0; t + 2 < n; t += 3) {
    addTriangle(mesh, id[t], id[t + 1], id[t + 2], source, cornerLines.empty() ? 0 : cornerLines[t]);
  }
  return mesh;
}

TriangleMesh parseBinaryStl(const std::string& bytes, const std::string& source) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const uint32_t count = readUint32LittleEndian(data + 80);
  if (count > MeshLimits::kMaxTriangles) {
    throw Error(ErrorCode::TooLarge, source + ": the binary STL has " + std::to_string(count) +
                                         " triangles, more than the limit of " +
                                         std::to_string(MeshLimits::kMaxTriangles));
  }
  std::vector<Vertex> corners;
  corners.reserve(static_cast<size_t>(count) * 3);
  for (uint32_t t = 0; t < count; ++t) {
    const unsigned char* record = data + 84 + 50 * static_cast<size_t>(t);
    for (int corner = 0; corner < 3; ++corner) {
      Vertex v;
      for (int axis = 0; axis < 3; ++axis) {
        const float value = readFloatLittleEndian(record + 12 + 12 * corner + 4 * axis);
        if (!std::isfinite(value)) {
          throwBadInput(source, "binary STL triangle " + std::to_string(t + 1) +
                                    " has a coordinate that is not finite (" + (std::isnan(value) ? "nan" : "inf") +
                                    ")");
        }
        v[axis] = value;
      }
      corners.push_back(v);
    }
  }
  return weldTriangleSoup(corners, source, {});
}

TriangleMesh parseAsciiStl(const std::string& text, const std::string& source) {
  enum class State { Top, InSolid, InFacet, InLoop, AfterLoop };
  State state = State::Top;
  std::vector<Vertex> corners;
  std::vector<int> cornerLines;
  std::vector<Vertex> loop;
  int loopLine = 0;
  int lastLine = 1;
  std::vector<std::string_view> tokens;
  auto fail = [&](int line, const std::string& what) { throwBadInput(location(source, line), what); };
  forEachLine(text, [&](std::string_view lineText, int line, size_t offset) {
    size_t nulOffset = 0;
    if (!splitLine(lineText, tokens, nulOffset)) {
      fail(line, "not a text file: unexpected byte 0x00 at offset " + std::to_string(offset + nulOffset) +
                     " (a binary STL must be 84 + 50 x triangles bytes; this file has " + std::to_string(text.size()) +
                     ")");
    }
    if (tokens.empty()) return;
    lastLine = line;
    const std::string_view keyword = tokens[0];
    auto expect = [&](const char* expected) {
      fail(line, std::string("expected ") + expected + ", found " + quoted(keyword));
    };
    switch (state) {
      case State::Top:
        if (!equalsIgnoringCase(keyword, "solid")) expect("'solid'");
        state = State::InSolid;
        break;
      case State::InSolid:
        if (equalsIgnoringCase(keyword, "facet")) {
          state = State::InFacet;
        } else if (equalsIgnoringCase(keyword, "endsolid")) {
          state = State::Top;
        } else {
          expect("'facet' or 'endsolid'");
        }
        break;
      case State::InFacet:
        if (!equalsIgnoringCase(keyword, "outer") || tokens.size() < 2 || !equalsIgnoringCase(tokens[1], "loop")) {
          expect("'outer loop'");
        }
        state = State::InLoop;
        loop.clear();
        loopLine = line;
        break;
      case State::InLoop:
        if (equalsIgnoringCase(keyword, "vertex")) {
          if (tokens.size() != 4) {
            fail(line, "vertex has " + std::to_string(tokens.size() - 1) + " coordinates, expected 'vertex x y z'");
          }
          loop.push_back({parseCoordinate(tokens[1], source, line, "vertex coordinate"),
                          parseCoordinate(tokens[2], source, line, "vertex coordinate"),
                          parseCoordinate(tokens[3], source, line, "vertex coordinate")});
        } else if (equalsIgnoringCase(keyword, "endloop")) {
          if (loop.size() < 3) {
            fail(line, "the loop has " + std::to_string(loop.size()) + " vertices, a facet needs at least 3");
          }
          for (size_t k = 1; k + 1 < loop.size(); ++k) {
            if (static_cast<int64_t>(corners.size()) >= 3 * MeshLimits::kMaxTriangles) {
              throw Error(ErrorCode::TooLarge, location(source, line) + ": the mesh has more than " +
                                                   std::to_string(MeshLimits::kMaxTriangles) +
                                                   " triangles (the limit)");
            }
            for (const Vertex& v : {loop[0], loop[k], loop[k + 1]}) {
              corners.push_back(v);
              cornerLines.push_back(loopLine);
            }
          }
          state = State::AfterLoop;
        } else {
          expect("'vertex x y z' or 'endloop'");
        }
        break;
      case State::AfterLoop:
        if (!equalsIgnoringCase(keyword, "endfacet")) expect("'endfacet'");
        state = State::InSolid;
        break;
    }
  });
  // A missing final "endsolid" is forgiven; a file cut inside a facet is not.
  if (state == State::InFacet || state == State::InLoop || state == State::AfterLoop) {
    throwBadInput(location(source, lastLine), "the file ends inside a facet (expected 'endloop' / 'endfacet')");
  }
  return weldTriangleSoup(corners, source, cornerLines);
}

}  // namespace

TriangleMesh parseObj(const std::string& text, const std::string& source) {
  std::vector<std::string_view> tokens;
  // Pass 1: count the vertices, so positive indices can be checked against the whole file (a
  // face may name a vertex defined further down) and memory reserved once.
  int64_t totalVertices = 0;
  forEachLine(text, [&](std::string_view lineText, int line, size_t offset) {
    size_t nulOffset = 0;
    if (!splitLine(lineText, tokens, nulOffset)) throwNotText(source, line, offset + nulOffset);
    if (!tokens.empty() && tokens[0] == "v") ++totalVertices;
  });
  if (totalVertices > MeshLimits::kMaxVertices) {
    throw Error(ErrorCode::TooLarge, source + ": the mesh has " + std::to_string(totalVertices) +
                                         " vertices, more than the limit of " +
                                         std::to_string(MeshLimits::kMaxVertices));
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(totalVertices));
  std::vector<int> face;
  forEachLine(text, [&](std::string_view lineText, int line, size_t) {
    size_t nulOffset = 0;
    splitLine(lineText, tokens, nulOffset);
    if (tokens.empty()) return;
    if (tokens[0] == "v") {
      // x y z, then optionally w (rational curves) or r g b (vertex colours, a common extension).
      if (tokens.size() < 4 || tokens.size() > 8) {
        throwBadInput(location(source, line), "vertex has " + std::to_string(tokens.size() - 1) +
                                                  " coordinates, expected 'v x y z' (optionally followed by w)");
      }
      Vertex v;
      for (int axis = 0; axis < 3; ++axis)
        v[axis] = parseCoordinate(tokens[1 + axis], source, line, "vertex coordinate");
      for (size_t k = 4; k < tokens.size(); ++k) parseCoordinate(tokens[k], source, line, "vertex value");
      mesh.vertices.push_back(v);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) {
        throwBadInput(location(source, line),
                      "face has " + std::to_string(tokens.size() - 1) + " vertices, a face needs at least 3");
      }
      face.clear();
      const int definedSoFar = static_cast<int>(mesh.vertices.size());
      for (size_t k = 1; k < tokens.size(); ++k) {
        face.push_back(objVertexIndex(tokens[k], definedSoFar, totalVertices, source, line));
      }
      for (size_t k = 1; k + 1 < face.size(); ++k) addTriangle(mesh, face[0], face[k], face[k + 1], source, line);
      if (!mesh.groupNames.empty()) mesh.triangleGroup.resize(mesh.triangles.size(), static_cast<int>(mesh.groupNames.size()) - 1);
    } else if (tokens[0] == "o" || tokens[0] == "g") {
      // A new object or group: plate designs from modelling tools use one per plate.
      std::string name;
      for (size_t k = 1; k < tokens.size(); ++k) name += (k > 1 ? " " : "") + std::string(tokens[k]);
      if (mesh.groupNames.empty() && !mesh.triangles.empty()) {
        mesh.groupNames.push_back("");  // faces before the first record form a group of their own
        mesh.triangleGroup.assign(mesh.triangles.size(), 0);
      }
      mesh.groupNames.push_back(name);
    }
    // Every other record (vn, vt, vp, s, usemtl, mtllib, l, p, ...) does not shape the solid.
  });
  return mesh;
}

TriangleMesh parseStl(const std::string& bytes, const std::string& source) {
  if (isBinaryStlSize(bytes)) return parseBinaryStl(bytes, source);
  if (startsWithSolid(bytes)) return parseAsciiStl(bytes, source);
  if (bytes.size() < 84) {
    throwBadInput(source, "not an STL file: it does not start with 'solid' (ASCII STL) and has " +
                              std::to_string(bytes.size()) + " bytes, fewer than a binary STL's 84-byte header");
  }
  const uint64_t count = readUint32LittleEndian(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  throwBadInput(source, "not a valid binary STL: its header announces " + std::to_string(count) +
                            " triangles, which take " + std::to_string(84 + 50 * count) + " bytes, but the file has " +
                            std::to_string(bytes.size()) +
                            " bytes (and it does not start with 'solid' as ASCII STL does)");
}

TriangleMesh parseMesh(const std::string& bytes, const std::string& source) {
  if (isBinaryStlSize(bytes)) return parseBinaryStl(bytes, source);
  if (endsWithIgnoringCase(source, ".obj")) return parseObj(bytes, source);
  if (endsWithIgnoringCase(source, ".stl") || startsWithSolid(bytes)) return parseStl(bytes, source);
  return parseObj(bytes, source);
}


std::string meshShapeName(const std::string& source) {
  if (source.empty() || source[0] == '<') return "";
  const size_t slash = source.find_last_of("/\\");
  std::string name = slash == std::string::npos ? source : source.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) name.erase(dot);
  return name;
}

}  // namespace desia
