// SPDX-License-Identifier: GPL-3.0-or-later
// Cut point repair for plate structures (paper Section 5.2, Fig. 18; see desia/plate.h).
// A parts-graph with a cut point cannot be interlocking; the paper adds one part that bypasses
// it. Here the added parts are bars laid against two coplanar faces of plates in different groups.
#include "desia/plate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

constexpr double kMinimumWidth = 10.0;  // mm a bar needs to be worth making
constexpr double kWidthPerThickness = 3.0;


// A planar face of a plate: one of its loops (the outline, or a side quad) and its outward normal.
struct Face {
  Loop loop;
  Vec3 normal;
};

std::vector<Face> facesOf(const Plate& plate) {
  const Vec3 axis = plateThicknessAxis(plate);
  std::vector<Face> faces{{plate.bottom[0], negated(axis)}, {plate.top[0], axis}};
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const std::vector<Vec3> normals = plateSideNormals(plate, l);
    const Loop& b = plate.bottom[l];
    const Loop& t = plate.top[l];
    for (size_t k = 0; k < b.size(); ++k) {
      const size_t next = (k + 1) % b.size();
      faces.push_back({{b[k], b[next], t[next], t[k]}, normals[k]});
    }
  }
  return faces;
}

double thicknessOf(const Plate& plate) {
  const Vec3 d{plate.top[0][0][0] - plate.bottom[0][0][0], plate.top[0][0][1] - plate.bottom[0][0][1],
               plate.top[0][0][2] - plate.bottom[0][0][2]};
  return std::abs(dot(d, plateThicknessAxis(plate)));
}

// A frame of the design's own: the plane of a face, u along the face's longest edge, v across it.
// Bars are laid out and kept clear of the other plates in it, so that a turned design is repaired
// as the design itself (in world axes, a turned design may find no bar, or a bar skewed to the
// design that then does not design).
struct DesignFrame {
  Vec3 origin, normal, u, v;
};

DesignFrame frameOfFace(const Loop& loop, const Vec3& normal) {
  size_t longest = 0;
  for (size_t k = 0; k < loop.size(); ++k) {
    if (norm(minus(loop[(k + 1) % loop.size()], loop[k])) > norm(minus(loop[(longest + 1) % loop.size()], loop[longest])))
      longest = k;
  }
  Vec3 edge = minus(loop[(longest + 1) % loop.size()], loop[longest]);
  edge = minus(edge, scaled(normal, dot(edge, normal)));
  const Vec3 u = normalized(edge);
  return {loop[0], normal, u, cross(normal, u)};
}

using Box3 = std::array<double, 6>;  // min u, v, n, max u, v, n in a DesignFrame

Box3 boxOf(const Plate& plate, const DesignFrame& frame) {
  Box3 box{HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      for (const Vec3& p : loop) {
        const Vec3 d = minus(p, frame.origin);
        const std::array<double, 3> c{dot(d, frame.u), dot(d, frame.v), dot(d, frame.normal)};
        for (int k = 0; k < 3; ++k) box[k] = std::min(box[k], c[k]), box[k + 3] = std::max(box[k + 3], c[k]);
      }
    }
  }
  return box;
}

// Do the boxes share a volume thicker than the tolerance in every direction?
bool boxesOverlap(const Box3& a, const Box3& b, double tolerance) {
  for (int k = 0; k < 3; ++k) {
    if (std::min(a[k + 3], b[k + 3]) - std::max(a[k], b[k]) <= tolerance) return false;
  }
  return true;
}

struct Bar {
  Plate plate;
  double area = HUGE_VAL;
  int from = -1, to = -1;  // the plates it joins
  DesignFrame frame;       // the frame it was laid out in
};

// The bar against face f of plate p and face g of plate q (coplanar, same outward normal): across
// the width their extents share, from the far end of one to the far end of the other.
std::optional<Bar> barBetween(const Face& f, const Face& g, double thickness) {
  const DesignFrame frame = frameOfFace(f.loop, f.normal);
  auto extent = [&](const Loop& loop) {
    std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Vec3& p : loop) {
      const double x = dot(minus(p, frame.origin), frame.u), y = dot(minus(p, frame.origin), frame.v);
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
    return box;
  };
  const std::array<double, 4> a = extent(f.loop), b = extent(g.loop);
  const double sharedU = std::min(a[2], b[2]) - std::max(a[0], b[0]);
  const double sharedV = std::min(a[3], b[3]) - std::max(a[1], b[1]);
  if ((sharedU > 0) == (sharedV > 0)) return std::nullopt;  // side by side along one axis only
  const bool alongU = sharedV > 0;                          // the bar runs along u, across v's shared width
  const double shared = alongU ? sharedV : sharedU;
  if (shared < kMinimumWidth) return std::nullopt;
  const double width = std::min(shared, kWidthPerThickness * thickness);
  const double middle =
      alongU ? (std::max(a[1], b[1]) + std::min(a[3], b[3])) / 2 : (std::max(a[0], b[0]) + std::min(a[2], b[2])) / 2;
  const double start = alongU ? std::min(a[0], b[0]) : std::min(a[1], b[1]);
  const double end = alongU ? std::max(a[2], b[2]) : std::max(a[3], b[3]);
  auto at = [&](double along, double across) {
    const double x = alongU ? along : across, y = alongU ? across : along;
    return plus(frame.origin, plus(scaled(frame.u, x), scaled(frame.v, y)));
  };
  Loop bottom{at(start, middle - width / 2), at(end, middle - width / 2), at(end, middle + width / 2),
              at(start, middle + width / 2)};
  Loop top;
  for (const Vec3& p : bottom) top.push_back(plus(p, scaled(f.normal, thickness)));
  Bar bar;
  bar.plate.bottom = {bottom};
  bar.plate.top = {top};
  bar.area = (end - start) * width;
  bar.frame = frame;
  return bar;
}

