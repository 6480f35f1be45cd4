// SPDX-License-Identifier: GPL-3.0-or-later
// When 'auto' falls back to the paper's plan (nothing cut), the plates and edges that got no made
// joint are named with how they meet (issue 26, item 2).
#include <gtest/gtest.h>

#include <string>

#include "desia/plate.h"
#include "plate/joints/missing_joints.h"
#include "test_support.h"

namespace desia {
namespace {

AssemblyDocument loadPlateExample(const std::string& name) {
  const std::string path = "examples/plate/" + name;
  return parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
}

// A search that ends at its root says why no plate can be the first step (the key), by plate.
std::string firstStepRefusal(const std::string& example) {
  const AssemblyDocument design = loadPlateExample(example);
  PlateDesignOptions options;
  options.realization = JointRealization::Cut;
  const PlateDesignResult result = designPlateJoints(design.plates, computePlateContacts(design.plates, {}), options);
  EXPECT_EQ(result.status, DesignStatus::NotFound) << example << ": " << result.message;
  EXPECT_EQ(result.progress.bestDepth, 0) << example;
  return result.message;
}

TEST(PlateMissingJoints, ASearchEndingAtItsRootSaysWhyNoPlateCanBeTakenFirst) {
  // The cube's plates meet edge to edge, mitred: no laser-cut joint fits, so each plate could leave
  // along many ways, and a key must have one only.
  EXPECT_NE(firstStepRefusal("cube.json").find("(no plate can be taken first: of 6 plates, 6 free to leave, but along "
                                               "more than the one way a key may)"),
            std::string::npos);
  // The LIZARD's plates meet at 31..38 degrees: most are held by their neighbours along every way.
  const std::string lizard = firstStepRefusal("lizard.json");
  EXPECT_NE(lizard.find("no plate can be taken first: of 38 plates, 32 blocked along every way out by the plates "
                        "they touch or would run into"),
            std::string::npos)
      << lizard;
  EXPECT_NE(lizard.find("; 6 free to leave"), std::string::npos) << lizard;
}

TEST(PlateMissingJoints, TheIcosahedronsPlanWithoutStepTenonsNamesTheEdgesNoMadeJointFits) {
  const AssemblyDocument icosahedron = loadPlateExample("icosahedron.json");
  const std::vector<PlateContact> contacts = computePlateContacts(icosahedron.plates, {});
  PlateDesignOptions options;
  options.realization = JointRealization::Auto;
  // Without step tenons (their angles narrowed past the icosahedron's 41.8 degrees; with them it
  // mills, plate_step_tenon_test.cpp).
  options.joints.stepTenon.leastDegrees = options.joints.stepTenon.mostDegrees = 50;
  const PlateDesignResult result = designPlateJoints(icosahedron.plates, contacts, options);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  ASSERT_EQ(result.realization, JointRealization::Planned) << "no laser-cut or milled plan exists";
  const std::vector<std::string> missing =
      jointsNothingMakes(icosahedron.plates, contacts, result.joints, options.joints);
  EXPECT_TRUE(jointsNothingMakes(icosahedron.plates, contacts, result.joints, {}).empty())
      << "step tenons make every joint of its plan";
  ASSERT_FALSE(missing.empty());
  EXPECT_LT(missing.size(), result.joints.size()) << "tenons across mitres fit some of the plan's joints";
  // Every face of the icosahedron meets its neighbours edge to edge, their planes 41.8 degrees apart
  // (a dihedral angle of 138.2 degrees).
  for (const std::string& said : missing) {
    EXPECT_NE(said.find(": edge to edge, their planes 41.8 degrees apart, plate "), std::string::npos) << said;
  }
  EXPECT_NE(result.message.find("no joint that can be cut or milled for " + std::to_string(missing.size()) +
                                " of the plan's " + std::to_string(result.joints.size()) + " joints: " + missing[0]),
            std::string::npos)
      << result.message;
  // Why milled found nothing names the milled families, step tenons and their angles included.
  EXPECT_NE(result.message.find("no milled plan: no interlocking joint plan exists"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("tenons across mitres, step tenons where plates meet edge to edge with their planes "
                                "50 to 50 degrees apart)"),
            std::string::npos)
      << result.message;
}

TEST(PlateMissingJoints, AMilledPlanHasAMadeJointForEachOfItsJoints) {
  // The slanted TABLE's milled plan (its halved joint at 60 degrees has slanted notch walls, which
  // only a router makes): mortise-and-tenon, dovetail and halved joints, each one a family makes; its planned plan has joints no made one fits (a side leaving across the top).
  const AssemblyDocument table = loadPlateExample("table_slanted_crossing.json");
  const std::vector<PlateContact> contacts = computePlateContacts(table.plates, {});
  PlateDesignOptions options;
  options.realization = JointRealization::Milled;
  const PlateDesignResult milled = designPlateJoints(table.plates, contacts, options);
  ASSERT_EQ(milled.status, DesignStatus::Success) << milled.message;
  EXPECT_EQ(jointsNothingMakesSentence(table.plates, contacts, milled.joints, {}), "");
  options.realization = JointRealization::Planned;
  const PlateDesignResult planned = designPlateJoints(table.plates, contacts, options);
  ASSERT_EQ(planned.status, DesignStatus::Success) << planned.message;
  for (const std::string& said : jointsNothingMakes(table.plates, contacts, planned.joints, {}))
    EXPECT_EQ(said.find("edge to edge"), std::string::npos) << "the TABLE's plates meet edge on face: " << said;
}

}  // namespace
}  // namespace desia
