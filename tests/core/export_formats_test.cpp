// SPDX-License-Identifier: GPL-3.0-or-later
// The export-format registry (desia/export.h) says what the writers do: every format
// writes every kind of assembly it lists, and refuses the kinds it does not list with BadInput.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "test_support.h"

namespace desia {
namespace {

// One assembly of each kind a user exports: a designed voxel puzzle (the original authors'),
// a plate structure and a designed frame.
const std::map<AssemblyKind, AssemblyDocument>& examplesByKind() {
  static const std::map<AssemblyKind, AssemblyDocument> examples{
      {AssemblyKind::Voxel, testing::loadReference("result_puz/Cube_4x4x4_K9.puz")},
      {AssemblyKind::Plate,
       parseAssemblyText(testing::readFileText(testing::projectPath("examples/plate/table.json")), "table.json")},
      {AssemblyKind::Frame,
       parseAssemblyText(testing::readFileText(testing::projectPath("examples/frame/frame_cube_result.json")),
                         "frame_cube_result.json")},
  };
  return examples;
}

bool lists(const ExportFormatInfo& format, AssemblyKind kind) {
  return std::find(format.kinds.begin(), format.kinds.end(), kind) != format.kinds.end();
}

TEST(ExportFormats, EveryFormatWritesTheKindsItListsAndRefusesTheOthers) {
  for (const ExportFormatInfo& format : exportFormats()) {
    for (const auto& [kind, document] : examplesByKind()) {
      ExportSettings settings;
      settings.mesh.source = settings.sheets.source = assemblyKindName(kind);
      if (lists(format, kind)) {
        const std::vector<std::string> files = exportFiles(document, format, settings);
        ASSERT_FALSE(files.empty()) << format.name << " of a " << assemblyKindName(kind);
        EXPECT_GT(files.front().size(), 100u) << format.name << " of a " << assemblyKindName(kind);
        EXPECT_EQ(files.size() > 1, format.perSheet && files.size() > 1) << format.name;
      } else {
        try {
          exportFiles(document, format, settings);
          ADD_FAILURE() << format.name << " wrote a " << assemblyKindName(kind) << " it does not list";
        } catch (const Error& error) {
          EXPECT_EQ(error.code(), ErrorCode::BadInput) << format.name << ": " << error.what();
        }
      }
    }
  }
}

TEST(ExportFormats, NamesAreUniqueAndUnknownNamesListEveryFormat) {
  std::vector<std::string> names;
  for (const ExportFormatInfo& format : exportFormats()) names.push_back(format.name);
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  EXPECT_EQ(&exportFormatNamed("svg"), &exportFormats()[6]);
  try {
    exportFormatNamed("step");
    FAIL() << "an unknown format was accepted";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::BadInput);
    for (const std::string& name : names) EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << name;
  }
}

TEST(ExportFormats, CutSheetsReadSheetOptionsAndMeshesDoNot) {
  EXPECT_TRUE(exportFormatNamed("svg").perSheet);
  EXPECT_TRUE(formatReads(exportFormatNamed("dxf"), ExportOptionGroup::Sheet));
  EXPECT_FALSE(formatReads(exportFormatNamed("stl"), ExportOptionGroup::Sheet));
  EXPECT_TRUE(formatReads(exportFormatNamed("build-plate-stl"), ExportOptionGroup::Spacing));
  EXPECT_FALSE(formatReads(exportFormatNamed("stl-zip"), ExportOptionGroup::Spacing));
}

}  // namespace
}  // namespace desia
