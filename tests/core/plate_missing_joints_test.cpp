// SPDX-License-Identifier: GPL-3.0-or-later
// When 'auto' falls back to the paper's plan (nothing cut), the plates and edges that got no made
// joint are named with how they meet (issue 26, item 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
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

// The plate ids in a list such as "plates 3, 4, 6 and 7" or "plate 1".
std::set<int> idsIn(const std::string& list) {
  std::set<int> ids;
  for (size_t k = 0; k < list.size();) {
    if (!std::isdigit(static_cast<unsigned char>(list[k]))) {
      ++k;
      continue;
    }
    size_t end = k;
    while (end < list.size() && std::isdigit(static_cast<unsigned char>(list[end]))) ++end;
    ids.insert(std::stoi(list.substr(k, end - k)));
    k = end;
  }
  return ids;
}

// Do the plates of `rest` other than `without` stay in one piece over the contacts (breadth first)?
bool staysInOnePiece(const std::vector<PlateContact>& contacts, std::set<int> rest, int without) {
  rest.erase(without);
  std::set<int> reached{*rest.begin()};
  std::vector<int> queue{*rest.begin()};
  while (!queue.empty()) {
    const int p = queue.back();
    queue.pop_back();
    for (const PlateContact& c : contacts) {
      const int q = c.a == p ? c.b : c.b == p ? c.a : -1;
      if (q >= 0 && rest.count(q) && reached.insert(q).second) queue.push_back(q);
    }
  }
  return reached.size() == rest.size();
}

TEST(PlateMissingJoints, ASearchThatGetsNoFurtherSaysWhyAtItsDeepestNode) {
  // The CABINET with laser-cut joints: the search ends two plates deep (19 nodes).
  const AssemblyDocument cabinet = loadPlateExample("cabinet.json");
  const std::vector<PlateContact> contacts = computePlateContacts(cabinet.plates, {});
  PlateDesignOptions options;
  options.realization = JointRealization::Cut;
  const PlateDesignResult result = designPlateJoints(cabinet.plates, contacts, options);
  ASSERT_EQ(result.status, DesignStatus::NotFound) << result.message;
  const size_t at = result.message.find("(the deepest node: ");
  ASSERT_NE(at, std::string::npos) << result.message;
  const std::string said = result.message.substr(at);
  const size_t takenEnd = said.find(" taken (");
  const size_t leftAt = said.find(" left, ");
  ASSERT_NE(takenEnd, std::string::npos);
  ASSERT_NE(leftAt, std::string::npos);
  std::set<int> taken = idsIn(said.substr(0, takenEnd));
  EXPECT_EQ(static_cast<int>(taken.size()) + 1, result.progress.bestDepth) << said;
  // Every plate left is named once, in one of the clauses.
  std::set<int> named;
  size_t clauses = 0;
  const std::string rest = said.substr(leftAt + 7);
  for (size_t from = 0; from < rest.size();) {
    const size_t end = std::min(rest.find("; ", from), rest.size());
    const std::string clause = rest.substr(from, end - from);
    ASSERT_EQ(clause.find(" more"), std::string::npos) << "every plate listed: " << said;
    const size_t verb = clause.find(clause.find(" are ") != std::string::npos ? " are " : " is ");
    const size_t cut = clause.find(" would ") < verb ? clause.find(" would ") : verb;
    const std::set<int> ids = idsIn(clause.substr(0, cut));
    for (int id : ids) EXPECT_TRUE(named.insert(id).second) << "plate " << id << " named twice: " << said;
    ++clauses;
    // A plate said to be a cut point splits the plates left, by a walk over the contacts.
    if (clause.find("cut point") != std::string::npos) {
      std::set<int> left;
      for (size_t p = 0; p < cabinet.plates.size(); ++p)
        if (!taken.count(cabinet.plates[p].id)) left.insert(static_cast<int>(p));
      for (int id : ids) {
        const auto plate = std::find_if(cabinet.plates.begin(), cabinet.plates.end(), [&](const Plate& q) { return q.id == id; });
        ASSERT_NE(plate, cabinet.plates.end()) << "no plate " << id << ": " << said;
        const int index = static_cast<int>(plate - cabinet.plates.begin());  // contacts name plates by index
        EXPECT_FALSE(staysInOnePiece(contacts, left, index)) << "plate " << id << ": " << said;
      }
    }
    from = end + 2;
  }
  EXPECT_GE(clauses, 1u);
  EXPECT_EQ(named.size() + taken.size(), cabinet.plates.size()) << said;
  for (int id : named) EXPECT_FALSE(taken.count(id)) << said;
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
                                "50 to 50 degrees apart, slanted tenons where a bevelled side lies on a face 60 to 90 "
                                "degrees apart, slanted sliding dovetails along such a side 60 to 90 degrees apart)"),
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
