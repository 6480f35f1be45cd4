// SPDX-License-Identifier: GPL-3.0-or-later
// Slanted sliding dovetails (issue 26): a plate's side bevelled to lie on another's face, their
// planes 60..<90 degrees apart (IBOIS's hexboxes: 80..88), a dovetail tongue on the side through
// a slot in the face plate whose walls lean with the side's slant, open at one end and stopped at
// the other; the side plate leaves only along the shared edge, out through the open end. The
// design: examples/plate/leaning_box.json (make_leaning_box.py), its long sides leaning out 15
// degrees on the base, whose ends they run out at.
#include <gtest/gtest.h>

#include <algorithm>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/missing_joints.h"
#include "plate/joints/slanted_dovetail.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kLeanDegrees = 15;  // the box's sides from upright: planes 75 degrees apart
constexpr double kThickness = 18;    // every board's, mm
constexpr double kLength = 400;      // the sides' and the base's, mm

AssemblyDocument leaningBox() { return testing::loadPlateExample("leaning_box.json"); }

double volumeOf(const Plate& plate) { return testing::plateVolume(plate); }

// The base and the front side (plates[0], plates[1]) and the site of the slanted dovetail on
// their contact.
struct BaseAndSide {
  std::vector<Plate> plates;
  PlateContact contact;
  SlantedDovetailSite site;
};

BaseAndSide baseAndSide(const std::vector<Plate>& box) {
  BaseAndSide pair;
  for (const Plate& plate : box) {
    if (plate.id == 1 || plate.id == 2) pair.plates.push_back(plate);
  }
  const std::vector<PlateContact> contacts = computePlateContacts(pair.plates, {});
  EXPECT_EQ(contacts.size(), 1u);
  pair.contact = contacts.at(0);
  const std::optional<SlantedDovetailSite> site = slantedDovetailSiteOf(pair.plates, pair.contact);
  EXPECT_TRUE(site.has_value());
  if (site) pair.site = *site;
  return pair;
}

BaseAndSide baseAndSide() { return baseAndSide(leaningBox().plates); }

// The slot opening at the side's end (+along): the side leaves along it.
SlantedDovetailCut openAtTheEnd(const SlantedDovetailSite& site) { return {site, 1}; }

TEST(PlateSlantedDovetails, TheSideStandsOnTheBaseAt75DegreesWithATongueLeaningWithIt) {
  const BaseAndSide pair = baseAndSide();
  const SlantedDovetailSite& site = pair.site;
  EXPECT_EQ(pair.plates[static_cast<size_t>(site.side.tenonPlate)].id, 2);
  EXPECT_EQ(pair.plates[static_cast<size_t>(site.side.mortisePlate)].id, 1);
  // The side runs the base's whole length: its slot may open at either end, stopped a base's
  // thickness (18 mm, more than dovetail.stop's 10) before the other.
  EXPECT_NEAR(site.side.to - site.side.from, kLength, 1e-6);
  EXPECT_TRUE(site.opens[0]);
  EXPECT_TRUE(site.opens[1]);
  EXPECT_NEAR(site.stop, kThickness, 1e-9);
  // The side on the base is its thickness over the sine of 75 degrees wide; its mid-plane runs
  // tan 15 degrees across per mm down; the neck two thirds of its thickness, the walls flaring
  // 1 in 6 each through the base.
  const double angle = (90 - kLeanDegrees) * M_PI / 180;
  EXPECT_NEAR(site.sideWidth, kThickness / std::sin(angle), 1e-6);
  EXPECT_NEAR(std::abs(site.lean), std::tan(kLeanDegrees * M_PI / 180), 1e-9);
  EXPECT_NEAR(site.depth, kThickness, 1e-9);
  EXPECT_NEAR(site.walls[0][1] - site.walls[0][0], 12, 1e-6);  // the side 18 mm to 6 decimals
  EXPECT_NEAR(site.walls[1][1] - site.walls[1][0], 12 + 2 * 3, 1e-6);
  EXPECT_NEAR((site.walls[1][0] + site.walls[1][1]) / 2 - (site.walls[0][0] + site.walls[0][1]) / 2,
              site.lean * kThickness, 1e-9);
  // Both walls lean back towards the side: the tongue is wider at the base's far face.
  for (const Vec3& n : slantedDovetailFaceNormals(openAtTheEnd(site))) EXPECT_LE(dot(n, site.side.along), 1e-12);
  // Tilted further than the least angle (slantedDovetail.leastDegrees), or too thin a neck, no site.
  JointCutOptions steep;
  steep.slantedDovetail.leastDegrees = 80;
  EXPECT_FALSE(slantedDovetailSiteOf(pair.plates, pair.contact, steep).has_value());
  JointCutOptions thin;
  thin.dovetail.narrowestNeck = 12.5;
  EXPECT_FALSE(slantedDovetailSiteOf(pair.plates, pair.contact, thin).has_value());
  // No room for the stop: none.
  JointCutOptions longStop;
  longStop.dovetail.stop = kLength;
  EXPECT_FALSE(slantedDovetailSiteOf(pair.plates, pair.contact, longStop).has_value());
}

