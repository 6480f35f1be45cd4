// SPDX-License-Identifier: GPL-3.0-or-later
// Cut files of plate structures (core/io/plate/cut_sheets.cpp), read back: true sizes in mm, the kerf and
// the clearance where they belong, every plate on a sheet, clear errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "desia/design_io.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

struct Box2 {
  double minX = HUGE_VAL, minY = HUGE_VAL, maxX = -HUGE_VAL, maxY = -HUGE_VAL;
  double width() const { return maxX - minX; }
  double height() const { return maxY - minY; }
};

Box2 boxOfPath(const std::string& d) {
  Box2 box;
  static const std::regex point("[ML](-?[0-9.]+) (-?[0-9.]+)");
  for (auto it = std::sregex_iterator(d.begin(), d.end(), point); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    box = {std::min(box.minX, x), std::min(box.minY, y), std::max(box.maxX, x), std::max(box.maxY, y)};
  }
  return box;
}

// The paths of each plate group: class ("outer" / "inner") and bounding box.
std::map<int, std::vector<std::pair<std::string, Box2>>> pathsByPlate(const std::string& svg) {
  std::map<int, std::vector<std::pair<std::string, Box2>>> plates;
  static const std::regex group("<g id=\"plate-([0-9]+)\">([^]*?)</g>");
  static const std::regex path("<path class=\"(outer|inner)\"[^>]* d=\"([^\"]+)\"");
  for (auto g = std::sregex_iterator(svg.begin(), svg.end(), group); g != std::sregex_iterator(); ++g) {
    const std::string body = (*g)[2];
    for (auto p = std::sregex_iterator(body.begin(), body.end(), path); p != std::sregex_iterator(); ++p) {
      plates[std::stoi((*g)[1])].push_back({(*p)[1], boxOfPath((*p)[2])});
    }
  }
  return plates;
}

std::string designedTable(double clearance) {
  const std::string path = "examples/plate/table.json";
  const AssemblyDocument table = parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
  PlateDesignOptions options;
  options.joints.clearance = clearance;
  const PlateDesignResult result = designPlateJoints(table.plates, computePlateContacts(table.plates, {}), options);
  EXPECT_EQ(result.status, DesignStatus::Success) << result.message;
  return plateDesignToJson(table, result);
}

TEST(CutSheets, TheTableAtTrueSizeWithKerfAndClearance) {
  const AssemblyDocument plan = parseJsonDocument(designedTable(0.2), "table plan");
  CutSheetOptions options;
  options.kerf = 0.15;
  const std::vector<std::string> sheets = plateCutSheets(plan, CutFileFormat::Svg, options);
  ASSERT_EQ(sheets.size(), 1u);
  const std::string& svg = sheets[0];
  EXPECT_NE(svg.find("mm\" height=\""), std::string::npos) << "width and height in mm";
  EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos);
  const auto plates = pathsByPlate(svg);
  ASSERT_EQ(plates.size(), 6u);
  // Plate 1 is the key: the top, 1050 x 650 mm, with 8 mortises.
  const auto& top = plates.at(1);
  ASSERT_EQ(top.size(), 9u);
  EXPECT_EQ(top[0].first, "outer");
  EXPECT_NEAR(top[0].second.width(), 1050 + 0.15, 1e-3) << "the outline grows by half the kerf on each side";
  EXPECT_NEAR(top[0].second.height(), 650 + 0.15, 1e-3);
  // Every mortise in the top is the tenon of an 18 mm board plus the 0.2 mm clearance, less the kerf.
  for (size_t k = 1; k < top.size(); ++k) {
    EXPECT_EQ(top[k].first, "inner");
    const double across = std::min(top[k].second.width(), top[k].second.height());
    EXPECT_NEAR(across, 18 + 0.2 - 0.15, 1e-3);
  }
  // The tenons on the sides' top edges: 18 mm out of the board, 120 mm along it (600 / 5), plus the kerf.
  for (int side : {2, 3, 4, 5, 6}) {
    ASSERT_EQ(plates.count(side), 1u);
    EXPECT_EQ(plates.at(side)[0].first, "outer");
  }
  // Every group has its id engraved.
  for (int id = 1; id <= 6; ++id) {
    EXPECT_NE(svg.find(">" + std::to_string(id) + "</text>"), std::string::npos) << id;
  }
  EXPECT_NE(svg.find("stroke:#ff0000"), std::string::npos);
  EXPECT_NE(svg.find("stroke:#0000ff"), std::string::npos);
  EXPECT_NE(svg.find("stroke:#000000"), std::string::npos);
  EXPECT_EQ(plateCutSheets(plan, CutFileFormat::Svg, options), sheets) << "deterministic";
}

