// SPDX-License-Identifier: GPL-3.0-or-later
// Slanted mortise-and-tenon joints (issue 26): a plate's side bevelled to lie on another's face,
// their planes 45..<90 degrees apart (IBOIS's hexboxes: 80..88), tenons along the side plate's
// plane through slanted mortises; the side plate leaves only along its plane, out of them. The
// design: examples/plate/leaning_box.json (make_leaning_box.py), its long sides leaning out 15
// degrees, an upright end between them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>

#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/missing_joints.h"
#include "plate/joints/slanted_tenon.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kLeanDegrees = 15;  // the box's sides from upright: planes 75 degrees apart
constexpr double kThickness = 18;    // every board's, mm

AssemblyDocument leaningBox() { return testing::loadPlateExample("leaning_box.json"); }

double volumeOf(const Plate& plate) { return testing::plateVolume(plate); }

// The base and the left side, and the site of the slanted tenon on their contact.
struct BaseAndSide {
  std::vector<Plate> plates;
  PlateContact contact;
  SlantedTenonSite site;
};

BaseAndSide baseAndSide() {
  const AssemblyDocument box = leaningBox();
  BaseAndSide pair;
  for (const Plate& plate : box.plates) {
    if (plate.id == 1 || plate.id == 2) pair.plates.push_back(plate);
  }
  const std::vector<PlateContact> contacts = computePlateContacts(pair.plates, {});
  EXPECT_EQ(contacts.size(), 1u);
  pair.contact = contacts.at(0);
  const std::optional<SlantedTenonSite> site = slantedTenonSiteOf(pair.plates, pair.contact);
  EXPECT_TRUE(site.has_value());
  pair.site = *site;
  return pair;
}

// The side plate's points around its tenons (a grid in the joint's frame: 0.7 mm across the side
// and along `out`, 3 mm along it), stepped along d: does one land inside the base?
bool steppedCollision(const SlantedTenonSite& site, const Plate& mover, const Plate& obstacle, const Vec3& d) {
  constexpr double kStep = 0.7, kMargin = 3;  // mm
  const std::vector<Vec3> samples =
      testing::samplesInside(mover, site.origin[0],
                             {{{site.out, -kMargin, site.reach + kMargin, kStep},
                               {site.across, -kMargin, kThickness + kMargin, kStep},
                               {site.along, site.from, site.to, 3}}});
  return testing::steppedCollision(samples, obstacle, d, kStep, site.reach + kMargin);
}

TEST(PlateSlantedTenons, TheSideStandsOnTheBaseAt75DegreesWithTwoTenonsThroughIt) {
  const BaseAndSide pair = baseAndSide();
  const SlantedTenonSite& site = pair.site;
  EXPECT_EQ(pair.plates[static_cast<size_t>(site.tenonPlate)].id, 2);
  EXPECT_EQ(pair.plates[static_cast<size_t>(site.mortisePlate)].id, 1);
  const double angle = std::acos(std::abs(dot(plateThicknessAxis(pair.plates[0]), plateThicknessAxis(pair.plates[1]))));
  EXPECT_NEAR(angle * 180 / M_PI, 90 - kLeanDegrees, 1e-6);
  // The side is 400 mm long: two tenons (from 8 thicknesses), each a fifth of it.
  ASSERT_EQ(site.spans.size(), 2u);
  EXPECT_NEAR(site.spans[0].second - site.spans[0].first, 400.0 / 5, 1e-6);
  // Through the base along the side's plane: its thickness over the sine of the angle.
  EXPECT_NEAR(site.reach, kThickness / std::sin(angle), 1e-6);
  // Tilted further than the family's least angle, or square (the square tenon's), no site.
  JointCutOptions steep;
  steep.slantedTenon.leastDegrees = 80;
  EXPECT_FALSE(slantedTenonSiteOf(pair.plates, pair.contact, steep).has_value());
  // Too little wood round the mortises (a margin wider than the 80 mm between them and the base's end), none.
  JointCutOptions wide;
  wide.woodMargin = 85;
  EXPECT_FALSE(slantedTenonSiteOf(pair.plates, pair.contact, wide).has_value());
  JointCutOptions bad;
  bad.slantedTenon.leastDegrees = 0;
  const PlateGraph graph = buildPlateGraph(pair.plates, {pair.contact}, JointRealization::Milled);
  EXPECT_THROW(JointFamilies families(graph, bad, JointRealization::Milled), Error);
}