TEST(PlateSlantedDovetails, TheSideGainsItsTongueAndTheBaseLosesItsSlotPlusTheClearance) {
  const BaseAndSide pair = baseAndSide();
  const SlantedDovetailSite& site = pair.site;
  for (const int openEnd : {0, 1}) {
    for (const double clearance : {0.0, 0.4}) {
      JointCutOptions options;
      options.clearance = clearance;
      const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(SlantedDovetailCut{site, openEnd})}, options);
      ASSERT_EQ(cut.size(), 2u);
      // The tongue: a trapezoid 12 mm wide at the base's face, 18 at its far face, 18 deep,
      // along the side from the stop to the open end; the slot: the trapezoid grown by half
      // the clearance on each wall, from the stop (moved back as much) out through the base's
      // end (computed here).
      const double play = clearance / 2;
      const double tongue = (12 + 18) / 2.0 * kThickness * (kLength - kThickness);
      const double slot = (12 + 18 + 4 * play) / 2.0 * kThickness * (kLength - kThickness + play);
      EXPECT_NEAR(volumeOf(cut[1]) - volumeOf(pair.plates[1]), tongue, 1e-6 * tongue);
      EXPECT_NEAR(volumeOf(pair.plates[0]) - volumeOf(cut[0]), slot, 1e-6 * slot);
      EXPECT_EQ(testing::manifoldProblem(plateMesh(cut[0])), "");
      for (const Plate& piece : cut[1].attached) EXPECT_EQ(testing::manifoldProblem(plateMesh(piece)), "");
    }
  }
  // Recomputed on the jointed plates, the tongue's walls and end touch the slot's.
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(openAtTheEnd(site))}, {});
  EXPECT_GT(computePlateContacts(cut, {}).size(), 1u);
}

// The side plate's points round its tongue (a grid in the joint's frame: 0.7 mm across and into
// the base, 3 mm along it, over the stop's end of the tongue), stepped along d: does one land
// inside the base?
bool steppedCollision(const SlantedDovetailSite& site, const Plate& mover, const Plate& obstacle, const Vec3& d) {
  constexpr double kStep = 0.7, kMargin = 4, kReach = 25;  // mm
  const SlantedSide& side = site.side;
  const std::vector<Vec3> samples = testing::samplesInside(
      mover, side.origin[0],
      {{{side.intoMortise, -kMargin, site.depth + kMargin, kStep},
        {site.width, -kMargin - 0.034, site.sideWidth + kThickness / 2 + kMargin, kStep},
        {side.along, side.from + site.stop - 6, side.from + site.stop + 60, 3}}});
  return testing::steppedCollision(samples, obstacle, d, kStep, kReach);
}

TEST(PlateSlantedDovetails, TheSweepAgreesWithSteppingTheSideOut) {
  const BaseAndSide pair = baseAndSide();
  const SlantedDovetailSite& s = pair.site;
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(openAtTheEnd(s))}, {});
  const Vec3 away = negated(s.side.intoMortise);
  // Along the side out through the open end: free; back into the stop, off the base, out along
  // the side's plane (a slanted tenon's way), across, into the base: blocked.
  int free = 0;
  for (const Vec3& d : {s.side.along, negated(s.side.along), away, negated(s.side.out), s.side.across,
                        negated(s.side.across), s.side.out}) {
    const bool swept = plateCollidesAlong(cut[1], cut[0], d, tolerance::kContactMm);
    EXPECT_EQ(swept, steppedCollision(s, cut[1], cut[0], d)) << d[0] << "," << d[1] << "," << d[2];
    free += swept ? 0 : 1;
  }
  EXPECT_EQ(free, 1) << "only along the side, out through the open end";
  // Without the joint the side also lifts straight off the base.
  EXPECT_FALSE(plateCollidesAlong(pair.plates[1], pair.plates[0], away, tolerance::kContactMm));
  // The joint model says the same: every face normal, from the side into the base, lets +along,
  // and some face stops each of the other six ways (a normal the way runs into).
  const std::vector<Vec3> normals = slantedDovetailFaceNormals(openAtTheEnd(s));
  for (const Vec3& n : normals) EXPECT_LE(dot(n, s.side.along), tolerance::kDirection);
  for (const Vec3& d : {negated(s.side.along), away, negated(s.side.out), s.side.across, negated(s.side.across), s.side.out}) {
    const bool stopped = std::any_of(normals.begin(), normals.end(), [&](const Vec3& n) { return dot(n, d) > 1e-3; });
    EXPECT_TRUE(stopped) << d[0] << "," << d[1] << "," << d[2];
  }
}