TEST(CutSheets, TenonsFitTheirMortisesLessTheClearance) {
  // Without kerf: a tenon's width and the mortise's length along the joint differ by the clearance.
  const AssemblyDocument plan = parseJsonDocument(designedTable(0.3), "table plan");
  const auto plates = pathsByPlate(plateCutSheets(plan, CutFileFormat::Svg, {})[0]);
  std::vector<double> mortiseLengths;
  for (const auto& [id, paths] : plates) {
    for (const auto& [kind, box] : paths) {
      if (kind == "inner") mortiseLengths.push_back(std::max(box.width(), box.height()));
    }
  }
  ASSERT_FALSE(mortiseLengths.empty());
  // Tenon widths of the table: 120 (sides, 600 / 5), 192.8 (aprons into the top, 964 / 5), 30
  // (aprons into the sides, 150 / 5), 104 (shelf, 520 / 5).
  for (double length : mortiseLengths) {
    bool matched = false;
    for (double tenon : {120.0, 192.8, 30.0, 104.0}) matched = matched || std::abs(length - (tenon + 0.3)) < 1e-3;
    EXPECT_TRUE(matched) << length;
  }
}

TEST(CutSheets, SheetsNestAndSayWhatDoesNotFit) {
  const AssemblyDocument plan = parseJsonDocument(designedTable(0), "table plan");
  CutSheetOptions options;
  parseSheetSize("1200x800", &options);
  const std::vector<std::string> sheets = plateCutSheets(plan, CutFileFormat::Svg, options);
  EXPECT_GT(sheets.size(), 1u);
  int groups = 0;
  for (const std::string& sheet : sheets) {
    EXPECT_NE(sheet.find("width=\"1200mm\" height=\"800mm\""), std::string::npos);
    groups += static_cast<int>(pathsByPlate(sheet).size());
    for (const auto& [id, paths] : pathsByPlate(sheet)) {
      for (const auto& [kind, box] : paths) {
        EXPECT_GE(box.minX, 5 - 1e-9);
        EXPECT_LE(box.maxX, 1195 + 1e-9);
        EXPECT_GE(box.minY, 5 - 1e-9);
        EXPECT_LE(box.maxY, 795 + 1e-9);
      }
    }
  }
  EXPECT_EQ(groups, 6) << "every plate once";
  CutSheetOptions small;
  parseSheetSize("600x400", &small);
  try {
    plateCutSheets(plan, CutFileFormat::Svg, small);
    ADD_FAILURE() << "the 1050 mm top fits no 600 x 400 sheet";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("plate 1 (1050 x 650 mm) does not fit on a 600 x 400 mm sheet"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parseSheetSize("600", &small), Error);
  EXPECT_THROW(parseSheetSize("600x-4", &small), Error);
  EXPECT_THROW(parseCutFileFormat("pdf"), Error);
}

TEST(CutSheets, DxfInMillimetresWithOneLayerPerKindOfLine) {
  const AssemblyDocument plan = parseJsonDocument(designedTable(0), "table plan");
  const std::string dxf = plateCutSheets(plan, CutFileFormat::Dxf, {})[0];
  EXPECT_NE(dxf.find("$INSUNITS\n70\n4\n"), std::string::npos);
  for (const char* layer : {"CUT_OUTER", "CUT_INNER", "ENGRAVE"})
    EXPECT_NE(dxf.find(std::string("2\n") + layer + "\n"), std::string::npos);
  // One closed polyline per outline and mortise: 6 outlines, 8 mortises in the top, 2 + 2 in each side.
  size_t polylines = 0;
  for (size_t at = dxf.find("POLYLINE"); at != std::string::npos; at = dxf.find("POLYLINE", at + 1)) ++polylines;
  EXPECT_EQ(polylines, 6u + 8u + 6u + 6u);
  EXPECT_EQ(dxf.substr(dxf.size() - 6), "0\nEOF\n");
}

}  // namespace
}  // namespace desia

namespace desia {
namespace {

// A kerf wider than an opening would erase it (the cut closes it): refused, naming the plate,
// about how wide the opening is and the kerf. Before, every such mortise was silently dropped.
TEST(CutSheets, AKerfWiderThanAnOpeningIsRefused) {
  const AssemblyDocument plan = parseAssemblyText(R"({"kind":"plate","plates":[
    {"id":1,"outline":[[0,0,0],[100,0,0],[100,100,0],[0,100,0]],"thickness":10,
     "holes":[[[40,30,0],[43,30,0],[43,70,0],[40,70,0]]]},
    {"id":2,"outline":[[0,0,10],[100,0,10],[100,100,10],[0,100,10]],"thickness":10}]})",
                                                  "slot.json");
  CutSheetOptions options;
  options.source = "slot.json";
  options.kerf = 2.8;
  EXPECT_NO_THROW(plateCutSheets(plan, CutFileFormat::Svg, options));
  options.kerf = 3.2;
  try {
    plateCutSheets(plan, CutFileFormat::Svg, options);
    ADD_FAILURE() << "a 3 mm slot cut with a 3.2 mm kerf";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::BadInput);
    const std::string what = error.what();
    EXPECT_NE(what.find("slot.json: plate 1: an opening about 2.7"), std::string::npos) << what;
    EXPECT_NE(what.find("narrower than the kerf (3.2 mm)"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace desia
