// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "test_support.h"

namespace desia {
namespace {

TEST(JsonDocument, VoxelDocumentRoundTripsThroughJson) {
  const AssemblyDocument original = testing::loadReference("result_puz/Cube_4x4x4_K9.puz");
  const std::string json = documentToJson(original);
  const AssemblyDocument reread = parseAssemblyText(json, "k9.json");
  EXPECT_EQ(reread.kind, AssemblyKind::Voxel);
  EXPECT_EQ(reread.voxels.labels(), original.voxels.labels());
  EXPECT_EQ(documentToJson(reread), json);
  const CheckReport report = checkAssembly(reread);
  testing::ExpectInterlocking(reread, report.result, 1, {"-z"});
}

TEST(JsonDocument, ContactDocumentKeepsIdsNormalsAndGeometry) {
  const std::string text = R"({
    "format": "desia-assembly", "version": 1, "kind": "frame", "name": "three beams",
    "parts": [{"id": 10, "name": "base"}, {"id": 20}, {"id": 30}],
    "contacts": [{"a": 10, "b": 20, "normal": [0, 0, 2]}, {"a": 20, "b": 30, "normal": [1, 0, 0], "area": 0.5}],
    "frame": {"joints": [[0, 0, 0], [1, 0, 0]], "beams": [[0, 1]]}
  })";
  const AssemblyDocument document = parseJsonDocument(text, "frame.json");
  EXPECT_EQ(document.kind, AssemblyKind::Frame);
  EXPECT_EQ(document.name, "three beams");
  ASSERT_EQ(document.assembly.partCount(), 3);
  EXPECT_EQ(document.assembly.parts[0].name, "base");
  ASSERT_EQ(document.assembly.contacts.size(), 2u);
  EXPECT_EQ(document.assembly.contacts[0].normal, (Vec3{0, 0, 1}));  // normalized
  EXPECT_EQ(document.assembly.contacts[1].a, 1);
  EXPECT_EQ(document.assembly.contacts[1].area, 0.5);
  const AssemblyDocument reread = parseJsonDocument(documentToJson(document), "again.json");
  EXPECT_FALSE(reread.frame.has_value());  // a frame given by its contacts carries no geometry
  EXPECT_EQ(documentToJson(reread), documentToJson(document));
}

struct BadJson {
  const char* name;
  std::string text;
  std::string expected;
};

// Readable test names in gtest output instead of a byte dump.
void PrintTo(const BadJson& value, std::ostream* out) { *out << value.name; }

class BadJsonInput : public ::testing::TestWithParam<BadJson> {};