TEST(PlateSlantedTenons, TheSideGainsItsTenonsAndTheBaseLosesThemPlusTheClearance) {
  const BaseAndSide pair = baseAndSide();
  const SlantedTenonSite& site = pair.site;
  const double sine = std::sin((90 - kLeanDegrees) * M_PI / 180);
  for (const double clearance : {0.0, 0.4}) {
    JointCutOptions options;
    options.clearance = clearance;
    const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(site)}, options);
    ASSERT_EQ(cut.size(), 2u);
    // Each tenon: a parallelepiped of its width, the side's thickness and the reach; each mortise:
    // the same grown by the clearance across and along, as deep as the base (computed here).
    double tenons = 0, mortises = 0;
    for (const auto& [start, end] : site.spans) {
      tenons += (end - start) * kThickness * kThickness / sine;
      mortises += (end - start + clearance) * (kThickness + clearance) * kThickness / sine;
    }
    EXPECT_NEAR(volumeOf(cut[1]) - volumeOf(pair.plates[1]), tenons, 1e-6 * tenons);
    EXPECT_NEAR(volumeOf(pair.plates[0]) - volumeOf(cut[0]), mortises, 1e-6 * mortises);
    EXPECT_EQ(testing::manifoldProblem(plateMesh(cut[0])), "");
    for (const Plate& tenon : cut[1].attached) EXPECT_EQ(testing::manifoldProblem(plateMesh(tenon)), "");
  }
  // Recomputed on the jointed plates, the tenons' cheeks and ends touch the mortises' walls.
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(site)}, {});
  EXPECT_GT(computePlateContacts(cut, {}).size(), 1u);
}

TEST(PlateSlantedTenons, TheSweepAgreesWithSteppingTheSideOut) {
  const BaseAndSide pair = baseAndSide();
  const std::vector<Plate> cut = cutJoints(pair.plates, {jointCut(pair.site)}, {});
  const SlantedTenonSite& s = pair.site;
  const Vec3 upright = normalized(plateThicknessAxis(pair.plates[0]));
  const Vec3 away = dot(upright, s.intoMortise) < 0 ? upright : negated(upright);
  // Out along its plane: free; straight up off the base, along the side, across it, down: blocked.
  int free = 0;
  for (const Vec3& d : {negated(s.out), away, s.along, negated(s.along), s.across, negated(s.across), s.out}) {
    const bool swept = plateCollidesAlong(cut[1], cut[0], d, tolerance::kContactMm);
    EXPECT_EQ(swept, steppedCollision(s, cut[1], cut[0], d)) << d[0] << "," << d[1] << "," << d[2];
    free += swept ? 0 : 1;
  }
  EXPECT_EQ(free, 1) << "only along its plane, out of the mortises";
  // Without the joint the side also lifts straight off the base.
  EXPECT_FALSE(plateCollidesAlong(pair.plates[1], pair.plates[0], away, tolerance::kContactMm));
  // The joint model says the same: every face normal, from the side into the base, lets -out only.
  for (const Vec3& n : slantedTenonFaceNormals(s)) EXPECT_LE(dot(n, negated(s.out)), tolerance::kDirection);
}

// The box designed: made joints, verified on the jointed plates, both tests on the written plan.
// Without slanted sliding dovetails (at 75 degrees they let the back side slide out first along
// its bottom and top, and no slanted tenon is needed: plate_slanted_dovetail_test.cpp).
PlateDesignResult designBox(const std::vector<Plate>& plates, JointRealization realization) {
  PlateDesignOptions options;
  options.realization = realization;
  options.joints.slantedDovetail.leastDegrees = 89;
  options.limits.timeLimitSeconds = 0;
  options.limits.nodeLimit = 3000;
  return designPlateJoints(plates, computePlateContacts(plates, {}), options);
}