// Groups of plates once `cut` is taken away (connected components of the rest of the parts-graph).
std::vector<int> groupsWithout(int plateCount, const std::vector<PlateContact>& contacts, int cut) {
  std::vector<int> group(plateCount, -1);
  int groups = 0;
  for (int start = 0; start < plateCount; ++start) {
    if (start == cut || group[start] >= 0) continue;
    std::vector<int> stack{start};
    group[start] = groups;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      for (const PlateContact& c : contacts) {
        const int other = c.a == p ? c.b : (c.b == p ? c.a : -1);
        if (other < 0 || other == cut || group[other] >= 0) continue;
        group[other] = groups;
        stack.push_back(other);
      }
    }
    ++groups;
  }
  return group;
}

// The smallest bar joining two groups that `cut` separates, clear of every plate.
std::optional<Bar> smallestBar(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts, int cut,
                               const PlateOptions& options) {
  const std::vector<int> group = groupsWithout(static_cast<int>(plates.size()), contacts, cut);
  std::vector<std::vector<Face>> faces;
  for (const Plate& plate : plates) faces.push_back(facesOf(plate));
  std::optional<Bar> best;
  for (size_t p = 0; p < plates.size(); ++p) {
    for (size_t q = p + 1; q < plates.size(); ++q) {
      if (group[p] < 0 || group[q] < 0 || group[p] == group[q]) continue;
      const double thickness = std::min(thicknessOf(plates[p]), thicknessOf(plates[q]));
      for (const Face& f : faces[p]) {
        for (const Face& g : faces[q]) {
          if (dot(f.normal, g.normal) < 1 - tolerance::kFacingCosine) continue;
          if (std::abs(dot(minus(g.loop[0], f.loop[0]), f.normal)) > tolerance::kContactMm) continue;
          std::optional<Bar> bar = barBetween(f, g, thickness);
          if (!bar || (best && bar->area >= best->area)) continue;
          // Clear of every plate: boxes in the bar's own frame (exact for the bar).
          const Box3 barBox = boxOf(bar->plate, bar->frame);
          bool clear = true;
          for (size_t k = 0; k < plates.size() && clear; ++k)
            clear = !boxesOverlap(barBox, boxOf(plates[k], bar->frame), options.contactTolerance);
          if (!clear) continue;
          bar->from = static_cast<int>(p);
          bar->to = static_cast<int>(q);
          best = bar;
        }
      }
    }
  }
  return best;
}

}  // namespace

std::optional<PlateRepair> proposeCutPointRepair(const std::vector<Plate>& plates, const PlateOptions& options) {
  PlateRepair repair;
  repair.plates = plates;
  int nextId = 0;
  for (const Plate& plate : plates) nextId = std::max(nextId, plate.id);
  std::ostringstream message;
  // Every bar joins two groups, so at most one bar per plate ends all cut points.
  for (size_t round = 0; round <= plates.size(); ++round) {
    const std::vector<PlateContact> contacts = computePlateContacts(repair.plates, options);
    const std::vector<int> cuts = plateCutPoints(static_cast<int>(repair.plates.size()), contacts);
    if (cuts.empty()) break;
    const std::optional<Bar> bar = smallestBar(repair.plates, contacts, cuts[0], options);
    if (!bar) return std::nullopt;
    Plate added = bar->plate;
    added.id = ++nextId;
    added.name = "bar joining plates " + std::to_string(repair.plates[bar->from].id) + " and " +
                 std::to_string(repair.plates[bar->to].id);
    message << (repair.added.empty() ? "" : "; ") << "plate " << added.id << ", a bar joining plates "
            << repair.plates[bar->from].id << " and " << repair.plates[bar->to].id << " past cut point "
            << repair.plates[cuts[0]].id;
    repair.added.push_back(static_cast<int>(repair.plates.size()));
    repair.plates.push_back(added);
  }
  if (repair.added.empty()) return std::nullopt;
  const std::vector<PlateContact> contacts = computePlateContacts(repair.plates, options);
  if (!plateCutPoints(static_cast<int>(repair.plates.size()), contacts).empty()) return std::nullopt;
  validatePlates(repair.plates, options, "the repaired design");
  repair.message = "added " + message.str();
  return repair;
}

}  // namespace desia
