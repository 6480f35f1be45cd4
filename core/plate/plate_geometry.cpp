// SPDX-License-Identifier: GPL-3.0-or-later
// Plate geometry (paper Section 5.2): a plate's axis and side normals, its faces as a solid, and
// the parts-graph of the plates (connected, its cut points). The plates' validation, their
// contacts and their crossings are in plate_validation.cpp, plate_contacts.cpp and
// plate_overlaps.cpp; the 2D booleans there are done by Clipper (Angus Johnson's library,
// Debian's libpolyclipping) on integer coordinates, exact and the same natively and in
// WebAssembly.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/plane_frame.h"
#include "plate/plate_solid.h"

namespace desia {
namespace geometry {

Vec3 centroidOf(const Loop& loop) {
  Vec3 c{0, 0, 0};
  for (const Vec3& p : loop) c = plus(c, p);
  return scaled(c, 1.0 / static_cast<double>(loop.size()));
}

std::string plateName(const Plate& plate) {
  return "plate " + std::to_string(plate.id) + (plate.name.empty() ? "" : " (" + plate.name + ")");
}

std::string millimetres(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value << " mm";
  return out.str();
}

std::string preciseMillimetres(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(std::abs(value) < 1 ? 6 : 4);
  out << value << " mm";
  return out.str();
}

std::vector<SolidFace> solidFaces(const Plate& plate) {
  const Vec3 axis = plateThicknessAxis(plate);
  std::vector<SolidFace> faces{{plate.bottom, negated(axis)}, {plate.top, axis}};
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& bottom = plate.bottom[l];
    const Loop& top = plate.top[l];
    const std::vector<Vec3> normals = plateSideNormals(plate, l);
    for (size_t k = 0; k < bottom.size(); ++k) {
      const size_t next = (k + 1) % bottom.size();
      faces.push_back({{Loop{bottom[k], bottom[next], top[next], top[k]}}, normals[k]});
    }
  }
  return faces;
}

double maxDistanceToPlane(const std::vector<Loop>& loops, const PlaneFrame& frame) {
  double worst = 0;
  for (const Loop& loop : loops) {
    for (const Vec3& p : loop) worst = std::max(worst, std::abs(dot(minus(p, frame.origin), frame.normal)));
  }
  return worst;
}

Box boxOf(const Plate& plate) {
  Box box;
  for (const auto* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      for (const Vec3& p : loop) box.add(p);
    }
  }
  return box;
}

}  // namespace geometry

using geometry::centroidOf;
using geometry::plateName;

namespace {

// Even-odd test of a point of the bottom face's plane against all its loops (outline and holes).
bool insideBottomFace(const Plate& plate, const PlaneFrame& frame, const Vec3& point) {
  const double px = dot(minus(point, frame.origin), frame.u), py = dot(minus(point, frame.origin), frame.v);
  bool inside = false;
  for (const Loop& loop : plate.bottom) {
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const double xi = dot(minus(loop[i], frame.origin), frame.u), yi = dot(minus(loop[i], frame.origin), frame.v);
      const double xj = dot(minus(loop[j], frame.origin), frame.u), yj = dot(minus(loop[j], frame.origin), frame.v);
      if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

Vec3 loopNormal(const Loop& loop) {
  Vec3 n{0, 0, 0};
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = loop[i];
    const Vec3& q = loop[(i + 1) % loop.size()];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

Vec3 plateThicknessAxis(const Plate& plate) {
  Vec3 n = normalized(loopNormal(plate.bottom[0]));
  if (dot(n, minus(centroidOf(plate.top[0]), centroidOf(plate.bottom[0]))) < 0) n = negated(n);
  return n;
}

// A side face's normal points out of the solid: a step from the middle of its bottom edge along
// the normal (projected into the bottom plane) must leave the bottom face. Loop orientation and
// holes need no separate rules this way. The quads of one loop all turn the same way about it,
// so the step is taken once per loop, from its longest edge: a step per edge (each a
// point-in-polygon test) would make this quadratic in the loop's vertices.
std::vector<Vec3> plateSideNormals(const Plate& plate, size_t loopIndex) {
  const Vec3 axis = plateThicknessAxis(plate);
  const Loop& bottom = plate.bottom[loopIndex];
  const Loop& top = plate.top[loopIndex];
  std::vector<Vec3> normals;
  size_t longest = 0;
  for (size_t k = 0; k < bottom.size(); ++k) {
    const size_t next = (k + 1) % bottom.size();
    normals.push_back(normalized(loopNormal(Loop{bottom[k], bottom[next], top[next], top[k]})));
    if (norm(minus(bottom[next], bottom[k])) >
        norm(minus(bottom[(longest + 1) % bottom.size()], bottom[longest])))
      longest = k;
  }
  if (normals.empty()) return normals;
  const PlaneFrame bottomFrame(centroidOf(plate.bottom[0]), axis);
  constexpr double kStep = tolerance::kInsideProbeMm;
  const Vec3& n = normals[longest];
  const Vec3 inPlane = normalized(minus(n, scaled(axis, dot(n, axis))));
  const Vec3 middle = scaled(plus(bottom[longest], bottom[(longest + 1) % bottom.size()]), 0.5);
  if (insideBottomFace(plate, bottomFrame, plus(middle, scaled(inPlane, kStep)))) {
    for (Vec3& normal : normals) normal = negated(normal);
  }
  return normals;
}

void requireConnectedPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                            const std::string& source) {
  const int n = static_cast<int>(plates.size());
  if (n < 2) return;
  std::vector<int> group(n);
  for (int i = 0; i < n; ++i) group[i] = i;
  auto find = [&](int x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  std::vector<bool> touches(n, false);
  for (const PlateContact& c : contacts) {
    touches[c.a] = touches[c.b] = true;
    group[find(c.a)] = find(c.b);
  }
  for (int i = 0; i < n; ++i) {
    if (!touches[i])
      throwBadInput(source,
                    plateName(plates[i]) + " touches no other plate (no face of it lies on another plate's face)");
  }
  std::vector<int> firstOfGroup;
  for (int i = 0; i < n; ++i) {
    if (find(i) == i) firstOfGroup.push_back(i);
  }
  if (firstOfGroup.size() > 1) {
    std::string groups;
    for (size_t g = 0; g < firstOfGroup.size() && g < 4; ++g) {
      std::string members;
      int count = 0;
      for (int i = 0; i < n && count < 6; ++i) {
        if (find(i) == firstOfGroup[g]) members += (count++ ? ", " : "") + std::to_string(plates[i].id);
      }
      groups += (g ? "; " : "") + std::string("plates ") + members;
    }
    throwBadInput(source, "the design falls apart into " + std::to_string(firstOfGroup.size()) +
                              " groups that do not touch: " + groups);
  }
}

Assembly assemblyFromPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts) {
  Assembly assembly;
  for (const Plate& plate : plates) assembly.parts.push_back({plate.id, plate.name});
  // A crossing blocks nothing yet: it is a joint to be cut (it joins the parts-graph all the same).
  for (const PlateContact& c : contacts) {
    if (!c.crossing) assembly.contacts.push_back({c.a, c.b, c.normal, c.area});
  }
  return assembly;
}

std::vector<int> plateCutPoints(int plateCount, const std::vector<PlateContact>& contacts) {
  std::vector<std::pair<int, int>> edges;
  for (const PlateContact& c : contacts) edges.push_back({c.a, c.b});
  return findCutPoints(plateCount, edges);
}

}  // namespace desia