TEST_P(BadJsonInput, IsRejectedWithPathAndReason) {
  try {
    parseAssemblyText(GetParam().text, "bad.json");
    FAIL() << "accepted: " << GetParam().name;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Desia, BadJsonInput,
    ::testing::Values(
        BadJson{"truncated", "{\n  \"kind\": \"voxel\",\n", "bad.json:3:1: malformed JSON"},
        BadJson{"numberOverflow", R"({"kind": "contacts", "parts": [{"id": 1e3081}]})", "bad.json: malformed JSON: number overflow parsing '1e3081'"},
        BadJson{"notAnObject", "[1, 2]", "bad.json: the JSON document must be an object"},
        BadJson{"missingKind", "{}", "bad.json: missing field 'kind'"},
        BadJson{"unknownKind", R"({"kind": "lego"})", "bad.json: kind: expected \"voxel\", \"plate\", \"frame\" or \"contacts\", found \"lego\""},
        BadJson{"wrongFormat", R"({"format": "x", "kind": "voxel"})", "bad.json: format: expected \"desia-assembly\""},
        BadJson{"futureVersion", R"({"version": 2, "kind": "voxel"})", "bad.json: version: unsupported version 2"},
        BadJson{"labelCount", R"({"kind": "voxel", "voxel": {"size": [2, 1, 1], "labels": [1]}})", "voxel.labels: has 1 values, but size 2 x 1 x 1 needs 2"},
        BadJson{"labelType", R"({"kind": "voxel", "voxel": {"size": [2, 1, 1], "labels": [1, "a"]}})", "voxel.labels[1]: expected an integer, found \"a\""},
        BadJson{"negativeSize", R"({"kind": "voxel", "voxel": {"size": [2, -1, 1], "labels": []}})", "voxel.size[1]: -1 is out of range"},
        BadJson{"unknownPart", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 3, "normal": [1, 0, 0]}]})", "contacts[0].b: part 3 is not in 'parts'"},
        BadJson{"zeroNormal", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 2, "normal": [0, 0, 0]}]})", "contacts[0].normal: is the zero vector"},
        BadJson{"selfContact", R"({"kind": "contacts", "parts": [{"id": 1}], "contacts": [{"a": 1, "b": 1, "normal": [1, 0, 0]}]})", "contacts[0]: a part cannot touch itself"},
        BadJson{"duplicateId", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 1}], "contacts": []})", "parts[1].id: duplicate part id 1"},
        BadJson{"noParts", R"({"kind": "plate", "parts": [], "contacts": []})", "parts: the assembly is empty"},
        // Contacts of a well-formed shape are packed as they are parsed, the others stay objects:
        // both are checked in one order and named alike.
        BadJson{"zeroArea", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 2, "normal": [1, 0, 0], "area": 0}]})", "contacts[0].area: expected a positive number"},
        BadJson{"textArea", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 2, "normal": [1, 0, 0], "area": "big"}]})", "contacts[0].area: expected a positive number"},
        BadJson{"idZero", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 0, "b": 2, "normal": [1, 0, 0]}]})", "contacts[0].a: 0 is out of range"},
        BadJson{"shortNormal", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 2, "normal": [1, 0]}]})", "contacts[0].normal: expected [nx, ny, nz]"},
        BadJson{"secondContactUnknownPart", R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}], "contacts": [{"a": 1, "b": 2, "normal": [1, 0, 0]}, {"a": 7, "b": 2, "normal": [1, 0, 0], "note": "x"}]})", "contacts[1].a: part 7 is not in 'parts'"}),
    [](const auto& info) { return std::string(info.param.name); });

// The reader that lets its text go once parsed (a moved string) reads what the other reads: a plate
// design, a plate result with its geometry sections, a voxel .puz and a bad document's message.
TEST(JsonDocument, ReadingAMovedTextGivesTheSameDocument) {
  for (const char* path : {"examples/plate/table.json", "tests/golden/cases/plate/bench_2_bays-cut-s1/result.json",
                           "tests/golden/cases/plate/bench_2_bays-planned-s1/result.json",
                           "examples/voxel/Cube_4x4x4_K9.puz"}) {
    const std::string text = testing::readFileText(testing::projectPath(path));
    const AssemblyDocument kept = parseAssemblyText(text, path);
    const AssemblyDocument moved = parseAssemblyText(std::string(text), path);
    EXPECT_EQ(documentToJson(moved), documentToJson(kept)) << path;
    EXPECT_EQ(moved.plateResult.has_value(), kept.plateResult.has_value()) << path;
  }
  const std::string bad = "{\"kind\": \"plate\", \"plates\": [{\"id\": 1, \"thickness\": -2}]}";
  std::string keptMessage, movedMessage;
  try {
    parseAssemblyText(bad, "bad.json");
  } catch (const Error& error) {
    keptMessage = error.what();
  }
  try {
    parseAssemblyText(std::string(bad), "bad.json");
  } catch (const Error& error) {
    movedMessage = error.what();
  }
  EXPECT_NE(keptMessage, "");
  EXPECT_EQ(movedMessage, keptMessage);
}

