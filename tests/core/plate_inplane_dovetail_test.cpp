// SPDX-License-Identifier: GPL-3.0-or-later
// In-plane dovetails (issue 26): two plates lying in one plane edge to edge (IBOIS's VDA corner's
// hexagons) joined by a dovetail-shaped tab on one in a socket through the other, cut square
// through the sheet; either plate leaves only along the sheets' thickness axis, both ways. The
// fixtures: two 18 mm boards side by side in the plane z = 0..18, and the TABLE of
// examples/plate/make_examples.py with its left side panel cut in two halves meeting edge to edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/joints/inplane_dovetail.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kThickness = 18;  // mm, every board's

using testing::board;

double volumeOf(const Plate& plate) { return testing::plateVolume(plate); }

// Two boards 300 mm deep side by side, meeting at x = 200.
struct SideBySide {
  std::vector<Plate> plates;
  PlateContact contact;
  InplaneDovetailSite site;
};

SideBySide sideBySide() {
  SideBySide pair;
  pair.plates = {board(1, {0, 0, 0}, {200, 300, kThickness}), board(2, {200, 0, 0}, {400, 300, kThickness})};
  const std::vector<PlateContact> contacts = computePlateContacts(pair.plates, {});
  EXPECT_EQ(contacts.size(), 1u);
  pair.contact = contacts.at(0);
  const std::optional<InplaneDovetailSite> site = inplaneDovetailSiteOf(pair.plates, pair.contact);
  EXPECT_TRUE(site.has_value());
  if (site) pair.site = *site;
  return pair;
}

// The mover's points round the joint (a grid 0.7 mm apart over the tab and its socket; the
// independent point test of plate_test_support.h), stepped along d up to 30 mm: does one land
// inside the obstacle?
bool steppedCollision(const Plate& mover, const Plate& obstacle, const Vec3& d) {
  constexpr double kStep = 0.7, kReach = 30;
  const std::vector<Vec3> samples = testing::samplesInside(
      mover, {0, 0, 0}, {{{{1, 0, 0}, 140, 280, kStep}, {{0, 1, 0}, 80, 220, kStep}, {{0, 0, 1}, 0.49, kThickness, 4.25}}});
  return testing::steppedCollision(samples, obstacle, d, kStep, kReach);
}

TEST(PlateInplaneDovetails, TheSiteIsAThirdOfTheSideInItsMiddleHalfAsDeep) {
  const SideBySide pair = sideBySide();
  const InplaneDovetailSite& site = pair.site;
  EXPECT_EQ(site.tabPlate, 0);
  EXPECT_EQ(site.socketPlate, 1);
  EXPECT_NEAR(site.intoSocket[0], 1, 1e-12);
  EXPECT_NEAR(std::abs(site.axis[2]), 1, 1e-12);
  EXPECT_NEAR(site.root1 - site.root0, 100, 1e-9);
  EXPECT_NEAR(site.depth, 50, 1e-9);
  EXPECT_NEAR(site.flare, 50.0 / 6, 1e-9);
  // Its root in the side's middle: y 100..200.
  const Vec3 root0 = plus(site.origin, scaled(site.along, site.root0));
  const Vec3 root1 = plus(site.origin, scaled(site.along, site.root1));
  EXPECT_NEAR(std::min(root0[1], root1[1]), 100, 1e-9);
  EXPECT_NEAR(std::max(root0[1], root1[1]), 200, 1e-9);
}