TEST(PlateSlantedDovetails, TheFamilyLetsTheSideOutAlongTheSideOnly) {
  const BaseAndSide pair = baseAndSide();
  // Both ends of the slot can open: along the side both ways, not along its plane or off the base.
  const PlateGraph graph = buildPlateGraph(pair.plates, {pair.contact}, JointRealization::Milled);
  const JointCutOptions options;
  const std::unique_ptr<JointFamily> family =
      makeSlantedDovetailFamily(JointSetting{graph, options, JointRealization::Milled});
  const int side = 1, base = 0;
  const SlantedSide& s = pair.site.side;
  EXPECT_TRUE(family->lets(0, side, s.along));
  EXPECT_TRUE(family->lets(0, side, negated(s.along)));
  EXPECT_TRUE(family->lets(0, base, negated(s.along)));
  EXPECT_FALSE(family->lets(0, side, negated(s.out)));
  EXPECT_FALSE(family->lets(0, side, negated(s.intoMortise)));
  // A way 0.03 degrees off the side (a drawn design's shared edge: IBOIS's hexboxes) is not let:
  // the slot, cut along the side and verified at clearance 0, would bind on it.
  auto turned = [&](double degrees) {
    const double a = degrees * M_PI / 180;
    return plus(scaled(s.along, std::cos(a)), scaled(s.across, std::sin(a)));
  };
  EXPECT_FALSE(family->lets(0, side, turned(0.03)));
  EXPECT_FALSE(family->lets(0, side, turned(1)));
  // The planner's choice for a slide along the side: the slanted tenon lets it out along its
  // plane only, the slanted dovetail along the side.
  const JointFamilies families(graph, options, JointRealization::Milled);
  const std::optional<PlateJoint> joint = families.jointFor(side, base, s.along);
  ASSERT_TRUE(joint.has_value());
  EXPECT_EQ(joint->type, JointType::SlantedDovetail);
  EXPECT_STREQ(jointTypeName(joint->type), "slanted-dovetail");
  EXPECT_EQ(families.jointFor(side, base, negated(s.out))->type, JointType::SlantedTenon);
}

// The box designed: made joints, verified on the jointed plates, both tests on the written plan.
PlateDesignResult designBox(const std::vector<Plate>& plates) {
  PlateDesignOptions options;
  options.realization = JointRealization::Milled;
  options.limits.timeLimitSeconds = 0;
  options.limits.nodeLimit = 3000;
  return designPlateJoints(plates, computePlateContacts(plates, {}), options);
}


void expectSlidAndVerified(const AssemblyDocument& box, const PlateDesignResult& result) {
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_EQ(result.realization, JointRealization::Milled) << result.message;
  int slides = 0;
  for (const PlateJoint& joint : result.joints) slides += joint.type == JointType::SlantedDovetail ? 1 : 0;
  EXPECT_GE(slides, 1) << result.message;
  EXPECT_EQ(verifyJointedPlates(testing::jointedInRemovalOrder(result), result.directions).failure, "");
  const AssemblyDocument written = parseJsonDocument(plateDesignToJson(box, result), "leaning box plan");
  for (const CheckReport& report : testing::checkedByBothMethods(written))
    EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
}

