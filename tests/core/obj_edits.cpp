// SPDX-License-Identifier: GPL-3.0-or-later
#include "obj_edits.h"

#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

#include "analysis/vec3.h"

namespace desia::testing {

std::string dentedObj(const std::string& obj, double depth) {
  std::vector<std::string> lines;
  std::vector<std::pair<size_t, Vec3>> vertices;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      Vec3 p{};
      std::istringstream(line.substr(2)) >> p[0] >> p[1] >> p[2];
      vertices.push_back({lines.size(), p});
    }
    lines.push_back(line);
  }
  for (int corner = 0; corner < 8 && !vertices.empty(); ++corner) {
    const Vec3 s{corner & 1 ? -1.0 : 1.0, corner & 2 ? -1.0 : 1.0, corner & 4 ? -1.0 : 1.0};
    Vec3 farthest = vertices.front().second;
    for (const auto& vertex : vertices) {
      if (dot(vertex.second, s) > dot(farthest, s)) farthest = vertex.second;
    }
    const Vec3 dented = minus(farthest, scaled(s, depth));
    char text[128];
    std::snprintf(text, sizeof text, "v %.17g %.17g %.17g", dented[0], dented[1], dented[2]);
    for (const auto& vertex : vertices) {
      if (vertex.second == farthest) lines[vertex.first] = text;
    }
  }
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

}  // namespace desia::testing
