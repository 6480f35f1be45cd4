// SPDX-License-Identifier: GPL-3.0-or-later
// Through slots (issue 26): an upright bar through a layer of two plates meeting edge to edge,
// straddling their shared edge (IBOIS's VDA corner), sits whole in notches cut through both and
// leaves along the layer's axis; halved joints cannot let it out, as each plate's slot opens
// towards the other. The fixture: boards A (x 0..200) and B (x 200..400) in the sheet z = 0..18,
// and a bar 18 mm thick (y 141..159) from x = 150 to 250 and z = -100 to 100.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <utility>

#include "analysis/vec3.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/through_slot.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kThickness = 18;

using testing::board;

std::vector<Plate> layerAndBar() {
  return {board(1, {0, 0, 0}, {200, 300, kThickness}), board(2, {200, 0, 0}, {400, 300, kThickness}),
          board(3, {150, 141, -100}, {250, 141 + kThickness, 100})};
}

using testing::meshVolume;

int crossingOf(const std::vector<PlateContact>& contacts, int p, int q) {
  for (size_t c = 0; c < contacts.size(); ++c) {
    const PlateContact& contact = contacts[c];
    if (contact.crossing && ((contact.a == p && contact.b == q) || (contact.a == q && contact.b == p)))
      return static_cast<int>(c);
  }
  return -1;
}

// The bar's points where it passes the layer (0.7 mm apart; the independent point test of
// plate_test_support.h), stepped along d up to 30 mm.
bool steppedCollision(const Plate& bar, const Plate& obstacle, const Vec3& d) {
  const std::vector<Vec3> samples = testing::samplesInside(
      bar, {0, 0, 0}, {{{{1, 0, 0}, 150, 250, 0.7}, {{0, 1, 0}, 141, 159, 0.7}, {{0, 0, 1}, -20.511, 40, 2.5}}});
  return testing::steppedCollision(samples, obstacle, d, 0.7, 30);
}

TEST(PlateThroughSlots, TheBarIsSeatedInBothBoardsAndNotTheOtherWayRound) {
  const std::vector<Plate> plates = layerAndBar();
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  for (int board : {0, 1}) {
    const int c = crossingOf(contacts, board, 2);
    ASSERT_GE(c, 0);
    const std::optional<ThroughSlotSite> barSeated = throughSlotSiteOf(plates, contacts, c, 2);
    ASSERT_TRUE(barSeated.has_value());
    EXPECT_EQ(barSeated->slotted, board);
    EXPECT_NEAR(std::abs(barSeated->out[2]), 1, 1e-12);
    // The board seated in the bar: a halved joint lets it slide off the bar, away from the edge.
    EXPECT_FALSE(throughSlotSiteOf(plates, contacts, c, board).has_value());
  }
  // A bar inside one board alone: no halved slot opens anywhere, a closed slot seats it.
  const std::vector<Plate> inA = {plates[0], plates[1], board(3, {100, 141, -100}, {180, 141 + kThickness, 100})};
  const std::vector<PlateContact> inAContacts = computePlateContacts(inA, {});
  const int c = crossingOf(inAContacts, 0, 2);
  ASSERT_GE(c, 0);
  const std::optional<ThroughSlotSite> closed = throughSlotSiteOf(inA, inAContacts, c, 2);
  ASSERT_TRUE(closed.has_value());
  EXPECT_FALSE(closed->opens[0] || closed->opens[1]);
  // A bar running out past the board's far side (x = 0) slides off it on a halved joint: no site.
  const std::vector<Plate> outOfA = {plates[0], plates[1], board(3, {-50, 141, -100}, {100, 141 + kThickness, 100})};
  const std::vector<PlateContact> outContacts = computePlateContacts(outOfA, {});
  const int d = crossingOf(outContacts, 0, 2);
  ASSERT_GE(d, 0);
  EXPECT_FALSE(throughSlotSiteOf(outOfA, outContacts, d, 2).has_value());
}

// The boards keep options.woodMargin (1 mm) of wood beside the slot at the clearance: a bar 1.1 mm
// from their side (y = 0) gets a slot at clearance 0, none at 0.4 (0.9 mm of wood) nor 0.3 mm
// from it (a 0.1 mm wall at 0.4, which would break off).
TEST(PlateThroughSlots, TheSlottedPlatesKeepTheWoodMarginBesideTheSlot) {
  for (const double from : {1.1, 0.3}) {
    const std::vector<Plate> plates = {board(1, {0, 0, 0}, {200, 300, kThickness}),
                                       board(2, {200, 0, 0}, {400, 300, kThickness}),
                                       board(3, {150, from, -100}, {250, from + kThickness, 100})};
    const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
    for (int board : {0, 1}) {
      const int c = crossingOf(contacts, board, 2);
      ASSERT_GE(c, 0);
      for (const double clearance : {0.0, 0.4}) {
        JointCutOptions options;
        options.clearance = clearance;
        const double wall = from - clearance / 2;
        EXPECT_EQ(throughSlotSiteOf(plates, contacts, c, 2, options).has_value(), wall >= options.woodMargin)
            << from << " mm from the side, clearance " << clearance << ", board " << board;
      }
    }
  }
  // The closed end too: a bar ending 0.8 mm inside board A's far side (x = 0) at clearance 0.
  const std::vector<Plate> plates = {board(1, {0, 0, 0}, {200, 300, kThickness}),
                                     board(2, {200, 0, 0}, {400, 300, kThickness}),
                                     board(3, {0.8, 141, -100}, {250, 141 + kThickness, 100})};
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  const int c = crossingOf(contacts, 0, 2);
  ASSERT_GE(c, 0);
  EXPECT_FALSE(throughSlotSiteOf(plates, contacts, c, 2).has_value());
}

