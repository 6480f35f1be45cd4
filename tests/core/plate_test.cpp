// SPDX-License-Identifier: GPL-3.0-or-later
// Plate structures read from geometry (paper Section 5.2): the contacts found between plates,
// the parts-graph's cut points, every bad input named, and verdicts that do not change when the
// whole design is turned (the contact normals are then computed from turned coordinates).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "analysis/vec3.h"
#include "desia/check.h"
#include "desia/cut_points.h"
#include "desia/error.h"
#include "test_support.h"

namespace desia {
namespace {

AssemblyDocument loadExample(const std::string& name) {
  const std::string path = "examples/plate/" + name;
  return parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
}

// "id-id" pairs of plates in contact, each once.
std::set<std::string> touchingPairs(const Assembly& assembly) {
  std::set<std::string> pairs;
  for (const Contact& c : assembly.contacts) {
    const int a = assembly.parts[c.a].id, b = assembly.parts[c.b].id;
    pairs.insert(std::to_string(std::min(a, b)) + "-" + std::to_string(std::max(a, b)));
  }
  return pairs;
}

TEST(PlateContacts, TheTableTouchesWhereItsBoardsMeet) {
  const AssemblyDocument table = loadExample("table.json");
  ASSERT_EQ(table.kind, AssemblyKind::Plate);
  ASSERT_EQ(table.assembly.partCount(), 6);
  // top on both sides and both aprons; sides hold the aprons and the shelf.
  EXPECT_EQ(touchingPairs(table.assembly), (std::set<std::string>{"1-2", "1-3", "1-4", "1-5", "2-4", "2-5", "2-6", "3-4", "3-5", "3-6"}));
  for (const Contact& c : table.assembly.contacts) {
    EXPECT_NEAR(norm(c.normal), 1.0, 1e-15);
    int axes = 0;
    for (double x : c.normal) axes += std::abs(x) == 1.0 ? 1 : 0;
    EXPECT_EQ(axes, 1) << "orthogonal boards give axis normals";
    EXPECT_GT(c.area, 0);
  }
  // The top rests on the left side: the contact from the top (part 1) to the side points down.
  for (const Contact& c : table.assembly.contacts) {
    if (table.assembly.parts[c.a].id == 1 && table.assembly.parts[c.b].id == 2) {
      EXPECT_EQ(c.normal, (Vec3{0, -1, 0}));
      EXPECT_NEAR(c.area, 18.0 * 600.0, 1e-6);
    }
  }
}

TEST(PlateContacts, MitredEdgesGiveFortyFiveDegreeContacts) {
  const AssemblyDocument box = loadExample("mitred_box.json");
  ASSERT_EQ(box.assembly.partCount(), 6);
  EXPECT_EQ(touchingPairs(box.assembly).size(), 12u) << "each of the cube's 12 edges is one mitre";
  for (const Contact& c : box.assembly.contacts) {
    int halves = 0;
    for (double x : c.normal) halves += std::abs(std::abs(x) - std::sqrt(0.5)) < 1e-12 ? 1 : 0;
    EXPECT_EQ(halves, 2) << "a 45-degree mitre";
  }
  // Non-orthogonal contacts: the two tests agree that nothing holds the plain box together.
  CheckOptions options;
  options.method = CheckMethod::Both;
  const CheckReport report = checkAssembly(box, options);
  EXPECT_EQ(report.graphResult->verdict, Verdict::NotInterlocking);
  EXPECT_EQ(report.inequalityResult->verdict, Verdict::NotInterlocking);
}

TEST(PlateCutPoints, TheChairsSeatIsACutPointUntilBarsBypassIt) {
  const AssemblyDocument chair = loadExample("chair_cut_point.json");
  ASSERT_EQ(chair.plateCutPoints.size(), 1u);
  EXPECT_EQ(chair.assembly.parts[chair.plateCutPoints[0]].id, 5);
  const std::string text = checkReportToText(chair, checkAssembly(chair));
  EXPECT_NE(text.find("cut points of the parts-graph: plate 5"), std::string::npos) << text;
  EXPECT_TRUE(loadExample("chair_repaired.json").plateCutPoints.empty());
  EXPECT_TRUE(loadExample("table.json").plateCutPoints.empty());
}

TEST(PlateCutPoints, IterativeSearchFindsArticulationPoints) {
  // 0-1-2-3 path with a triangle 3-4-5: cut points 1, 2, 3.
  EXPECT_EQ(findCutPoints(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 3}}), (std::vector<int>{1, 2, 3}));
  EXPECT_TRUE(findCutPoints(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}).empty());
  // A 200,000-node path: every inner node is a cut point, and no recursion overflows the stack.
  std::vector<std::pair<int, int>> path;
  for (int i = 0; i + 1 < 200000; ++i) path.push_back({i, i + 1});
  EXPECT_EQ(findCutPoints(200000, path).size(), 199998u);
}