// The leaning box: the back side, the key, slides out along its bottom and top on two slanted
// dovetails, into the base and the lid (before this family: the base slid out first on a square
// dovetail, and a slanted tenon held the front side in the lid).
TEST(PlateSlantedDovetails, TheLeaningBoxDesignsWithSlantedDovetailsAndATamperedPlanFails) {
  const AssemblyDocument box = leaningBox();
  const PlateDesignResult result = designBox(box.plates);
  expectSlidAndVerified(box, result);
  // The key is the back side (plate 3), sliding out along its bottom and top on the tongues
  // that hold the base and the lid to it.
  const std::vector<Plate> inOrder = testing::jointedInRemovalOrder(result);
  ASSERT_EQ(inOrder[0].id, 3);
  ASSERT_EQ(inOrder[0].attached.size(), 2u);
  // Tampered: its tongues taken off (the base then drops away from it too), or its way reversed
  // (into the slots' stops): no longer verified.
  std::vector<Plate> tongueless = inOrder;
  tongueless[0].attached.clear();
  EXPECT_NE(verifyJointedPlates(tongueless, result.directions).failure, "");
  std::vector<Vec3> reversed = result.directions;
  reversed[0] = negated(reversed[0]);
  EXPECT_NE(verifyJointedPlates(inOrder, reversed).failure, "");
}

// The base's end bevelled (its bottom face 20 mm longer, as a mitred end of IBOIS's hexboxes'
// plates): the contact runs out of its top face there, the slot runs on through the bevel.
TEST(PlateSlantedDovetails, TheSlotRunsOutThroughABevelledEnd) {
  std::vector<Plate> box = leaningBox().plates;
  for (Plate& plate : box) {
    if (plate.id != 1) continue;
    for (Vec3& p : plate.bottom[0]) p[0] = p[0] > kLength / 2 ? kLength + 20 : p[0];
  }
  const BaseAndSide pair = baseAndSide(box);
  const SlantedDovetailSite& site = pair.site;
  const int outwards = dot(site.side.along, Vec3{1, 0, 0}) > 0 ? 1 : 0;  // the bevelled end
  ASSERT_TRUE(site.opens[outwards]);
  EXPECT_NEAR(site.reach[outwards], 20, 1e-6);
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(SlantedDovetailCut{site, outwards})}, {});
  const Vec3 out = outwards == 1 ? site.side.along : negated(site.side.along);
  EXPECT_FALSE(plateCollidesAlong(cut[1], cut[0], out, tolerance::kContactMm));
  EXPECT_TRUE(plateCollidesAlong(cut[1], cut[0], negated(out), tolerance::kContactMm));
  EXPECT_TRUE(plateCollidesAlong(cut[1], cut[0], negated(site.side.intoMortise), tolerance::kContactMm));
}

// The paper's plan of the box slides plates along their bevelled sides: the joints no family
// made there (a slanted tenon fitted but let the plate out another way) are made now.
TEST(PlateSlantedDovetails, ThePlanSlidesAlongBevelledSidesAreMade) {
  const AssemblyDocument box = leaningBox();
  const std::vector<PlateContact> contacts = computePlateContacts(box.plates, {});
  PlateDesignOptions options;
  options.realization = JointRealization::Planned;
  options.limits.timeLimitSeconds = 0;
  options.limits.nodeLimit = 3000;
  const PlateDesignResult planned = designPlateJoints(box.plates, contacts, options);
  ASSERT_EQ(planned.status, DesignStatus::Success) << planned.message;
  auto slidesNothingMakes = [&](const JointCutOptions& joints) {
    int count = 0;
    for (const std::string& said : jointsNothingMakes(box.plates, contacts, planned.joints, joints))
      count += said.find("a slanted tenon fits there but lets") != std::string::npos ? 1 : 0;
    return count;
  };
  JointCutOptions without;
  without.slantedDovetail.leastDegrees = 89;
  EXPECT_GE(slidesNothingMakes(without), 1);
  EXPECT_EQ(slidesNothingMakes({}), 0);
}

TEST(PlateSlantedDovetails, TheLeaningBoxTurnedAndRoundedTo6DecimalsDesignsTheSame) {
  const AssemblyDocument box = leaningBox();
  const std::array<Vec3, 3> turn = testing::rotation(0.3, -0.7, 1.1);
  const AssemblyDocument turned =
      documentFromPlates(testing::turnedPlates(box.plates, turn, 1, 6), {}, "turned leaning box");
  expectSlidAndVerified(turned, designBox(turned.plates));
  // The joint alone, turned: the same volumes.
  const BaseAndSide pair = baseAndSide(turned.plates);
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(openAtTheEnd(pair.site))}, {});
  const double tongue = (12 + 18) / 2.0 * kThickness * (kLength - kThickness);
  EXPECT_NEAR(volumeOf(cut[1]) - volumeOf(pair.plates[1]), tongue, 1e-6 * tongue);
}

}  // namespace
}  // namespace desia
