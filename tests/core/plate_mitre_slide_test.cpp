// SPDX-License-Identifier: GPL-3.0-or-later
// Slides along a mitre in thin plates (issue 26; IBOIS's folded plates: 6 mm plates meeting edge to
// edge 62-87 degrees apart, their mitres ending in short bevelled sides).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "plate/joints/mitre_slide.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"
#include "plate/swept_collision.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

constexpr double kThickness = 6, kLength = 120, kWidth = 40;

double volumeOf(const Plate& plate) { return testing::plateVolume(plate); }

// Two 6 mm plates folded along the x axis, their planes `degrees` apart, meeting along a mitre.
// Plate A (the first) ends at x = 0 in a side bevelled 45 degrees (x = 0 on its outer face, 6 on
// its inner) and next to its mitre that side is short (`shortSide` mm on the outer face) before
// a square side runs off at 45 degrees: the shape of the folded plates' ends.
std::vector<Plate> foldedPair(double degrees, double shortSide) {
  const double phi = degrees * M_PI / 180, mitre = kThickness * std::tan(phi / 2);
  // Section coordinates (y, z); A runs along -y with its outer face z = 0, B along dB.
  const Vec3 dA{0, -1, 0}, nA{0, 0, -1};
  const Vec3 dB{0, std::cos(phi), -std::sin(phi)}, nB{0, -std::sin(phi), -std::cos(phi)};
  auto onA = [&](double x, double w, bool inner) {
    return plus(Vec3{x, 0, 0}, plus(scaled(dA, w), scaled(nA, inner ? kThickness : 0)));
  };
  auto onB = [&](double x, double w, bool inner) {
    return plus(Vec3{x, 0, 0}, plus(scaled(dB, w), scaled(nB, inner ? kThickness : 0)));
  };
  const double bevel = kThickness;  // the end side's run along x across the thickness
  Plate a;
  a.id = 1;
  a.bottom = {{onA(0, 0, false), onA(kLength, 0, false), onA(kLength, kWidth, false),
               onA(kWidth - shortSide, kWidth, false), onA(0, shortSide, false)}};
  a.top = {{onA(bevel, mitre, true), onA(kLength, mitre, true), onA(kLength, kWidth, true),
            onA(kWidth - shortSide, kWidth, true), onA(bevel, shortSide + bevel, true)}};
  Plate b;
  b.id = 2;
  b.bottom = {{onB(0, 0, false), onB(kLength, 0, false), onB(kLength, kWidth, false), onB(0, kWidth, false)}};
  b.top = {{onB(0, mitre, true), onB(kLength, mitre, true), onB(kLength, kWidth, true), onB(0, kWidth, true)}};
  return {a, b};
}

// Plate A leaving along +x off B: its groove is stopped ahead and run out behind through the short
// bevelled side. A groove as deep as the plate (6 mm) takes the notch ~8 mm in, past the short
// side on the outer face and within it on the inner (the old code refused every such slide); a
// shallower one holds and cuts cleanly, and the jointed pair lets A out along +x only.
TEST(PlateMitreSlides, AThinPlateWithAShortBevelledEndGetsAShallowerGrooveThatCutsCleanly) {
  for (const double degrees : {62.2, 86.7}) {
    const std::vector<Plate> plates = foldedPair(degrees, 7.4);
    validatePlates(plates, {}, "folded pair");
    const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
    ASSERT_EQ(contacts.size(), 1u) << degrees;
    const PlateContact& contact = contacts[0];
    ASSERT_EQ(contact.a, 0);
    const Vec3 leave{1, 0, 0};
    const std::optional<MitreSlide> slide = mitreSlideOf(plates, contact, 0, leave);
    ASSERT_TRUE(slide.has_value()) << degrees;
    EXPECT_LT(slide->depth, kThickness) << "shallower than the plate: the deepest groove's notch would not cut";
    EXPECT_GE(slide->depth, JointCutOptions{}.mitreSlide.shallowestGroove);
    const std::vector<Plate> jointed = cutJoints(plates, {jointCut(*slide)}, {});
    validatePlates(jointed, {}, "jointed");
    for (const Plate& plate : jointed) EXPECT_NO_THROW(checkClosedMesh(plateMesh(plate), "jointed"));
    // DBG+LP's input: the contacts recomputed from the jointed pair.
    Assembly two;
    two.parts = {{1, "slide"}, {2, "tongue"}};
    for (const PlateContact& c : computePlateContacts(jointed, {})) two.contacts.push_back({c.a, c.b, c.normal, c.area});
    const Vec3 axisA = plateThicknessAxis(plates[0]), axisB = plateThicknessAxis(plates[1]);
    for (const Vec3& d : {leave, negated(leave), contact.normal, negated(contact.normal), axisA, negated(axisA), axisB,
                          negated(axisB)}) {
      EXPECT_EQ(isPartFreeAlong(two, nullptr, 0, d), dot(d, leave) > 1 - 1e-9)
          << degrees << ": " << d[0] << "," << d[1] << "," << d[2];
    }
    // The sweep agrees with the contacts: out along +x clear, back and across blocked.
    EXPECT_FALSE(plateCollidesAlong(jointed[0], jointed[1], leave, 0.05)) << degrees;
    EXPECT_TRUE(plateCollidesAlong(jointed[0], jointed[1], negated(leave), 0.05)) << degrees;
    EXPECT_TRUE(plateCollidesAlong(jointed[0], jointed[1], negated(contact.normal), 0.05)) << degrees;
    // The tongue plate gains the tongue exactly: its section (a dovetail: root 2h, tip 2(h + lean
    // depth), depth * (into . mitre normal) high) times its length along the edge.
    const double high = slide->depth * dot(slide->into, slide->mitreNormal);
    const double section = (2 * slide->halfHeight + slide->lean * slide->depth) * high;
    const double tongue = section * (slide->tongueTo - slide->tongueFrom);
    EXPECT_GT(tongue, 100) << degrees;
    EXPECT_NEAR(volumeOf(jointed[1]) - volumeOf(plates[1]), tongue, 1e-6 * tongue) << degrees;
    // Tampered: the tongue taken off, the slide plate is no longer held across the mitre.
    std::vector<Plate> tampered = jointed;
    tampered[1].attached.clear();
    EXPECT_FALSE(plateCollidesAlong(tampered[0], tampered[1], negated(contact.normal), 0.05)) << degrees;
  }
}