// Packed on parsing or not (an extra key keeps a contact an object), contacts read the same.
// A plate result's plan is held typed (no JSON carried verbatim): its removal, joints, clearance and
// fabrication plates are read, written back, and the document written checks as the file does.
TEST(JsonDocument, APlateResultKeepsItsPlanWhenWrittenAgain) {
  const char* path = "tests/golden/cases/plate/table-cut-s1-clearance/result.json";
  const nlohmann::json file = nlohmann::json::parse(testing::readFileText(testing::projectPath(path)));
  const AssemblyDocument document = parseAssemblyText(file.dump(), path);
  ASSERT_TRUE(document.plateResult.has_value());
  const PlateResultPlan& plan = *document.plateResult;
  ASSERT_EQ(plan.joints.size(), file["joints"].size());
  for (size_t k = 0; k < plan.joints.size(); ++k) {
    EXPECT_EQ(plan.joints[k].mover, file["joints"][k]["mover"].get<int>());
    EXPECT_EQ(plan.joints[k].other, file["joints"][k]["other"].get<int>());
    EXPECT_EQ(plan.joints[k].type, file["joints"][k]["type"].get<std::string>());
  }
  EXPECT_EQ(plan.clearance, file["clearance"].get<double>());
  const nlohmann::json written = nlohmann::json::parse(documentToJson(document));
  for (const char* section : {"removal", "joints", "jointGeometry", "clearance"}) {
    EXPECT_EQ(written[section], file[section]) << section;
  }
  EXPECT_EQ(written["fabricationPlates"].size(), file["fabricationPlates"].size());
  const AssemblyDocument reread = parseJsonDocument(written.dump(), "again.json");
  const nlohmann::json again = nlohmann::json::parse(documentToJson(reread));
  for (const char* section : {"removal", "joints", "jointGeometry", "clearance"}) {
    EXPECT_EQ(again[section], file[section]) << section;
  }
  CheckOptions options;
  options.method = CheckMethod::Both;
  EXPECT_TRUE(checkPassed(checkDocument(document, options)));
  EXPECT_TRUE(checkPassed(checkDocument(reread, options)));
  // A plan that names a part it does not have is refused, naming the joint.
  nlohmann::json tampered = file;
  tampered["joints"][0]["mover"] = 99;
  try {
    parseAssemblyText(tampered.dump(), "tampered.json");
    ADD_FAILURE() << "a joint of a missing part was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("joints[0].mover"), std::string::npos) << error.what();
  }
}

TEST(JsonDocument, ContactsReadTheSamePackedOrNot) {
  const std::string packed =
      R"({"kind": "contacts", "parts": [{"id": 1}, {"id": 2}, {"id": 5}], "contacts": [)"
      R"({"a": 1, "b": 2, "normal": [0, 0, 2], "area": 12.5}, {"a": 5, "b": 1, "normal": [0.6, -0.8, 0]}]})";
  std::string objects = packed;
  const std::string note = "\"note\": \"kept as an object\", ";
  for (size_t at = objects.find("\"normal\""); at != std::string::npos;
       at = objects.find("\"normal\"", at + note.size() + 1)) {
    objects.insert(at, note);
  }
  ASSERT_NE(objects, packed);
  const AssemblyDocument a = parseAssemblyText(packed, "packed.json"), b = parseAssemblyText(objects, "objects.json");
  ASSERT_EQ(a.assembly.contacts.size(), 2u);
  EXPECT_EQ(documentToJson(a), documentToJson(b));
  EXPECT_EQ(a.assembly.contacts[0].normal, (Vec3{0, 0, 1}));
  EXPECT_EQ(a.assembly.contacts[0].area, 12.5);
  EXPECT_EQ(a.assembly.parts[a.assembly.contacts[1].a].id, 5);
}

TEST(CheckMethodNames, UnknownMethodIsBadInput) {
  EXPECT_EQ(parseCheckMethod("lp"), CheckMethod::Inequalities);
  EXPECT_THROW(parseCheckMethod("simplex"), Error);
}

}  // namespace
}  // namespace desia