std::string plateDocument(const std::string& platesJson) {
  return R"({"kind":"plate","plates":)" + platesJson + "}";
}

void ExpectBadPlates(const std::string& platesJson, const std::string& message) {
  try {
    parseAssemblyText(plateDocument(platesJson), "design.json");
    ADD_FAILURE() << "accepted: " << platesJson;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("design.json", 0), 0u) << e.what();
  }
}

const char* kSquare = "[[0,0,0],[100,0,0],[100,100,0],[0,100,0]]";

TEST(PlateInput, BadPlatesAreNamedWithTheProblem) {
  ExpectBadPlates(std::string(R"([{"id":1,"outline":)") + kSquare + R"(,"thickness":0}])",
                  "plates[0] (plate 1).thickness: must be positive");
  ExpectBadPlates(std::string(R"([{"id":1,"outline":)") + kSquare + R"(,"thickness":-3}])", "must be positive, found -3");
  ExpectBadPlates(R"([{"id":1,"outline":[[0,0,0],[100,0,0],[100,100,3],[0,100,0]],"thickness":10}])",
                  "plate 1: its first face is not planar: vertex 1 is 0.75 mm off");
  ExpectBadPlates(R"([{"id":4,"outline":[[0,0,0],[100,100,0],[100,0,0],[0,60,0]],"thickness":10}])",
                  "plate 4: its outline crosses itself: edge 1-2 meets edge 3-4");
  ExpectBadPlates(R"([{"id":2,"faces":[[[0,0,0],[100,0,0],[100,100,0]],[[0,0,10],[100,0,10],[100,100,10],[0,100,10]]]}])",
                  "the faces do not match: 3 and 4 vertices");
  ExpectBadPlates(R"([{"id":3,"faces":[[[0,0,0],[100,0,0],[100,100,0],[0,100,0]],[[0,0,10],[100,0,12],[100,100,12],[0,100,10]]]}])",
                  "plate 3: its faces are not parallel");
  ExpectBadPlates(R"([{"id":3,"faces":[[[0,0,0],[100,0,0],[100,100,0],[0,100,0]],[[0,0,10],[0,100,10],[100,100,10],[100,0,10]]]}])",
                  "plate 3: its faces do not match: the side between vertices");
  ExpectBadPlates(std::string(R"([{"id":1,"outline":)") + kSquare + R"(,"thickness":10},{"id":1,"outline":)" + kSquare +
                      R"(,"thickness":10}])",
                  "plates[1].id: duplicate plate id 1");
  // Two boards that do not touch, and a third far away.
  ExpectBadPlates(std::string(R"([{"id":1,"outline":)") + kSquare +
                      R"(,"thickness":10},{"id":2,"outline":[[0,0,10],[100,0,10],[100,100,10],[0,100,10]],"thickness":10},)" +
                      R"({"id":3,"outline":[[500,0,0],[600,0,0],[600,100,0],[500,100,0]],"thickness":10}])",
                  "plate 3 touches no other plate");
  ExpectBadPlates(std::string(R"([{"id":1,"outline":)") + kSquare +
                      R"(,"thickness":10},{"id":2,"outline":[[0,0,10],[100,0,10],[100,100,10],[0,100,10]],"thickness":10},)" +
                      R"({"id":3,"outline":[[500,0,0],[600,0,0],[600,100,0],[500,100,0]],"thickness":10},)" +
                      R"({"id":4,"outline":[[500,0,10],[600,0,10],[600,100,10],[500,100,10]],"thickness":10}])",
                  "the design falls apart into 2 groups that do not touch: plates 1, 2; plates 3, 4");
  ExpectBadPlates(R"({"id":1})", "plates: expected an array of plates");
  ExpectBadPlates(R"([{"id":1,"outline":[[0,0,0],[1,0,0]],"thickness":1}])", "a face needs at least 3 vertices");
  ExpectBadPlates(R"([{"id":1,"outline":[[0,0,0],[1e300,0,0],[0,1,0]],"thickness":1}])", "is not a finite number of millimetres");
}

