// SPDX-License-Identifier: GPL-3.0-or-later
// Plates crossing a shared side (issue 26): in IBOIS's VDA corner an upright bar straddles the
// side two hexagons of a layer share, through both, and its slots are cut there; the in-plane
// dovetail on that side must sit beside it, or its socket runs into the slots and no cut plan
// exists (the VDA corner's search: 1,813 nodes, 7 of 9 plates taken). The fixtures: two 18 mm
// boards side by side with a bar through their shared side, and a hexagon corner of our own making
// with the VDA corner's shape: two layers (40 mm apart) of three regular hexagons (150 mm sides)
// meeting at a point, and three upright bars through both layers, each straddling one shared side.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/plate.h"
#include "plate/joints/inplane_dovetail.h"
#include "plate/joints/side_crossings.h"
#include "plate/plate_graph.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kThickness = 18;  // mm, every plate's

using testing::board;

// A prism: `first` and the same loop moved by `offset` (first's normal points along it).
Plate prism(int id, const Loop& first, const Vec3& offset) {
  Plate plate;
  plate.id = id;
  plate.bottom = {first};
  Loop second;
  for (const Vec3& p : first) second.push_back(plus(p, offset));
  plate.top = {second};
  return plate;
}

// Boards A (x 0..200) and B (x 200..400) in the sheet z = 0..18 and a bar 18 mm thick (y 141..159)
// from x = 150 to 250 and z = -100 to 100, through their shared side (x = 200, y 0..300).
std::vector<Plate> layerAndBar() {
  return {board(1, {0, 0, 0}, {200, 300, kThickness}), board(2, {200, 0, 0}, {400, 300, kThickness}),
          board(3, {150, 141, -100}, {250, 141 + kThickness, 100})};
}

// The y range of the tab's outline.
std::pair<double, double> tabAcrossY(const InplaneDovetailSite& site) {
  std::pair<double, double> range{HUGE_VAL, -HUGE_VAL};
  for (const Vec3& p : site.tab(0, 0)) range = {std::min(range.first, p[1]), std::max(range.second, p[1])};
  return range;
}

TEST(PlateSideCrossings, TheDovetailSitsBesideTheBarThroughTheSide) {
  const std::vector<Plate> plates = layerAndBar();
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  const PlateGraph graph = buildPlateGraph(plates, contacts, JointRealization::Cut);
  int side = -1;
  for (size_t c = 0; c < graph.computedContacts.size(); ++c) {
    if (!graph.computedContacts[c].crossing) side = static_cast<int>(c);
  }
  ASSERT_GE(side, 0);
  const PlateContact& contact = graph.computedContacts[static_cast<size_t>(side)];
  EXPECT_EQ(platesCrossingBoth(graph, contact), std::vector<int>{2});
  // Without the bar: a third of the side in its middle (y 100..200), right where the bar passes.
  const std::optional<InplaneDovetailSite> middle = inplaneDovetailSiteOf(plates, contact);
  ASSERT_TRUE(middle.has_value());
  EXPECT_NEAR(std::abs(middle->root1 - middle->root0), 100, 1e-9);
  // With it: the side less the bar's slab grown by the wood margin (1 mm) leaves y 0..140 and
  // 160..300; the tab takes a third of one (140 / 3 mm) in its middle, clear of the bar's slots.
  const JointCutOptions options;
  const std::optional<InplaneDovetailSite> beside =
      inplaneDovetailSiteOf(plates, contact, options, platesCrossingBoth(graph, contact));
  ASSERT_TRUE(beside.has_value());
  EXPECT_NEAR(beside->root1 - beside->root0, 140.0 / 3, 1e-9);
  const auto [low, high] = tabAcrossY(*beside);
  EXPECT_TRUE(high <= 141 - options.woodMargin || low >= 159 + options.woodMargin) << low << ".." << high;
  EXPECT_TRUE(std::abs((low + high) / 2 - 70) < 1e-6 || std::abs((low + high) / 2 - 230) < 1e-6) << low << ".." << high;
}

