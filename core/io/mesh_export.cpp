// SPDX-License-Identifier: GPL-3.0-or-later
// STL (binary, ASCII) and OBJ writers for the part surfaces of a voxel assembly.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "io/export_internals.h"

namespace desia {
namespace {

using Vec = std::array<double, 3>;

// Little-endian by construction (STL is little-endian whatever the machine).
void appendUint32(std::string& out, uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((value >> shift) & 0xffu));
}

void appendFloat(std::string& out, double value) {
  const float single = static_cast<float>(value);
  uint32_t bits = 0;
  std::memcpy(&bits, &single, sizeof bits);
  appendUint32(out, bits);
}

// Unit normal of a triangle, with +0 for zero components (never -0, so the bytes are stable).
Vec unitNormal(const Vec& a, const Vec& b, const Vec& c) {
  const Vec e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  Vec n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& value : n) value = (length > 0 ? value / length : 0.0) + 0.0;
  return n;
}

template <typename Visit>
void forEachTriangle(const std::vector<NamedMesh>& parts, Visit&& visit) {
  for (const NamedMesh& part : parts) {
    for (const auto& t : part.mesh.triangles) {
      visit(part.mesh.vertices[t[0]], part.mesh.vertices[t[1]], part.mesh.vertices[t[2]]);
    }
  }
}

}  // namespace

std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value + 0.0);
  return buffer;
}

// 80-byte header (not starting with "solid", which some readers take for ASCII STL), the
// triangle count, then per triangle the normal, three vertices (float32) and a zero attribute.
std::string binaryStl(const std::vector<NamedMesh>& parts, const std::string& title) {
  uint64_t triangles = 0;
  for (const NamedMesh& part : parts) triangles += part.mesh.triangles.size();
  std::string out = ("desia " + title).substr(0, 80);
  out.resize(80, ' ');
  out.reserve(84 + 50 * triangles);
  appendUint32(out, static_cast<uint32_t>(triangles));
  forEachTriangle(parts, [&](const Vec& a, const Vec& b, const Vec& c) {
    for (double value : unitNormal(a, b, c)) appendFloat(out, value);
    for (const Vec* vertex : {&a, &b, &c}) {
      for (double value : *vertex) appendFloat(out, value);
    }
    out.append(2, '\0');
  });
  return out;
}

// One solid holding every triangle (some readers take only the first solid of a file).
std::string asciiStl(const std::vector<NamedMesh>& parts, const std::string& solidName) {
  std::string out = "solid " + solidName + "\n";
  forEachTriangle(parts, [&](const Vec& a, const Vec& b, const Vec& c) {
    const Vec n = unitNormal(a, b, c);
    out += "facet normal " + formatNumber(n[0]) + " " + formatNumber(n[1]) + " " + formatNumber(n[2]) + "\n";
    out += "  outer loop\n";
    for (const Vec* vertex : {&a, &b, &c}) {
      out += "    vertex " + formatNumber((*vertex)[0]) + " " + formatNumber((*vertex)[1]) + " " +
             formatNumber((*vertex)[2]) + "\n";
    }
    out += "  endloop\nendfacet\n";
  });
  out += "endsolid " + solidName + "\n";
  return out;
}

// One `o partN` object per part; vertex numbers are 1-based and global across the file, as OBJ
// wants. The vertices of each part are its own, so every object is a closed mesh on its own.
std::string wavefrontObj(const std::vector<NamedMesh>& parts, const std::string& title) {
  std::string out = "# desia " + title + "\n";
  int64_t firstVertex = 1;
  for (const NamedMesh& part : parts) {
    out += "o " + (part.name.empty() ? "part" + std::to_string(part.partId) : part.name) + "\n";
    for (const Vec& v : part.mesh.vertices) {
      out += "v " + formatNumber(v[0]) + " " + formatNumber(v[1]) + " " + formatNumber(v[2]) + "\n";
    }
    for (const auto& t : part.mesh.triangles) {
      out += "f " + std::to_string(firstVertex + t[0]) + " " + std::to_string(firstVertex + t[1]) + " " +
             std::to_string(firstVertex + t[2]) + "\n";
    }
    firstVertex += static_cast<int64_t>(part.mesh.vertices.size());
  }
  return out;
}

}  // namespace desia
