// SPDX-License-Identifier: GPL-3.0-or-later
// Squaring a plan's ways out and its jointed plates' contacts to each other (plan_squaring.h):
// what rounding a design to a micrometre turns by 1e-9 rad is made square, a real block is kept.
#include "plate/plan_squaring.h"

#include <gtest/gtest.h>

#include "analysis/part_motion.h"
#include "analysis/vec3.h"

namespace desia {
namespace {

PlateContact faceContact(int a, int b, const Vec3& normal) {
  PlateContact contact;
  contact.a = a;
  contact.b = b;
  contact.normal = normalized(normal);
  contact.area = 100;
  return contact;
}

// Plates 0 and 1 leave one after the other along the same way out (+x), each sliding along a face
// of plate 2 that stays; rounding turned plate 0's face by +5e-9 rad and plate 1's by -5e-9 rad.
struct TwoSlidesAlongOneVector {
  std::vector<PlateContact> contacts;
  std::vector<int> position{0, 1, 2};
  std::vector<Part> parts{{1, "first"}, {2, "second"}, {3, "stays"}};
  std::vector<Vec3> directions{{1, 0, 0}, {1, 0, 0}};
  explicit TwoSlidesAlongOneVector(double secondFaceTurn = -5e-9) {
    contacts.push_back(faceContact(0, 2, {5e-9, 1, 0}));
    contacts.push_back(faceContact(1, 2, {secondFaceTurn, 1, 0}));
  }
};

bool leavesInOrder(const Assembly& assembly, const std::vector<Vec3>& directions) {
  std::vector<bool> present(assembly.parts.size(), true);
  for (size_t k = 0; k < directions.size(); ++k) {
    if (!isPartFreeAlong(assembly, &present, static_cast<int>(k), directions[k])) return false;
    present[k] = false;
  }
  return true;
}

TEST(PlanSquaring, PlatesLeavingAlongOneVectorStayOnOneVector) {
  // Squared plate by plate, the two ways out came apart by 1e-8 rad; plate 1's face, squared to
  // plate 0's way out, then blocked plate 1's own by 1e-8 (the LIZARD's plates 35 and 36 on plate 1).
  TwoSlidesAlongOneVector plan;
  std::vector<Vec3> directions = plan.directions;
  const Assembly assembly = jointedAssembly(plan.contacts, plan.position, plan.parts, &directions);
  EXPECT_EQ(directions[0][0], directions[1][0]);
  EXPECT_EQ(directions[0][1], directions[1][1]);
  EXPECT_EQ(directions[0][2], directions[1][2]);
  EXPECT_NEAR(directions[0][0], 1.0, 1e-12);  // turned by nanoradians only
  for (const Contact& contact : assembly.contacts) EXPECT_LT(std::abs(dot(contact.normal, directions[0])), 1e-15);
  EXPECT_TRUE(leavesInOrder(assembly, directions));
}

TEST(PlanSquaring, EachPlateAloneIsSquaredToItsOwnFaces) {
  TwoSlidesAlongOneVector plan;
  std::vector<Vec3> directions{{1, 0, 0}, normalized({1, 0, 1e-3})};  // two ways out
  const Assembly assembly = jointedAssembly(plan.contacts, plan.position, plan.parts, &directions);
  EXPECT_LT(std::abs(dot(directions[0], assembly.contacts[0].normal)), 1e-15);
  EXPECT_LT(std::abs(dot(directions[1], assembly.contacts[1].normal)), 1e-15);
  EXPECT_TRUE(leavesInOrder(assembly, directions));
}

TEST(PlanSquaring, AFaceTurnedByMoreThanAMicroradianStillBlocks) {
  // Plate 1's face turned by 1e-4 rad into its way out is a real block: nothing is squared to it.
  TwoSlidesAlongOneVector plan(1e-4);
  std::vector<Vec3> directions = plan.directions;
  const Assembly assembly = jointedAssembly(plan.contacts, plan.position, plan.parts, &directions);
  EXPECT_GT(dot(directions[1], assembly.contacts[1].normal), 1e-5);
  EXPECT_FALSE(leavesInOrder(assembly, directions));
}

}  // namespace
}  // namespace desia

