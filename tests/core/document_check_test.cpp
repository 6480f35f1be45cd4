// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` on design results (core/io/document_check.cpp): beyond the tests on the written
// contacts, a plate or frame result's removal plan is replayed on its real shapes, so a result
// whose plan or geometry was changed after the design is caught, with the part named.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "desia/document_check.h"
#include "desia/error.h"
#include "desia/plate_design.h"
#include "desia/plate_design_io.h"
#include "test_support.h"

namespace desia {
namespace {

using nlohmann::json;

std::string exampleText(const std::string& path) { return testing::readFileText(testing::projectPath(path)); }

// The TABLE designed with cut joints, as the result document `desia design plate` writes.
json tableResult() {
  const AssemblyDocument input = parseAssemblyText(exampleText("examples/plate/table.json"), "table.json");
  const PlateDesignResult result = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), {});
  EXPECT_EQ(result.status, PlateDesignStatus::Success) << result.message;
  return json::parse(plateDesignToJson(input, result));
}

CheckReport checkText(const std::string& text) {
  const AssemblyDocument document = parseAssemblyText(text, "result.json");
  CheckOptions options;
  options.method = CheckMethod::Both;
  return checkDocument(document, options);
}

TEST(DocumentCheck, PlateResultIsReplayedOnItsJointedPlates) {
  const CheckReport report = checkText(tableResult().dump());
  ASSERT_TRUE(report.shapeRemoval.has_value());
  EXPECT_EQ(report.shapeRemoval->failure, "");
  EXPECT_TRUE(checkPassed(report));
}

TEST(DocumentCheck, PlateResultWithAChangedDirectionFailsNamingThePlate) {
  json result = tableResult();
  const json planned = result["removal"][1]["direction"];
  result["removal"][1]["direction"] = {-planned[0].get<double>(), -planned[1].get<double>(), -planned[2].get<double>()};
  const CheckReport report = checkText(result.dump());
  ASSERT_TRUE(report.shapeRemoval.has_value());
  EXPECT_NE(report.shapeRemoval->failure.find("plate 2"), std::string::npos) << report.shapeRemoval->failure;
  EXPECT_FALSE(checkPassed(report));
}

TEST(DocumentCheck, PlateResultWithATenonCutOffFailsOnTheRecomputedContacts) {
  // The written contacts still say interlocking; the jointed plates no longer are. Plate 1 (the
  // key) is replaced by the same plate without its joints (the input's top): its faces now
  // overlap the tenons of the plates below or it slides off, and the check must see it.
  json result = tableResult();
  const int inputId = result["plates"][0]["inputId"].get<int>();
  const json input = json::parse(exampleText("examples/plate/table.json"));
  json plain;
  for (const json& plate : input["plates"]) {
    if (plate["id"] == inputId) plain = plate;
  }
  ASSERT_FALSE(plain.is_null());
  plain["id"] = 1;
  result["plates"][0] = plain;
  bool caught = false;
  try {
    const CheckReport report = checkText(result.dump());
    caught = report.shapeRemoval && !report.shapeRemoval->failure.empty();
  } catch (const Error&) {
    caught = true;  // the plates now overlap: refused on reading, which names them
  }
  EXPECT_TRUE(caught);
}

TEST(DocumentCheck, PlannedPlateResultHasNoShapesToReplay) {
  const AssemblyDocument input = parseAssemblyText(exampleText("examples/plate/cabinet.json"), "cabinet.json");
  PlateDesignOptions options;
  options.realization = JointRealization::Planned;
  const PlateDesignResult result = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), options);
  ASSERT_EQ(result.status, PlateDesignStatus::Success) << result.message;
  const CheckReport report = checkText(plateDesignToJson(input, result));
  EXPECT_FALSE(report.shapeRemoval.has_value());
  EXPECT_TRUE(checkPassed(report));
}

TEST(DocumentCheck, MalformedRemovalPlanIsBadInput) {
  json result = tableResult();
  result["removal"][0]["direction"] = nullptr;
  EXPECT_THROW(checkText(result.dump()), Error);
  result = tableResult();
  result["removal"].erase(0);
  EXPECT_THROW(checkText(result.dump()), Error);
}

TEST(DocumentCheck, FrameResultIsSweptBeamByBeam) {
  const CheckReport report = checkText(exampleText("examples/frame/frame_cube_result.json"));
  ASSERT_TRUE(report.shapeRemoval.has_value());
  EXPECT_EQ(report.shapeRemoval->failure, "");
  EXPECT_TRUE(checkPassed(report));
}

TEST(DocumentCheck, FrameResultWithAReversedAxisFailsNamingTheBeam) {
  json result = json::parse(exampleText("examples/frame/frame_cube_result.json"));
  std::string& direction = result["removal"][2]["direction"].get_ref<std::string&>();
  direction[0] = direction[0] == '+' ? '-' : '+';
  const CheckReport report = checkText(result.dump());
  ASSERT_TRUE(report.shapeRemoval.has_value());
  EXPECT_NE(report.shapeRemoval->failure.find("beam 3 cannot leave along " + direction), std::string::npos)
      << report.shapeRemoval->failure;
  EXPECT_FALSE(checkPassed(report));
}

TEST(DocumentCheck, FrameWithoutJointsAndVoxelPuzzlesHaveNoPlanToReplay) {
  EXPECT_FALSE(checkText(exampleText("examples/frame/frame_cube.json")).shapeRemoval.has_value());
  const AssemblyDocument cube = testing::loadReference("result_puz/Cube_4x4x4_K9.puz");
  EXPECT_FALSE(checkDocument(cube).shapeRemoval.has_value());
}

}  // namespace
}  // namespace desia