// Each board holds the bar along y (the slot's walls) and on the slot's closed end: the bar leaves
// each along z, either way, or out of the slot's open end (towards the other board), and the
// joint model's faces (the family's face normals) say the same as the sweep.
TEST(PlateThroughSlots, TheBoardsLoseTheBarsSectionPlusTheClearanceAndTheBarLeavesAlongZOrOutOfTheOpenEnd) {
  const std::vector<Plate> plates = layerAndBar();
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  for (const double clearance : {0.0, 0.4}) {
    JointCutOptions options;
    options.clearance = clearance;
    JointCutList cuts;
    const PlateGraph graph = buildPlateGraph(plates, contacts, JointRealization::Cut);
    const JointFamilies families(graph, options, JointRealization::Cut);
    std::vector<PlateJoint> joints;
    for (int board : {0, 1}) {
      const std::optional<PlateJoint> joint = families.jointFor(2, board, {0, 0, 1});
      ASSERT_TRUE(joint.has_value());
      EXPECT_EQ(joint->type, JointType::ThroughSlot);
      EXPECT_STREQ(jointTypeName(joint->type), "through-slot");
      joints.push_back(*joint);
    }
    const std::vector<Plate> cut = cutJoints(plates, families.cuts(joints, clearance), options);
    // Each board loses the bar's 50 mm of section in it (plus half the clearance at the closed
    // end) by 18 + the clearance, through its 18 mm; the bar keeps its volume.
    const double slot = (50 + clearance / 2) * (kThickness + clearance) * kThickness;
    for (int board : {0, 1})
      EXPECT_NEAR(meshVolume(plateMesh(plates[board])) - meshVolume(plateMesh(cut[board])), slot, 1e-6 * slot);
    EXPECT_NEAR(meshVolume(plateMesh(cut[2])), meshVolume(plateMesh(plates[2])), 1e-6);
    if (clearance > 0) continue;
    for (int board : {0, 1}) {
      const std::vector<Vec3> normals = families.faceNormals(joints[static_cast<size_t>(board)]);
      int free = 0;
      for (const Vec3& d : std::vector<Vec3>{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}}) {
        const bool swept = plateCollidesAlong(cut[2], cut[board], d, tolerance::kContactMm);
        EXPECT_EQ(swept, steppedCollision(cut[2], cut[board], d)) << board << ": " << d[0] << "," << d[1] << "," << d[2];
        // The joint's faces, from the bar (the mover) into the board: one facing d stops it.
        const bool faced = std::any_of(normals.begin(), normals.end(), [&](const Vec3& n) { return dot(n, d) > 1e-9; });
        EXPECT_EQ(faced, swept) << "faces, board " << board << ": " << d[0] << "," << d[1] << "," << d[2];
        free += swept ? 0 : 1;
      }
      // Out of board A's slot +x (into B) is free of A, and -x of B: the two together hold it.
      EXPECT_EQ(free, 3) << board;
      EXPECT_TRUE(plateCollidesAlong(cut[2], cut[board], board == 0 ? Vec3{-1, 0, 0} : Vec3{1, 0, 0},
                                     tolerance::kContactMm));
    }
    // Without the slots the bar cannot leave at all (it crosses the boards).
    EXPECT_TRUE(plateCollidesAlong(plates[2], plates[0], {0, 0, 1}, tolerance::kContactMm));
  }
}

TEST(PlateThroughSlots, OnlyMadeJointsOfferIt) {
  const std::vector<Plate> plates = layerAndBar();
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  const JointCutOptions options;
  const PlateGraph planned = buildPlateGraph(plates, contacts, JointRealization::Planned);
  const JointFamilies plannedFamilies(planned, options, JointRealization::Planned);
  EXPECT_FALSE(plannedFamilies.jointFor(2, 0, {0, 0, 1}).has_value());
  const PlateGraph graph = buildPlateGraph(plates, contacts, JointRealization::Cut);
  const JointFamilies families(graph, options, JointRealization::Cut);
  EXPECT_FALSE(families.jointFor(2, 0, {0, 1, 0}).has_value());
  // The halved joint still comes first where it opens: the board slides off the bar along -x.
  const std::optional<PlateJoint> halved = families.jointFor(0, 2, {-1, 0, 0});
  ASSERT_TRUE(halved.has_value());
  EXPECT_EQ(halved->type, JointType::Halved);
}

}  // namespace
}  // namespace desia