TEST(PlateSideCrossings, AStretchIsTakenAsFarAsTheSlabReachesAcrossTheSideAtAnAngle) {
  // A bar at 60 degrees to the side (the side: y = 0..300 at x = 0, `across` +x): within 30 mm
  // of the side either way its 18 mm slab sweeps 18 / sin 60 along it plus 2 x 30 / tan 60.
  const Vec3 w{std::sin(M_PI / 3), std::cos(M_PI / 3), 0}, n{-w[1], w[0], 0};
  const Vec3 start = plus(Vec3{0, 150, -50}, scaled(w, -60));
  const Plate bar = prism(
      1, {start, plus(start, {0, 0, 100}), plus(start, plus(scaled(w, 120), {0, 0, 100})), plus(start, scaled(w, 120))},
      scaled(n, kThickness));
  const std::vector<Plate> plates = {bar};
  const auto [from, to] = clearStretchOfSide(plates, {0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0, 300, 30, 0);
  const double taken = kThickness / std::sin(M_PI / 3) + 2 * 30 / std::tan(M_PI / 3);
  // The slab's first face passes y = 150 at x = 0 and its second lies above it (n has +y): it
  // takes y from 150 - 30 / tan 60 on, leaving 132.7 mm below it and 111.9 above.
  const double takenFrom = 150 - 30 / std::tan(M_PI / 3);
  EXPECT_NEAR(from, 0, 1e-9);
  EXPECT_NEAR(to, takenFrom, 1e-9);
  const auto above = clearStretchOfSide(plates, {0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 100, 300, 30, 0);
  EXPECT_NEAR(above.first, takenFrom + taken, 1e-9);
  EXPECT_NEAR(above.second, 300, 1e-9);
  // No crossers: the whole side.
  const auto whole = clearStretchOfSide(plates, {}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0, 300, 30, 0);
  EXPECT_EQ(whole, (std::pair<double, double>{0, 300}));
}

// Three regular hexagons with sides of `edge` around the origin (pointy-topped, as the VDA
// corner's), in the sheets z = 40..58 and z = -60..-42; bars 18 mm thick from z = -85 to 85, each
// through one shared side: crossing it `along` of the way out from the origin, running `before`
// back and `after` on along its way w.
std::vector<Plate> hexagonCorner() {
  constexpr double edge = 150;
  const double c = std::cos(M_PI / 6);
  const std::vector<Vec3> centres = {{c * edge, edge / 2, 0}, {-c * edge, edge / 2, 0}, {0, -edge, 0}};
  std::vector<Plate> plates;
  for (const double z : {40.0, -60.0}) {
    for (const Vec3& centre : centres) {
      Loop outline;
      for (int k = 0; k < 6; ++k) {
        const double angle = M_PI / 2 + k * M_PI / 3;  // counter-clockwise about +z
        outline.push_back({centre[0] + edge * std::cos(angle), centre[1] + edge * std::sin(angle), z});
      }
      plates.push_back(prism(static_cast<int>(plates.size()) + 1, outline, {0, 0, kThickness}));
    }
  }
  struct Bar {
    Vec3 side, w;
    double before, after;
  };
  constexpr double along = 0.63;
  for (const Bar& bar : {Bar{{0, 1, 0}, {c, 0.5, 0}, 75, 57}, Bar{{c, -0.5, 0}, {c, 0.5, 0}, 75, 57},
                         Bar{{-c, -0.5, 0}, {-0.5, c, 0}, 66, 66}}) {
    const Vec3 n{-bar.w[1], bar.w[0], 0};
    const Vec3 middle = scaled(bar.side, along * edge);
    const Vec3 p0 = plus(plus(middle, scaled(bar.w, -bar.before)), plus(scaled(n, -kThickness / 2), {0, 0, -85}));
    const Vec3 p1 = plus(p0, scaled(bar.w, bar.before + bar.after));
    // Counter-clockwise about n: p0, up, p1 up, p1.
    plates.push_back(prism(static_cast<int>(plates.size()) + 1, {p0, plus(p0, {0, 0, 170}), plus(p1, {0, 0, 170}), p1},
                           scaled(n, kThickness)));
  }
  return plates;
}

// The hexagon corner designed with `realization`, verified, checked as written on both tests, and
// failing with its key reversed; the joints' types counted.
std::map<JointType, int> designedHexagonCorner(JointRealization realization) {
  const std::vector<Plate> plates = hexagonCorner();
  PlateDesignOptions options;
  options.realization = realization;
  options.limits.timeLimitSeconds = 0;
  options.limits.nodeLimit = 3000;
  const PlateDesignResult result = designPlateJoints(plates, computePlateContacts(plates, {}), options);
  std::map<JointType, int> types;
  EXPECT_EQ(result.status, DesignStatus::Success) << result.message;
  if (result.status != DesignStatus::Success) return types;
  for (const PlateJoint& joint : result.joints) {
    ++types[joint.type];
    EXPECT_FALSE(joint.contact < 0 && joint.type != JointType::Empty) << "a planned joint";
  }
  const std::vector<Plate> inOrder = testing::jointedInRemovalOrder(result);
  EXPECT_EQ(verifyJointedPlates(inOrder, result.directions).failure, "");
  const AssemblyDocument written = testing::writtenPlateResult(plates, result, "hexagon corner");
  for (const CheckReport& report : testing::checkedByBothMethods(written))
    EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
  std::vector<Vec3> reversed = result.directions;
  reversed[0] = negated(reversed[0]);
  EXPECT_NE(verifyJointedPlates(inOrder, reversed).failure, "");
  return types;
}

// Before the joints on the hexagons' sides sat beside the bars, the cut search ended after 1,813
// nodes with 7 of 9 plates taken, the milled one after 5 nodes with 1 taken (its first hexagon's
// mitre tenons ran into every bar's slots).
TEST(PlateSideCrossings, TheHexagonCornerGetsACutPlanThatVerifies) {
  const std::map<JointType, int> types = designedHexagonCorner(JointRealization::Cut);
  const auto count = [&](JointType type) { return types.count(type) ? types.at(type) : 0; };
  // Every bar crosses four hexagons: 12 crossings, each a halved joint or a through slot (the
  // bars lifted out of their layers sit in through slots).
  EXPECT_EQ(count(JointType::Halved) + count(JointType::ThroughSlot), 12);
  EXPECT_GE(count(JointType::ThroughSlot), 1);
  EXPECT_GE(count(JointType::InplaneDovetail), 1);
}

TEST(PlateSideCrossings, TheHexagonCornerGetsAMilledPlanWithMitreTenonsBesideTheBars) {
  const std::map<JointType, int> types = designedHexagonCorner(JointRealization::Milled);
  const auto count = [&](JointType type) { return types.count(type) ? types.at(type) : 0; };
  EXPECT_EQ(count(JointType::Halved) + count(JointType::ThroughSlot), 12);
  EXPECT_GE(count(JointType::MitreTenon), 1);
}

}  // namespace
}  // namespace desia