TEST(PlateInplaneDovetails, OnlyPlatesInOneSheetEdgeToEdgeGetOne) {
  // The second board 5 mm higher: no longer one sheet.
  std::vector<Plate> stepped = {board(1, {0, 0, 0}, {200, 300, kThickness}),
                                board(2, {200, 0, 5}, {400, 300, kThickness + 5})};
  for (const PlateContact& contact : computePlateContacts(stepped, {}))
    EXPECT_FALSE(inplaneDovetailSiteOf(stepped, contact).has_value());
  // A board standing on the other's face (a T joint): a tenon's site, not this one's.
  std::vector<Plate> tee = {board(1, {0, 0, 0}, {200, 300, kThickness}),
                            board(2, {50, 0, kThickness}, {50 + kThickness, 300, 200})};
  for (const PlateContact& contact : computePlateContacts(tee, {}))
    EXPECT_FALSE(inplaneDovetailSiteOf(tee, contact).has_value());
  // The second plate too narrow for the socket and its margin (40 mm: the tab reaches 50): the
  // tab goes on it instead, its socket in the first.
  std::vector<Plate> narrow = {board(1, {0, 0, 0}, {200, 300, kThickness}), board(2, {200, 0, 0}, {240, 300, kThickness})};
  const std::vector<PlateContact> contacts = computePlateContacts(narrow, {});
  ASSERT_EQ(contacts.size(), 1u);
  const std::optional<InplaneDovetailSite> turned = inplaneDovetailSiteOf(narrow, contacts[0]);
  ASSERT_TRUE(turned.has_value());
  EXPECT_EQ(turned->tabPlate, contacts[0].b);
  EXPECT_EQ(turned->socketPlate, contacts[0].a);
  EXPECT_NEAR(dot(turned->intoSocket, contacts[0].normal), -1, 1e-12) << "into the first plate";
  const std::vector<Plate> cut = cutJoints(narrow, {jointCut(*turned)}, {});
  const int tab = turned->tabPlate, socket = turned->socketPlate;
  const double tabVolume = (100 + 50.0 / 6) * 50 * kThickness;
  EXPECT_NEAR(volumeOf(cut[tab]) - volumeOf(narrow[tab]), tabVolume, 1e-6 * tabVolume);
  EXPECT_NEAR(volumeOf(narrow[socket]) - volumeOf(cut[socket]), tabVolume, 1e-6 * tabVolume);
  // Both too narrow: no site either way.
  std::vector<Plate> bothNarrow = {board(1, {160, 0, 0}, {200, 300, kThickness}), narrow[1]};
  const std::vector<PlateContact> bothContacts = computePlateContacts(bothNarrow, {});
  ASSERT_EQ(bothContacts.size(), 1u);
  EXPECT_FALSE(inplaneDovetailSiteOf(bothNarrow, bothContacts[0]).has_value());
  JointCutOptions shallow;
  shallow.inplaneDovetail.depth = LengthShare{1, 4};  // 25 mm deep: fits with the margin
  const std::optional<InplaneDovetailSite> shallowSite = inplaneDovetailSiteOf(bothNarrow, bothContacts[0], shallow);
  ASSERT_TRUE(shallowSite.has_value());
  EXPECT_EQ(shallowSite->tabPlate, bothContacts[0].a);
}

// Straight flanks (slope 0) would let the tab plate out backwards, which the family's ways out
// (the sheets' axis only) do not say: the family refuses them, naming the setting.
TEST(PlateInplaneDovetails, TheFamilyRefusesStraightFlanks) {
  const SideBySide pair = sideBySide();
  const PlateGraph graph = buildPlateGraph(pair.plates, {pair.contact}, JointRealization::Cut);
  JointCutOptions straight;
  straight.inplaneDovetail.slope = 0;
  try {
    makeInplaneDovetailFamily(JointSetting{graph, straight, JointRealization::Cut});
    ADD_FAILURE() << "slope 0 accepted";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::BadInput);
    EXPECT_NE(std::string(error.what()).find("inplaneDovetail.slope"), std::string::npos) << error.what();
  }
  // What it would have let: the straight tab slides out of its socket backwards.
  const std::optional<InplaneDovetailSite> site = inplaneDovetailSiteOf(pair.plates, pair.contact, straight);
  ASSERT_TRUE(site.has_value());
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(*site)}, straight);
  EXPECT_FALSE(plateCollidesAlong(cut[0], cut[1], negated(site->intoSocket), tolerance::kContactMm));
  const std::vector<Plate> dovetailed = cutJoints(pair.plates, {jointCut(pair.site)}, {});
  EXPECT_TRUE(plateCollidesAlong(dovetailed[0], dovetailed[1], negated(pair.site.intoSocket), tolerance::kContactMm));
}

TEST(PlateInplaneDovetails, TheTabPlateGainsTheTabAndTheSocketPlateLosesItPlusTheClearance) {
  const SideBySide pair = sideBySide();
  const InplaneDovetailSite& site = pair.site;
  for (const double clearance : {0.0, 0.4}) {
    JointCutOptions options;
    options.clearance = clearance;
    const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(site)}, options);
    ASSERT_EQ(cut.size(), 2u);
    // The tab: a trapezoid 100 mm at the root, 100 + 2 * 50/6 at the tip, 50 deep; the socket:
    // its flanks moved out by half the clearance square to themselves (sideways by g L / D,
    // L the flank's length), its tip by as much (computed here).
    const double w = 100, depth = 50, flare = depth / 6, g = clearance / 2;
    const double tab = (w + flare) * depth * kThickness;
    const double sideways = g * std::sqrt(depth * depth + flare * flare) / depth;
    const double socket = ((w + 2 * sideways) * (depth + g) + flare * (depth + g) * (depth + g) / depth) * kThickness;
    EXPECT_NEAR(volumeOf(cut[0]) - volumeOf(pair.plates[0]), tab, 1e-6 * tab);
    EXPECT_NEAR(volumeOf(pair.plates[1]) - volumeOf(cut[1]), socket, 1e-6 * socket);
    EXPECT_EQ(testing::manifoldProblem(plateMesh(cut[0])), "");
    EXPECT_EQ(testing::manifoldProblem(plateMesh(cut[1])), "");
    // Still prisms: a laser cuts them.
    EXPECT_EQ(cut[0].bottom[0].size(), 8u);
    EXPECT_EQ(cut[1].bottom[0].size(), 8u);
  }
}