void expectMadeAndVerified(const AssemblyDocument& box, const PlateDesignResult& result) {
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_EQ(result.realization, JointRealization::Milled) << result.message;
  std::map<JointType, int> byType;
  for (const PlateJoint& joint : result.joints) ++byType[joint.type];
  EXPECT_GE(byType[JointType::SlantedTenon], 1) << result.message;
  const std::vector<Plate> inOrder = testing::jointedInRemovalOrder(result);
  EXPECT_EQ(verifyJointedPlates(inOrder, result.directions).failure, "");
  const AssemblyDocument written = parseJsonDocument(plateDesignToJson(box, result), "leaning box plan");
  for (const CheckReport& report : testing::checkedByBothMethods(written))
    EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
}

TEST(PlateSlantedTenons, TheLeaningBoxDesignsMilledAndAutoWithSlantedTenons) {
  const AssemblyDocument box = leaningBox();
  expectMadeAndVerified(box, designBox(box.plates, JointRealization::Milled));
  const PlateDesignResult automatic = designBox(box.plates, JointRealization::Auto);
  expectMadeAndVerified(box, automatic);
  // A laser cuts square to the sheet: the plates' planes 75 degrees apart get no cut joint.
  EXPECT_NE(designBox(box.plates, JointRealization::Cut).status, DesignStatus::Success);
  // Tampered: a side's tenons taken off, the plan no longer verifies.
  std::vector<Plate> inOrder;
  for (int index : automatic.order) inOrder.push_back(automatic.jointedPlates[static_cast<size_t>(index)]);
  int tampered = 0;
  for (Plate& plate : inOrder) {
    if (plate.attached.empty() || tampered > 0) continue;
    std::vector<Plate> plates = inOrder;
    plates[static_cast<size_t>(&plate - inOrder.data())].attached.clear();
    EXPECT_NE(verifyJointedPlates(plates, automatic.directions).failure, "") << "plate " << plate.id;
    ++tampered;
  }
  EXPECT_EQ(tampered, 1);
}

TEST(PlateSlantedTenons, TheLeaningBoxTurnedAndRoundedTo6DecimalsDesignsTheSame) {
  const AssemblyDocument box = leaningBox();
  const std::array<Vec3, 3> turn = testing::rotation(0.3, -0.7, 1.1);
  const AssemblyDocument turned =
      documentFromPlates(testing::turnedPlates(box.plates, turn, 1, 6), {}, "turned leaning box");
  expectMadeAndVerified(turned, designBox(turned.plates, JointRealization::Milled));
}

// The paper's plan of the box lets some plates out along their edges: where a slanted tenon fits
// such a pair but lets the plate out another way, the list of joints nothing makes says so.
TEST(PlateSlantedTenons, TheMissingJointsSayWhereASlantedTenonFitsButLetsThePlateOutAnotherWay) {
  const AssemblyDocument box = leaningBox();
  const std::vector<PlateContact> contacts = computePlateContacts(box.plates, {});
  const PlateDesignResult planned = designBox(box.plates, JointRealization::Planned);
  ASSERT_EQ(planned.status, DesignStatus::Success) << planned.message;
  int fits = 0;
  JointCutOptions noSlantedDovetails;  // which make those joints (plate_slanted_dovetail_test.cpp)
  noSlantedDovetails.slantedDovetail.leastDegrees = 89;
  for (const std::string& said : jointsNothingMakes(box.plates, contacts, planned.joints, noSlantedDovetails))
    fits += said.find("a slanted tenon fits there but lets") != std::string::npos ? 1 : 0;
  EXPECT_GE(fits, 1);
}

}  // namespace
}  // namespace desia