namespace desia {
namespace {

TEST(PlanSquaring, AFaceIsSquaredToTheWaysOutFurthestApartFirst) {
  // A horizontal face and three ways out nearly in its plane: two 0.09 rad apart, one of them off
  // the plane by 5e-9 (rounding), and a third at 70 degrees. Taken in order, the first two span a
  // plane tilted by 5e-8 and the face squared to it blocked the third way out (the LIZARD's plate
  // 31 against plate 32); taken furthest apart first, the face is square to the plane to rounding.
  const std::vector<Vec3> directions{normalized({1, 0, 0}), normalized({std::cos(0.09), std::sin(0.09), -5e-9}),
                                     normalized({std::cos(1.2), -std::sin(1.2), 0})};
  const Vec3 face = squaredToPlan(normalized({3e-9, -2e-8, -1}), directions);
  EXPECT_LT(std::abs(dot(face, directions[0])), 1e-15);
  EXPECT_LT(std::abs(dot(face, directions[2])), 1e-15);
  EXPECT_LT(std::abs(dot(face, directions[1])), 6e-9);  // the rounding of that way out stays its own
}

TEST(PlanSquaring, AFaceIsSquareToTheWayOutOfThePlateThatLeavesItFirst) {
  // Plates 0 and 1 leave first along horizontal ways rounded out of the plane by -2e-9 and 1e-9;
  // plate 2 leaves third, sliding along a face of plate 3 that stays, a face rounding turned by
  // 6e-9 rad. Squared to the plane the two furthest apart span (plates 0 and 1's ways), the face was
  // left 5e-9 off square to plate 2's way, past the blocking tolerance: the LIZARD with step tenons
  // from 30 degrees verified in memory and failed once written. Squared to plate 2's way before
  // the others, it lets plate 2 slide.
  const std::vector<PlateContact> contacts{faceContact(2, 3, {-6e-9, 0, 1})};
  std::vector<Vec3> directions{normalized({1, 0, -2e-9}), normalized({0, 1, 1e-9}), normalized({0.73, 0.68, 0})};
  const std::vector<Part> parts{{1, "first"}, {2, "second"}, {3, "third"}, {4, "stays"}};
  const Assembly assembly = jointedAssembly(contacts, {0, 1, 2, 3}, parts, &directions);
  EXPECT_TRUE(leavesInOrder(assembly, directions));
  EXPECT_LT(std::abs(dot(assembly.contacts[0].normal, directions[2])), 1e-15);
  // A real block (the face tilted by 1e-4 rad against the way out) is kept.
  const std::vector<PlateContact> blocking{faceContact(2, 3, {0, -1e-4, 1})};
  std::vector<Vec3> ways{normalized({1, 0, 0}), normalized({0.6, 0.8, 0}), normalized({0, -1, 0})};
  EXPECT_FALSE(leavesInOrder(jointedAssembly(blocking, {0, 1, 2, 3}, parts, &ways), ways));
}

TEST(PlanSquaring, AFaceNearlySquareToThreeIndependentWaysOutIsLeftAsItIs) {
  // Nothing is square to three independent vectors: the face is kept (a real block is the tests'
  // to judge), not replaced by the noise left after taking out all three.
  const Vec3 face = normalized({1e-7, 2e-7, 1});
  // The third is out of the plane of the first two by 1.1e-6, and within 1e-6 of square to the face.
  const std::vector<Vec3> directions{{1, 0, 0}, {0, 1, 0}, normalized({std::sqrt(0.5), std::sqrt(0.5), -1.1e-6})};
  for (const Vec3& d : directions) ASSERT_LT(std::abs(dot(face, d)), 1e-6);
  const Vec3 squared = squaredToPlan(face, directions);
  EXPECT_NEAR(dot(squared, face), 1, 1e-12);
}

}  // namespace
}  // namespace desia
