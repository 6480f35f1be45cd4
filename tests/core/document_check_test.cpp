// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` on design results (core/io/document_check.cpp): beyond the tests on the written
// contacts, a plate or frame result's removal plan is replayed on its real shapes, so a result
// whose plan or geometry was changed after the design is caught, with the part named.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

using nlohmann::json;

std::string exampleText(const std::string& path) { return testing::readFileText(testing::projectPath(path)); }

// The TABLE designed with cut joints, as the result document `desia design plate` writes.
json tableResult() {
  const AssemblyDocument input = parseAssemblyText(exampleText("examples/plate/table.json"), "table.json");
  const PlateDesignResult result = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), {});
  EXPECT_EQ(result.status, DesignStatus::Success) << result.message;
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

json plannedCabinet() {
  const AssemblyDocument input = parseAssemblyText(exampleText("examples/plate/cabinet.json"), "cabinet.json");
  PlateDesignOptions options;
  options.realization = JointRealization::Planned;
  const PlateDesignResult result = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), options);
  EXPECT_EQ(result.status, DesignStatus::Success) << result.message;
  return json::parse(plateDesignToJson(input, result));
}

TEST(DocumentCheck, PlannedPlateResultIsReplayedOnItsUncutPlatesAndSaysNothingIsCut) {
  const CheckReport report = checkText(plannedCabinet().dump());
  ASSERT_TRUE(report.shapeRemoval.has_value());
  EXPECT_EQ(report.shapeRemoval->failure, "");
  EXPECT_NE(report.shapeRemoval->checked.find("nothing is cut"), std::string::npos) << report.shapeRemoval->checked;
  EXPECT_TRUE(checkPassed(report));
}

// A planned result whose directions are reversed fails: its plan is tested whatever
// `jointGeometry` says (before, only "cut" and "milled" results were).
TEST(DocumentCheck, PlannedPlateResultWithReversedDirectionsFails) {
  json result = plannedCabinet();
  for (size_t k = 0; k + 1 < result["removal"].size(); ++k) {
    json& d = result["removal"][k]["direction"];
    d = {-d[0].get<double>(), -d[1].get<double>(), -d[2].get<double>()};
  }
  EXPECT_FALSE(checkPassed(checkText(result.dump())));
}

TEST(DocumentCheck, AResultWithAnUnknownJointGeometryIsBadInput) {
  for (const json& value : {json("CUT"), json(nullptr), json(1), json("Planned")}) {
    json result = tableResult();
    result["jointGeometry"] = value;
    EXPECT_THROW(checkText(result.dump()), Error) << value.dump();
  }
  json result = tableResult();
  result.erase("jointGeometry");
  EXPECT_THROW(checkText(result.dump()), Error) << "a removal plan without its jointGeometry";
}

// The ids of plates 1 and 6 swapped in `plates` (their geometry stays in place): the plan now
// takes the table's side out first, which the jointed plates do not allow.
TEST(DocumentCheck, PlateIdsSwappedFail) {
  json result = tableResult();
  ASSERT_EQ(result["plates"].size(), 6u);
  result["plates"][0]["id"] = 6;
  result["plates"][5]["id"] = 1;
  EXPECT_FALSE(checkPassed(checkText(result.dump())));
}

// The same result with `parts`, `plates` and `contacts` listed in another order is the same result.
TEST(DocumentCheck, PartsAndPlatesInAnyOrderGiveTheSameVerdict) {
  json result = tableResult();
  std::reverse(result["parts"].begin(), result["parts"].end());
  std::reverse(result["plates"].begin(), result["plates"].end());
  std::reverse(result["contacts"].begin(), result["contacts"].end());
  const CheckReport report = checkText(result.dump());
  EXPECT_TRUE(checkPassed(report)) << report.result.reason << " / "
                                   << (report.shapeRemoval ? report.shapeRemoval->failure : "");
  EXPECT_EQ(report.result.key, 0);
}

// Every plate deleted in turn, with its direction kept or reversed: never a pass, always an
// error naming the part that has no plate.
TEST(DocumentCheck, APlateMissingIsBadInputNamingItsPart) {
  const json original = tableResult();
  for (size_t k = 0; k < original["plates"].size(); ++k) {
    json result = original;
    const int id = result["plates"][k]["id"].get<int>();
    result["plates"].erase(k);
    try {
      checkText(result.dump());
      ADD_FAILURE() << "plate " << id << " deleted was read";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("part " + std::to_string(id) + " has no plate"), std::string::npos)
          << error.what();
    }
  }
}

