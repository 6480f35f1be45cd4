// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/side_crossings.h"

#include <algorithm>
#include <cmath>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

std::vector<int> platesCrossingBoth(const PlateGraph& graph, const PlateContact& contact) {
  // The plates crossing a (a few: its crossings), kept where they cross b too.
  std::vector<int> crossers;
  for (int c : graph.contactsOf[static_cast<size_t>(contact.a)]) {
    const PlateContact& crossing = graph.contacts[static_cast<size_t>(c)];
    if (!crossing.crossing) continue;
    const int plate = crossing.a == contact.a ? crossing.b : crossing.a;
    if (plate != contact.b && crossingBetween(graph, plate, contact.b) >= 0) crossers.push_back(plate);
  }
  std::sort(crossers.begin(), crossers.end());
  crossers.erase(std::unique(crossers.begin(), crossers.end()), crossers.end());
  return crossers;
}

namespace {

// The stretch of the side's line (distances along `along` from `origin`) that the crosser's slab,
// grown by `grow`, takes within `reach` of the side: empty (first > second) when none.
std::pair<double, double> stretchTakenBy(const Plate& crosser, const Vec3& origin, const Vec3& along,
                                         const Vec3& across, double reach, double grow) {
  const Vec3 normal = plateThicknessAxis(crosser);
  const double first = dot(crosser.bottom[0][0], normal), second = dot(crosser.top[0][0], normal);
  const double low = std::min(first, second) - grow, high = std::max(first, second) + grow;
  // The point s along the side, t across it, is at height origin + s * slope + t * lean on the normal.
  const double height = dot(origin, normal), slope = dot(along, normal);
  const double sway = std::abs(dot(across, normal)) * reach;
  if (std::abs(slope) < tolerance::kParallelSine) {  // the slab runs along the side: all of it or none
    const bool meets = height + sway >= low && height - sway <= high;
    return meets ? std::pair<double, double>{-HUGE_VAL, HUGE_VAL} : std::pair<double, double>{1, 0};
  }
  const double s0 = (low - height - sway) / slope, s1 = (high - height + sway) / slope;
  return {std::min(s0, s1), std::max(s0, s1)};
}

}  // namespace

std::pair<double, double> clearStretchOfSide(const std::vector<Plate>& plates, const std::vector<int>& crossers,
                                             const Vec3& origin, const Vec3& along, const Vec3& across, double from,
                                             double to, double reach, double grow) {
  std::vector<std::pair<double, double>> taken;
  for (int crosser : crossers) {
    const std::pair<double, double> stretch =
        stretchTakenBy(plates[static_cast<size_t>(crosser)], origin, along, across, reach, grow);
    if (stretch.first <= stretch.second) taken.push_back(stretch);
  }
  std::sort(taken.begin(), taken.end());
  std::pair<double, double> best{from, from};
  double start = from;  // the free stretch so far begins here
  auto offer = [&](double end) {
    if (std::min(end, to) - start > best.second - best.first) best = {start, std::min(end, to)};
  };
  for (const auto& [takenFrom, takenTo] : taken) {
    if (takenFrom > start) offer(takenFrom);
    start = std::max(start, takenTo);
    if (start >= to) break;
  }
  if (start < to) offer(to);
  return best;
}

}  // namespace desia
