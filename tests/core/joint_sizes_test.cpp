// SPDX-License-Identifier: GPL-3.0-or-later
// The joint families' dimensions as settings (issue 25): each name sets its size, values out of
// range and unknown names are refused naming them, and a design made with other sizes is still
// verified on its jointed plates (and differs from the default one).
#include <gtest/gtest.h>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::BadInput);
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(JointSizes, EveryNamedSizeIsSetAndRangesAreKept) {
  const std::vector<JointSizeSetting> settings = jointSizeSettings();
  ASSERT_GE(settings.size(), 16u);
  for (const JointSizeSetting& setting : settings) {
    JointCutOptions options;
    const double middle = (setting.least + setting.most) / 2;
    EXPECT_NO_THROW(setJointSize(options, setting.name, middle)) << setting.name;
    EXPECT_NE(messageOf([&] { setJointSize(options, setting.name, setting.most * 2 + 1); }).find(setting.name),
              std::string::npos);
  }
  JointCutOptions options;
  setJointSize(options, "dovetail.slope", 0.2);
  EXPECT_EQ(options.dovetail.slope, 0.2);
  setJointSize(options, "stepTenon.width", 0.25);
  EXPECT_EQ(options.stepTenon.width.of(100), 25);
  EXPECT_NE(messageOf([&] { setJointSize(options, "dovetail.angle", 1); }).find("unknown joint size 'dovetail.angle'"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { parsePlateDesignOptionsJson(R"({"jointSizes": {"dovetail": {"slope": "steep"}}})"); })
                .find("jointSizes.dovetail.slope must be a number"),
            std::string::npos);
  EXPECT_EQ(parsePlateDesignOptionsJson(R"({"jointSizes": {"mitreTenon": {"width": 0.25}}})").joints.mitreTenon.width.of(8),
            2);
}

TEST(JointSizes, ADesignWithOtherSizesIsVerifiedAndDiffers) {
  const AssemblyDocument box =
      parseAssemblyText(testing::readFileText(testing::projectPath("examples/plate/mitred_box.json")), "mitred_box.json");
  PlateDesignOptions options;
  options.realization = JointRealization::Milled;
  const PlateDesignResult standard = designPlateJoints(box.plates, box.plateContacts, options);
  setJointSize(options.joints, "mitreTenon.width", 0.2);
  setJointSize(options.joints, "mitreTenon.height", 0.3);
  const PlateDesignResult other = designPlateJoints(box.plates, box.plateContacts, options);
  ASSERT_EQ(standard.status, DesignStatus::Success) << standard.message;
  ASSERT_EQ(other.status, DesignStatus::Success) << other.message;
  const std::string written = plateDesignToJson(box, other);
  EXPECT_NE(written, plateDesignToJson(box, standard));
  CheckOptions check;
  check.method = CheckMethod::Both;
  EXPECT_TRUE(checkPassed(checkDocument(parseJsonDocument(written, "other sizes"), check)));
}

}  // namespace
}  // namespace desia