TEST(PlateInput, StackedBoardsTouchAndAClosingVertexIsDropped) {
  const AssemblyDocument document = parseAssemblyText(
      plateDocument(R"([{"id":1,"outline":[[0,0,0],[100,0,0],[100,100,0],[0,100,0],[0,0,0]],"thickness":10},)"
                    R"({"id":2,"outline":[[50,50,10],[150,50,10],[150,150,10],[50,150,10]],"thickness":5,)"
                    R"("holes":[[[60,60,10],[60,70,10],[70,70,10],[70,60,10]]]}])"),
      "stack.json");
  ASSERT_EQ(document.plates[0].bottom[0].size(), 4u);
  ASSERT_EQ(document.assembly.contacts.size(), 1u);
  const Contact& c = document.assembly.contacts[0];
  EXPECT_EQ(c.normal, (Vec3{0, 0, 1}));
  EXPECT_NEAR(c.area, 50.0 * 50.0 - 10.0 * 10.0, 1e-6) << "the overlap minus the hole";
}

TEST(PlateInput, DocumentsRoundTripThroughTheWriter) {
  for (const char* name : {"table.json", "chair_cut_point.json", "mitred_box.json"}) {
    const AssemblyDocument document = loadExample(name);
    const AssemblyDocument reread = parseJsonDocument(documentToJson(document), name);
    ASSERT_EQ(reread.plates.size(), document.plates.size()) << name;
    EXPECT_EQ(touchingPairs(reread.assembly), touchingPairs(document.assembly)) << name;
    EXPECT_EQ(reread.plateCutPoints, document.plateCutPoints) << name;
  }
}

// Rotations about several axes computed with cos/sin, like a modelling tool's export.
std::array<Vec3, 3> rotation(double ax, double ay, double az) {
  auto mul = [](const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    std::array<Vec3, 3> r{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    }
    return r;
  };
  const std::array<Vec3, 3> x{{{1, 0, 0}, {0, std::cos(ax), -std::sin(ax)}, {0, std::sin(ax), std::cos(ax)}}};
  const std::array<Vec3, 3> y{{{std::cos(ay), 0, std::sin(ay)}, {0, 1, 0}, {-std::sin(ay), 0, std::cos(ay)}}};
  const std::array<Vec3, 3> z{{{std::cos(az), -std::sin(az), 0}, {std::sin(az), std::cos(az), 0}, {0, 0, 1}}};
  return mul(z, mul(y, x));
}

TEST(PlateRobustness, VerdictsAndContactsSurviveTurningTheWholeDesign) {
  const double q = M_PI / 2;
  const std::vector<std::array<double, 3>> angles{{q, 0, 0}, {0, q, q}, {2 * q, 0, 3 * q}, {q, 2 * q, q},
                                                  {0.3, 1.1, -0.7}, {2.0, -0.4, 0.9}, {-1.3, 0.2, 2.6}};
  for (const char* name : {"table.json", "chair_cut_point.json", "chair_repaired.json", "mitred_box.json"}) {
    const AssemblyDocument original = loadExample(name);
    CheckOptions options;
    options.method = CheckMethod::Both;
    const CheckReport base = checkAssembly(original, options);
    for (const auto& [ax, ay, az] : angles) {
      const std::array<Vec3, 3> r = rotation(ax, ay, az);
      AssemblyDocument turned = original;
      for (Plate& plate : turned.plates) {
        for (auto* face : {&plate.bottom, &plate.top}) {
          for (Loop& loop : *face) {
            for (Vec3& p : loop) p = {dot(r[0], p), dot(r[1], p), dot(r[2], p)};
          }
        }
      }
      const std::string context = std::string(name) + " turned by " + std::to_string(ax) + ", " + std::to_string(ay) + ", " + std::to_string(az);
      const AssemblyDocument reread = parseJsonDocument(documentToJson(turned), context);
      EXPECT_EQ(touchingPairs(reread.assembly), touchingPairs(original.assembly)) << context;
      EXPECT_EQ(reread.plateCutPoints, original.plateCutPoints) << context;
      const CheckReport report = checkAssembly(reread, options);
      EXPECT_EQ(report.graphResult->verdict, base.graphResult->verdict) << context;
      EXPECT_EQ(report.inequalityResult->verdict, base.inequalityResult->verdict) << context;
      EXPECT_EQ(report.inequalityResult->key, base.inequalityResult->key) << context;
    }
  }
}

}  // namespace
}  // namespace desia