// The family works each answer out once (per contact, mover and way along the edge): its answers
// are mitreSlideOf's, along the edge only, and sizes that would make no groove (straight flanks,
// a shallowest groove of 0, which would never end the depths tried) are refused by name.
TEST(PlateMitreSlides, TheFamilyAnswersAsMitreSlideOfAndRefusesGroovesThatCannotHold) {
  const std::vector<Plate> plates = foldedPair(62.2, 7.4);
  const std::vector<PlateContact> contacts = computePlateContacts(plates, {});
  ASSERT_EQ(contacts.size(), 1u);
  const PlateGraph graph = buildPlateGraph(plates, contacts, JointRealization::Milled);
  const JointCutOptions options;
  const std::unique_ptr<JointFamily> family =
      makeMitreSlideFamily(JointSetting{graph, options, JointRealization::Milled});
  const Vec3 edge = normalized(contacts[0].edgeDirection);
  const std::vector<Vec3> ways{edge, negated(edge), contacts[0].normal, normalized(plus(edge, Vec3{0, 0, 1e-3}))};
  int lets = 0;
  for (int pass = 0; pass < 2; ++pass) {  // the second pass is answered from what the first worked out
    for (const int mover : {0, 1}) {
      for (const Vec3& d : ways) {
        const bool expected = mitreSlideOf(plates, contacts[0], mover, d, options).has_value();
        EXPECT_EQ(family->lets(0, mover, d), expected) << pass << " " << mover << ": " << d[0] << "," << d[1] << "," << d[2];
        lets += expected ? 1 : 0;
      }
    }
  }
  EXPECT_GE(lets, 2) << "plate A leaves along +x on a slide (the test above)";
  // Asked off the edge first, then along it: the answer along it is still a slide.
  const std::unique_ptr<JointFamily> fresh = makeMitreSlideFamily(JointSetting{graph, options, JointRealization::Milled});
  EXPECT_FALSE(fresh->lets(0, 0, normalized(plus(Vec3{1, 0, 0}, Vec3{0, 0, 1e-3}))));
  EXPECT_TRUE(fresh->lets(0, 0, {1, 0, 0}));
  for (const auto& [setting, change] :
       std::vector<std::pair<std::string, void (*)(JointCutOptions&)>>{
           {"mitreSlide.slope", [](JointCutOptions& o) { o.mitreSlide.slope = 0; }},
           {"mitreSlide.shallowestGroove", [](JointCutOptions& o) { o.mitreSlide.shallowestGroove = 0; }}}) {
    JointCutOptions bad;
    change(bad);
    try {
      makeMitreSlideFamily(JointSetting{graph, bad, JointRealization::Milled});
      ADD_FAILURE() << setting << " accepted";
    } catch (const Error& error) {
      EXPECT_EQ(error.code(), ErrorCode::BadInput);
      EXPECT_NE(std::string(error.what()).find(setting), std::string::npos) << error.what();
    }
  }
  // The free function ends too with such a least (depths tried down to 0.1 mm).
  JointCutOptions zero;
  zero.mitreSlide.shallowestGroove = 0;
  EXPECT_TRUE(mitreSlideOf(plates, contacts[0], 0, {1, 0, 0}, zero).has_value());
}

}  // namespace
}  // namespace desia