TEST(PlateInplaneDovetails, TheSweepAgreesWithSteppingAndOnlyTheSheetsAxisIsFree) {
  const SideBySide pair = sideBySide();
  const InplaneDovetailSite& s = pair.site;
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(s)}, {});
  const std::vector<Vec3> ways{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                               normalized(Vec3{-1, 1, 0}), normalized(Vec3{-1, 0, 1})};
  for (const int mover : {0, 1}) {
    int free = 0;
    for (const Vec3& d : ways) {
      const bool swept = plateCollidesAlong(cut[mover], cut[1 - mover], d, tolerance::kContactMm);
      EXPECT_EQ(swept, steppedCollision(cut[mover], cut[1 - mover], d)) << mover << ": " << d[0] << "," << d[1] << "," << d[2];
      free += swept ? 0 : 1;
    }
    EXPECT_EQ(free, 2) << "plate " << mover << ": out of the sheet, up or down, only";
  }
  // Without the joint the boards part sideways too.
  EXPECT_FALSE(plateCollidesAlong(pair.plates[0], pair.plates[1], {-1, 0, 0}, tolerance::kContactMm));
  EXPECT_FALSE(plateCollidesAlong(pair.plates[0], pair.plates[1], {0, 1, 0}, tolerance::kContactMm));
  // The joint model says the same: no face stops the axis; some face stops every way in the plane.
  const std::vector<Vec3> normals = inplaneDovetailFaceNormals(s);
  for (const Vec3& n : normals) EXPECT_LE(std::abs(dot(n, s.axis)), tolerance::kDirection);
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * M_PI * k / 16;
    const Vec3 d = plus(scaled(s.intoSocket, std::cos(a)), scaled(s.along, std::sin(a)));
    const bool stopped = std::any_of(normals.begin(), normals.end(), [&](const Vec3& n) { return dot(n, d) > 1e-3; });
    EXPECT_TRUE(stopped) << a;
  }
}

TEST(PlateInplaneDovetails, TheFamilyLetsEitherPlateOutOfTheSheetBothWaysOnly) {
  const SideBySide pair = sideBySide();
  const PlateGraph graph = buildPlateGraph(pair.plates, {pair.contact}, JointRealization::Cut);
  const JointCutOptions options;
  const std::unique_ptr<JointFamily> family =
      makeInplaneDovetailFamily(JointSetting{graph, options, JointRealization::Cut});
  const Vec3 up{0, 0, 1}, down{0, 0, -1};
  for (const int mover : {0, 1}) {
    EXPECT_TRUE(family->lets(0, mover, up));
    EXPECT_TRUE(family->lets(0, mover, down));
    EXPECT_FALSE(family->lets(0, mover, {1, 0, 0}));
    EXPECT_FALSE(family->lets(0, mover, {-1, 0, 0}));
    EXPECT_FALSE(family->lets(0, mover, {0, 1, 0}));
    EXPECT_FALSE(family->lets(0, mover, normalized(Vec3{0, std::sin(0.01), std::cos(0.01)})));
  }
  std::vector<Vec3> ways;
  family->addWaysOut(0, 0, ways);
  EXPECT_EQ(ways.size(), 2u);
  // A cut joint (a laser makes it): the registry offers it for Cut, by its name.
  const JointFamilies families(graph, options, JointRealization::Cut);
  const std::optional<PlateJoint> joint = families.jointFor(1, 0, down);
  ASSERT_TRUE(joint.has_value());
  EXPECT_EQ(joint->type, JointType::InplaneDovetail);
  EXPECT_STREQ(jointTypeName(joint->type), "inplane-dovetail");
  const std::optional<PlateJoint> across = families.jointFor(1, 0, {1, 0, 0});
  ASSERT_TRUE(across.has_value());
  EXPECT_EQ(across->type, JointType::Empty);
  // The wood under the tab's root (a halved slot running out through that side there would
  // leave the tab bridging it): a 1 mm strip inside the tab plate's side, as long as the root.
  int strips = 0;
  for (const CutFootprint& strip : families.footprints({*joint})) {
    if (strip.kind != FootprintKind::UnderAddedPiece) continue;
    ++strips;
    const InplaneDovetailSite& site = pair.site;
    EXPECT_EQ(strip.plate, site.tabPlate);
    ASSERT_EQ(strip.region.size(), 4u);
    const Vec3 outer = scaled(plus(strip.region[0], strip.region[1]), 0.5);
    const Vec3 inner = scaled(plus(strip.region[2], strip.region[3]), 0.5);
    EXPECT_NEAR(dot(minus(outer, inner), site.intoSocket), 1, 1e-9) << "1 mm in from the side";
    EXPECT_NEAR(norm(minus(strip.region[1], strip.region[0])), site.root1 - site.root0, 1e-9);
    const Vec3 lift{0, 0, kThickness / 2};
    EXPECT_TRUE(testing::PlateInside(pair.plates[site.tabPlate]).contains(plus(scaled(plus(outer, inner), 0.5), lift)));
    EXPECT_FALSE(testing::PlateInside(pair.plates[site.tabPlate]).contains(plus(plus(outer, scaled(site.intoSocket, 0.5)), lift)));
  }
  EXPECT_EQ(strips, 1);
}