// What the cut files make is checked against what was verified: mortises taken out of the
// fabrication plates, or a plate moved there, fail.
TEST(DocumentCheck, FabricationPlatesThatAreNotTheVerifiedOnesFail) {
  const AssemblyDocument input = parseAssemblyText(exampleText("examples/plate/table.json"), "table.json");
  PlateDesignOptions options;
  options.joints.clearance = 0.2;
  const PlateDesignResult designed = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), options);
  ASSERT_EQ(designed.status, DesignStatus::Success) << designed.message;
  const json result = json::parse(plateDesignToJson(input, designed));
  ASSERT_TRUE(result.contains("fabricationPlates"));
  EXPECT_TRUE(checkPassed(checkText(result.dump())));
  int mortised = -1;  // a fabrication plate with holes (mortises)
  for (size_t k = 0; k < result["fabricationPlates"].size() && mortised < 0; ++k) {
    if (result["fabricationPlates"][k].contains("holes")) mortised = static_cast<int>(k);
  }
  ASSERT_GE(mortised, 0);
  json noMortises = result;
  noMortises["fabricationPlates"][mortised].erase("holes");
  const CheckReport withoutMortises = checkText(noMortises.dump());
  EXPECT_FALSE(checkPassed(withoutMortises));
  ASSERT_TRUE(withoutMortises.shapeRemoval.has_value());
  EXPECT_NE(withoutMortises.shapeRemoval->failure.find("fabricationPlates: plate"), std::string::npos);
  json moved = result;
  for (json& face : moved["fabricationPlates"][1]["faces"]) {
    for (json& point : face) point[0] = point[0].get<double>() + 300;
  }
  if (moved["fabricationPlates"][1].contains("holes")) {
    for (json& hole : moved["fabricationPlates"][1]["holes"]) {
      for (json& face : hole) {
        for (json& point : face) point[0] = point[0].get<double>() + 300;
      }
    }
  }
  EXPECT_FALSE(checkPassed(checkText(moved.dump())));
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

namespace desia {
namespace {

// What the designer writes, `desia check` passes: both run one verification on the plates in
// removal order. Seeds 9 and 12 of the DODECAHEDRON with milled joints wrote results that their
// own check then failed ("plate 3 cannot leave along its direction"): the designer judged the
// contacts of the plates in input order, the check in removal order.
TEST(DocumentCheck, WhatTheDesignerWritesTheCheckPasses) {
  const AssemblyDocument input =
      parseAssemblyText(exampleText("examples/plate/dodecahedron.json"), "dodecahedron.json");
  for (const uint64_t seed : {9, 12}) {
    PlateDesignOptions options;
    options.realization = JointRealization::Milled;
    options.seed = seed;
    options.limits.timeLimitSeconds = 0;
    options.limits.nodeLimit = 5000;
    const PlateDesignResult result = designPlateJoints(input.plates, input.plateContacts, options);
    ASSERT_EQ(result.status, DesignStatus::Success) << "seed " << seed << ": " << result.message;
    const CheckReport report = checkText(plateDesignToJson(input, result));
    EXPECT_TRUE(checkPassed(report)) << "seed " << seed << ": "
                                     << (report.shapeRemoval ? report.shapeRemoval->failure : report.result.reason);
  }
}

}  // namespace
}  // namespace desia

namespace desia {
namespace {

// The seed corpus of the plate_result fuzz harness is real: its results pass `desia check` and
// its tampered copies (ids swapped, a plate deleted, the key's way out reversed, a fabrication
// plate moved 300 mm, jointGeometry "CUT") never do, refused (exit 2) or failing.
TEST(DocumentCheck, ThePlateResultFuzzSeedsPassOrFailAsTheyShould) {
  const std::string folder = "tests/fuzz/corpus/plate_result/";
  for (const char* passing : {"table_cut.json", "mitred_box_milled.json", "bookshelf_planned.json",
                              "turned_table_6_decimals.json"}) {
    EXPECT_TRUE(checkPassed(checkText(exampleText(folder + passing)))) << passing;
  }
  for (const char* tampered : {"table_ids_swapped.json", "table_plate_deleted.json", "table_key_reversed.json",
                               "table_fabrication_moved.json", "table_joint_geometry_case.json"}) {
    bool passed = false;
    try {
      passed = checkPassed(checkText(exampleText(folder + tampered)));
    } catch (const Error&) {
      passed = false;  // refused as bad input
    }
    EXPECT_FALSE(passed) << tampered;
  }
}

}  // namespace
}  // namespace desia