// The TABLE (examples/plate/make_examples.py) with its left side panel in two halves, front and
// back, meeting edge to edge at z = 300 in the plane x = 0..18.
std::vector<Plate> tableWithSplitSide() {
  const double t = kThickness;
  return {board(1, {-25, 700, -25}, {1025, 700 + t, 625}),  board(2, {0, 0, 0}, {t, 700, 300}),
          board(3, {1000 - t, 0, 0}, {1000, 700, 600}),     board(4, {t, 550, 20}, {1000 - t, 700, 20 + t}),
          board(5, {t, 550, 580 - t}, {1000 - t, 700, 580}), board(6, {t, 150, 40}, {1000 - t, 150 + t, 560}),
          board(7, {0, 0, 300}, {t, 700, 600})};
}


TEST(PlateInplaneDovetails, TheTableWithASplitSideDesignsWithAnInplaneDovetailAndATamperedPlanFails) {
  const std::vector<Plate> plates = tableWithSplitSide();
  PlateDesignOptions options;
  options.realization = JointRealization::Cut;
  options.limits.timeLimitSeconds = 0;
  options.limits.nodeLimit = 3000;
  const PlateDesignResult result = designPlateJoints(plates, computePlateContacts(plates, {}), options);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  int keys = 0;
  for (const PlateJoint& joint : result.joints) keys += joint.type == JointType::InplaneDovetail ? 1 : 0;
  EXPECT_EQ(keys, 1) << result.message;
  const std::vector<Plate> inOrder = testing::jointedInRemovalOrder(result);
  EXPECT_EQ(verifyJointedPlates(inOrder, result.directions).failure, "");
  const AssemblyDocument written = testing::writtenPlateResult(plates, result, "table with a split side");
  for (const CheckReport& report : testing::checkedByBothMethods(written))
    EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
  // The halves' joint: one leaves the other out of the sheet (along x, the side's axis), the way
  // the plan uses (the tab lets both).
  int halfMoving = -1;
  for (const PlateJoint& joint : result.joints) {
    if (joint.type != JointType::InplaneDovetail) continue;
    EXPECT_NEAR(std::abs(joint.direction[0]), 1, 1e-9);
    halfMoving = joint.mover;
  }
  ASSERT_GE(halfMoving, 0);
  // Tampered: the key's way reversed, or the half that leaves sent along the sheet, away from
  // the other half (into the tab's flanks, and the tenons standing in it): no longer verified.
  std::vector<Vec3> reversed = result.directions;
  reversed[0] = negated(reversed[0]);
  EXPECT_NE(verifyJointedPlates(inOrder, reversed).failure, "");
  const size_t step = static_cast<size_t>(
      std::find(result.order.begin(), result.order.end(), halfMoving) - result.order.begin());
  ASSERT_LT(step, result.directions.size());
  std::vector<Vec3> alongTheSheet = result.directions;
  const double away = plates[static_cast<size_t>(halfMoving)].bottom[0][0][2] < 300 - 1e-9 ? -1 : 1;
  alongTheSheet[step] = {0, 0, away};
  EXPECT_NE(verifyJointedPlates(inOrder, alongTheSheet).failure, "");
}

}  // namespace
}  // namespace desia
