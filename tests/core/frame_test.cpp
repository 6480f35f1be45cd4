// SPDX-License-Identifier: GPL-3.0-or-later
// Frame structures (paper Section 5.3): frames read from JSON, OBJ and .fpuz, every bad input named,
// joints designed and verified (DBG test with key 1, swept removal in id order), the same bytes
// for the same seed, result documents that desia check re-verifies, exports that round-trip.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "frame/frame_designer.h"
#include "test_support.h"

namespace desia {
namespace {

FrameDocument loadFrameExample(const std::string& name) {
  const std::string path = "examples/frame/" + name;
  return parseFrameText(testing::readFileText(testing::projectPath(path)), path);
}

FrameDesignResult design(const FrameDocument& frame, uint64_t seed = 1) {
  FrameDesignOptions options;
  options.seed = seed;
  options.limits.timeLimitSeconds = 120;
  return designFrame(frame.layout, options);
}

// The written result, read back as desia check reads it: interlocking with part 1 as the key, and
// every beam leaving along its planned axis in id order without hitting the beams after it.
void ExpectVerifiedResult(const FrameDocument& frame, const FrameDesignResult& result, int beams) {
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_EQ(static_cast<int>(result.order.size()), beams);
  EXPECT_EQ(frameDesignFailure(frame.layout, result.labels, result.order, result.directions), "");
  const std::string text = frameResultToJson(frame.layout, result, "result");
  const AssemblyDocument document = parseAssemblyText(text, "result.json");
  EXPECT_EQ(document.kind, AssemblyKind::Frame);
  ASSERT_EQ(document.assembly.partCount(), beams);
  CheckOptions both;
  both.method = CheckMethod::Both;
  const CheckReport report = checkAssembly(document, both);
  EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
  ASSERT_GE(report.result.key, 0);
  EXPECT_EQ(document.assembly.parts[report.result.key].id, 1);
  EXPECT_TRUE(hasOnlyAxisAlignedContacts(document.assembly));
  const FrameDocument reread = frameFromAssemblyDocument(document, "result.json");
  EXPECT_EQ(reread.directions.size() + 1, static_cast<size_t>(beams));
  EXPECT_EQ(frameDesignFailure(reread.layout, reread.labels, reread.order, reread.directions), "");
  // Written again, the same bytes.
  EXPECT_EQ(frameDocumentToJson(reread), frameDocumentToJson(parseFrameText(text, "result.json")));
}

TEST(FrameDesign, FrameCubeIsInterlockingWithKeyOneAndRemovableInOrder) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  EXPECT_EQ(cube.layout.frame.joints.size(), 8u);
  ExpectVerifiedResult(cube, design(cube), 12);
}

// The joint cubes are square to x, y and z: the FRAME CUBE turned about all three axes meets every
// cube at an angle, its search finds nothing, and the message says that the turn is why (issue 24:
// such a frame got "no interlocking joints exist" and no word about the turn).
TEST(FrameDesign, AFrameTurnedOffTheAxesIsToldSo) {
  std::string text = testing::readFileText(testing::projectPath("examples/frame/frame_cube.json"));
  nlohmann::json document = nlohmann::json::parse(text);
  const double a = 0.3, b = 0.2, c = 0.4;  // about x, then y, then z
  for (nlohmann::json& joint : document["joints"]) {
    const double x0 = joint["position"][0], y0 = joint["position"][1], z0 = joint["position"][2];
    const double y1 = y0 * std::cos(a) - z0 * std::sin(a), z1 = y0 * std::sin(a) + z0 * std::cos(a);
    const double x2 = x0 * std::cos(b) + z1 * std::sin(b), z2 = -x0 * std::sin(b) + z1 * std::cos(b);
    const double x3 = x2 * std::cos(c) - y1 * std::sin(c), y3 = x2 * std::sin(c) + y1 * std::cos(c);
    joint["position"] = {x3, y3, z2};
  }
  const FrameDocument turned = parseFrameText(document.dump(), "turned.json");
  const FrameDesignResult result = design(turned);
  ASSERT_EQ(result.status, DesignStatus::NotFound) << result.message;
  EXPECT_NE(result.message.find("no beam meets its joints along the x, y or z axis"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("turn it square to the axes"), std::string::npos) << result.message;
  // Square to the axes (the same frame designs, above), nothing is said of turns.
  EXPECT_EQ(frame_design::offTheAxesNote(loadFrameExample("frame_cube.json").layout.frame), "");
  EXPECT_NE(frame_design::offTheAxesNote(turned.layout.frame), "");
}

TEST(FrameDesign, FrameChairIsInterlocking) {
  const FrameDocument chair = loadFrameExample("frame_chair.json");
  for (const std::vector<int>& beams : chair.layout.beamsAtJoint) {
    EXPECT_GE(beams.size(), 2u);
    EXPECT_LE(beams.size(), 4u);
  }
  ExpectVerifiedResult(chair, design(chair), 11);
}

TEST(FrameDesign, ScaffoldOf92BeamsIsInterlocking) {
  const FrameDocument scaffold = loadFrameExample("scaffold_92.json");
  ExpectVerifiedResult(scaffold, design(scaffold, 4), 92);
}

// Seeds that once took 27 s or ran out of time (the remainder collapsing onto one joint): the
// star look-ahead and the restarts design each of them, verified, within a few thousand nodes.
TEST(FrameDesign, ScaffoldOf92BeamsDesignsForSeedsOneToThree) {
  const FrameDocument scaffold = loadFrameExample("scaffold_92.json");
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    FrameDesignOptions options;
    options.seed = seed;
    options.limits.timeLimitSeconds = 0;  // the node limit alone: the same outcome on every machine
    options.limits.nodeLimit = 20000;
    const FrameDesignResult result = designFrame(scaffold.layout, options);
    ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
    EXPECT_EQ(result.order.size(), 92u);
    EXPECT_EQ(frameDesignFailure(scaffold.layout, result.labels, result.order, result.directions), "");
  }
}

// A lattice of cells x cells x cells cubes of 1 m, every joint where its beams meet (valence up
// to 6), as examples/frame/make_examples.py writes SCAFFOLD 300.
FrameDocument latticeFrame(int cells) {
  std::string joints, beams;
  auto id = [&](int x, int y, int z) { return 1 + x + (cells + 1) * (z + (cells + 1) * y); };
  int beam = 0;
  for (int y = 0; y <= cells; ++y) {
    for (int z = 0; z <= cells; ++z) {
      for (int x = 0; x <= cells; ++x) {
        joints += std::string(joints.empty() ? "" : ",") + "{\"id\":" + std::to_string(id(x, y, z)) +
                  ",\"position\":[" + std::to_string(1000 * x) + "," + std::to_string(1000 * y) + "," +
                  std::to_string(1000 * z) + "]}";
        const int ends[3] = {x < cells ? id(x + 1, y, z) : 0, y < cells ? id(x, y + 1, z) : 0,
                             z < cells ? id(x, y, z + 1) : 0};
        for (int end : ends) {
          if (end == 0) continue;
          beams += std::string(beams.empty() ? "" : ",") + "{\"id\":" + std::to_string(++beam) + ",\"joints\":[" +
                   std::to_string(id(x, y, z)) + "," + std::to_string(end) + "]}";
        }
      }
    }
  }
  return parseFrameText("{\"format\":\"desia-assembly\",\"version\":1,\"kind\":\"frame\",\"joints\":[" + joints +
                            "],\"beams\":[" + beams + "]}",
                        "lattice.json");
}

// The sweep ranking (frame_design.cpp, top): the taken beams grow from the key's corner along the
// diagonal, so R ends at the opposite corner, where joints hold 3 beams and their cubes still have
// free voxels. Peeling the beams with the fewest neighbours in R first left R a path through
// joints of valence 6 whose ends were never interlocking: a lattice of 3 x 3 x 3 cells (144
// beams) ran out of time at 143 beams for every seed. Now one descent, almost without
// backtracking, ending at the corner (0, 0, 0).
TEST(FrameDesign, LatticeOfThreeCellsCubedEndsAtTheFarCornerInOneDescent) {
  const FrameDocument lattice = latticeFrame(3);
  ASSERT_EQ(lattice.layout.frame.beams.size(), 144u);
  FrameDesignOptions options;
  options.limits.timeLimitSeconds = 0;  // the node limit alone: the same outcome on every machine
  options.limits.nodeLimit = 2 * 144;
  const FrameDesignResult result = designFrame(lattice.layout, options);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_EQ(frameDesignFailure(lattice.layout, result.labels, result.order, result.directions), "");
  const FrameBeam& last = lattice.layout.frame.beams[result.order.back()];
  const Vec3& a = lattice.layout.frame.joints[last.joints[0]].position;
  const Vec3& b = lattice.layout.frame.joints[last.joints[1]].position;
  EXPECT_EQ(std::min(a[0] + a[1] + a[2], b[0] + b[1] + b[2]), 0.0) << "the last beam meets the corner (0, 0, 0)";
  const FrameBeam& key = lattice.layout.frame.beams[result.order.front()];
  EXPECT_EQ(std::max(lattice.layout.frame.joints[key.joints[0]].position[1],
                     lattice.layout.frame.joints[key.joints[1]].position[1]),
            3000.0)
      << "the key is at the top";
}

// SCAFFOLD 300 (4 x 4 x 4 cells), which never finished before the sweep (71,103 nodes in 120 s,
// deepest 299 of 300): seeds 1 to 3 within a node limit of about one descent and a few steps back.
TEST(FrameDesign, Scaffold300DesignsForSeedsOneToThree) {
  const FrameDocument scaffold = loadFrameExample("scaffold_300.json");
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    FrameDesignOptions options;
    options.seed = seed;
    options.limits.timeLimitSeconds = 0;
    options.limits.nodeLimit = 400;
    const FrameDesignResult result = designFrame(scaffold.layout, options);
    ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
    EXPECT_EQ(result.order.size(), 300u);
    EXPECT_EQ(frameDesignFailure(scaffold.layout, result.labels, result.order, result.directions), "");
  }
}

TEST(FrameDesign, FlowerOfCurvedBeamsIsInterlocking) {
  const FrameDocument flower = loadFrameExample("flower.json");
  int curved = 0;
  for (const FrameBeam& beam : flower.layout.frame.beams) curved += beam.path.empty() ? 0 : 1;
  EXPECT_EQ(curved, 23);
  ExpectVerifiedResult(flower, design(flower), 23);
}

TEST(FrameDesign, SameSeedSameBytes) {
  const FrameDocument chair = loadFrameExample("frame_chair.json");
  const std::string first = frameResultToJson(chair.layout, design(chair, 7));
  EXPECT_EQ(frameResultToJson(chair.layout, design(chair, 7)), first);
  // The example's stored result is what the default seed gives.
  const std::string stored = testing::readFileText(testing::projectPath("examples/frame/frame_chair_result.json"));
  EXPECT_EQ(frameResultToJson(chair.layout, design(chair), chair.name) + "\n", stored);
}

TEST(FrameDesign, CutPointBeamIsRefusedByName) {
  const FrameDocument frame = loadFrameExample("cut_point.json");
  EXPECT_EQ(frameCutBeams(frame.layout), std::vector<int>{8});
  const FrameDesignResult result = design(frame);
  EXPECT_EQ(result.status, DesignStatus::CutPoint);
  EXPECT_NE(result.message.find("beam 9 is a cut point"), std::string::npos) << result.message;
}

TEST(FrameDesign, ProgressCanCancel) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  FrameDesignOptions options;
  int calls = 0;
  options.limits.onProgress = [&](const DesignProgress& progress) {
    EXPECT_EQ(progress.targetParts, 12);
    return ++calls < 3;
  };
  EXPECT_EQ(designFrame(cube.layout, options).status, DesignStatus::Cancelled);
  EXPECT_EQ(calls, 3);
}

struct BadFrame {
  const char* name;
  std::string text;
  std::string expected;
};

void PrintTo(const BadFrame& value, std::ostream* out) { *out << value.name; }

class BadFrameInput : public ::testing::TestWithParam<BadFrame> {};

TEST_P(BadFrameInput, IsRefusedNamingJointAndBeams) {
  try {
    parseFrameText(GetParam().text, "bad.json");
    FAIL() << "accepted: " << GetParam().name;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
}

std::string frameJson(const std::string& joints, const std::string& beams, const std::string& extra = "") {
  return R"({"kind": "frame", )" + extra + R"("joints": )" + joints + R"(, "beams": )" + beams + "}";
}

INSTANTIATE_TEST_SUITE_P(
    FrameValidation, BadFrameInput,
    ::testing::Values(
        BadFrame{"twoBeamsOneFace", frameJson("[[0,0,0],[100,0,0],[100,10,0]]", "[[1,2],[1,3],[2,3]]"),
                 "joint 1: beams 1 and 2 both enter its +x face"},
        BadFrame{
            "tie", frameJson("[[0,0,0],[100,100,0],[200,0,0]]", "[[1,2],[2,3],[1,3]]"),
            "joint 1: beam 1 leaves along (0.707107, 0.707107, 0), as close to the cube's +x face as to its +y face"},
        BadFrame{"valence7",
                 frameJson("[[0,0,0],[100,0,0],[-100,0,0],[0,100,0],[0,-100,0],[0,0,100],[0,0,-100],[100,100,100]]",
                           "[[1,2],[1,3],[1,4],[1,5],[1,6],[1,7],[1,8]]"),
                 "joint 1 joins 7 beams (1, 2, 3, 4, 5, 6, 7)"},
        BadFrame{"zeroLength", frameJson("[[0,0,0],[0,0,0]]", "[[1,2]]"), "beam 1 has zero length"},
        BadFrame{"loop", frameJson("[[0,0,0],[1,0,0]]", "[[1,1]]"), "beam 1 starts and ends at joint 1"},
        BadFrame{"duplicate", frameJson("[[0,0,0],[100,0,0]]", "[[1,2],[2,1]]"), "beams 1 and 2 are the same beam"},
        BadFrame{"overlap", frameJson("[[0,0,0],[100,0,0],[0,100,0]]", "[[1,2],[1,3]]", R"("jointSize": 100, )"),
                 "the joint cubes of joint 1 and joint 3 overlap or touch: the joints are 100 apart along an axis and "
                 "a cube is 100 wide"},
        BadFrame{"fallsApart", frameJson("[[0,0,0],[100,0,0],[0,500,0],[100,500,0]]", "[[1,2],[3,4]]"),
                 "the frame falls apart: joint 3 (with beam 2) is not connected to joint 1"},
        BadFrame{"twoJointsAtOnePlace",
                 frameJson("[[0,0,0],[100,0,0],[0,100,0],[100,100,0],[100,100,0]]", "[[1,2],[2,4],[1,3],[3,5]]"),
                 "joint 4 and joint 5 are at the same place (100, 100, 0): merge them, or move one"},
        BadFrame{"lonelyJoint", frameJson("[[0,0,0],[100,0,0],[500,500,500]]", "[[1,2]]"),
                 "joint 3 at (500, 500, 500) joins no beam"},
        BadFrame{"unknownJoint", frameJson("[[0,0,0],[100,0,0]]", "[[1,3]]"), "beams[0]: joint 3 is not in 'joints'"},
        BadFrame{"crossing",
                 frameJson("[[0,0,0],[1000,0,0],[500,-500,0],[500,500,0],[0,500,0],[1000,-500,0]]",
                           "[[1,2],[3,4],[4,5],[5,1],[3,6],[6,2]]"),
                 "beams 1 and 2 cross or overlap"},
        BadFrame{"thickBeam", frameJson("[[0,0,0],[100,0,0]]", "[[1,2]]", R"("jointSize": 30, "beamSection": 20, )"),
                 "the beam section 20 must be positive and at most the voxel size 10"}));

TEST(FrameFormats, ObjFacesAndLinesGiveBeamsOnce) {
  // The cube as six quads (each edge in two faces) and one extra line along an edge.
  const std::string obj =
      "v 0 0 0\nv 600 0 0\nv 600 0 600\nv 0 0 600\nv 0 600 0\nv 600 600 0\nv 600 600 600\nv 0 600 600\n"
      "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\nl 1 2\n";
  const FrameDocument frame = parseFrameText(obj, "cube.obj");
  EXPECT_EQ(frame.layout.frame.joints.size(), 8u);
  EXPECT_EQ(frame.layout.frame.beams.size(), 12u);
  EXPECT_DOUBLE_EQ(frame.layout.frame.jointSize, 120);  // a fifth of the shortest beam
  ExpectVerifiedResult(frame, design(frame), 12);
  try {
    parseFrameText("v 0 0 0\nl 1 2\n", "bad.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.obj:2:5: vertex reference '2' is not a vertex defined above"),
              std::string::npos)
        << e.what();
  }
}

TEST(FrameFormats, FpuzRoundTripsAndChecks) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  const FrameDesignResult result = design(cube);
  const FrameDocument written = parseFrameText(frameResultToJson(cube.layout, result), "result.json");
  const std::vector<uint8_t> bytes = exportFrame(written, "fpuz");
  const std::string text(bytes.begin(), bytes.end());
  const FrameDocument reread = parseFrameText(text, "cube.fpuz");
  EXPECT_EQ(reread.labels, written.labels);
  EXPECT_EQ(reread.layout.endFace, written.layout.endFace);
  EXPECT_DOUBLE_EQ(reread.layout.frame.jointSize, written.layout.frame.jointSize);
  const std::vector<uint8_t> again = exportFrame(reread, "fpuz");
  EXPECT_EQ(std::string(again.begin(), again.end()), text);
  const AssemblyDocument document = parseAssemblyText(text, "cube.fpuz");
  const CheckReport report = checkAssembly(document);
  EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
  EXPECT_EQ(document.assembly.parts[report.result.key].id, 1);
}

TEST(FrameFormats, PartMeshesAreClosedAndCutListHasEveryBeam) {
  const FrameDocument chair = loadFrameExample("frame_chair.json");
  const FrameDesignResult result = design(chair);
  const FrameDocument written = parseFrameText(frameResultToJson(chair.layout, result), "result.json");
  for (size_t beam = 0; beam < written.layout.frame.beams.size(); ++beam) {
    const TriangleMesh mesh = beamPartMesh(written.layout, written.labels, static_cast<int>(beam));
    EXPECT_NO_THROW(checkClosedMesh(mesh, "part " + std::to_string(beam + 1)));
  }
  const std::vector<uint8_t> stl = exportFrame(written, "stl");
  const TriangleMesh all = parseStl(std::string(stl.begin(), stl.end()), "chair.stl");
  EXPECT_NO_THROW(checkClosedMesh(all, "chair.stl"));
  const std::vector<uint8_t> csv = exportFrame(written, "csv");
  const std::string text(csv.begin(), csv.end());
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 12);  // header + 11 beams
  EXPECT_NE(text.find("\n1,"), std::string::npos);
  EXPECT_NE(text.find(",stays\n"), std::string::npos);
}

TEST(FrameFormats, VoxelExportOfTheCubeIsInterlockingAndRemovableInIdOrder) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  const FrameDocument written = parseFrameText(frameResultToJson(cube.layout, design(cube), cube.name), "result.json");
  const AssemblyDocument voxels = frameVoxelDocument(written, "result.json");
  EXPECT_EQ(voxels.kind, AssemblyKind::Voxel);
  ASSERT_EQ(voxels.voxels.maxLabel(), 12);
  // 600 mm apart, joint cubes of 120 mm: 40 mm voxels, 15 from joint to joint, 18 in all.
  EXPECT_EQ(voxels.voxels.nx(), 18);
  EXPECT_EQ(voxels.voxels.ny(), 18);
  EXPECT_EQ(voxels.voxels.nz(), 18);
  // Every beam: a rod of 12 voxels plus its voxels in its two joint cubes.
  const std::vector<int64_t> counts = voxels.voxels.labelCounts();
  for (size_t b = 0; b < written.layout.frame.beams.size(); ++b) {
    int owned = 0;
    for (const JointLabels& joint : written.labels) owned += static_cast<int>(std::count(joint.begin(), joint.end(), b));
    EXPECT_EQ(counts[written.layout.frame.beams[b].id], 12 + owned) << "part " << written.layout.frame.beams[b].id;
  }
  const CheckReport report = checkAssembly(voxels);
  EXPECT_EQ(report.result.verdict, Verdict::Interlocking) << report.result.reason;
  ASSERT_GE(report.result.key, 0);
  EXPECT_EQ(voxels.assembly.parts[report.result.key].id, 1);
  ASSERT_TRUE(report.disassembly.has_value());
  EXPECT_TRUE(report.disassembly->complete);
  // The planner removes the lowest id that can leave: id order means each part leaves in turn.
  ASSERT_EQ(report.disassembly->removals.size(), 12u);
  for (size_t k = 0; k < report.disassembly->removals.size(); ++k)
    EXPECT_EQ(voxels.assembly.parts[report.disassembly->removals[k].part].id, static_cast<int>(k) + 1);
  // .puz and voxel JSON hold the same grid; .xmpuzzle is written.
  const std::vector<uint8_t> puz = exportFrame(written, "puz");
  EXPECT_EQ(parsePuz(std::string(puz.begin(), puz.end()), "cube.puz").labels(), voxels.voxels.labels());
  const std::vector<uint8_t> json = exportFrame(written, "voxel-json");
  EXPECT_EQ(parseAssemblyText(std::string(json.begin(), json.end()), "cube.json").voxels.labels(),
            voxels.voxels.labels());
  EXPECT_FALSE(exportFrame(written, "xmpuzzle").empty());
}

TEST(FrameFormats, VoxelExportNamesTheBeamOffTheGrid) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  FrameDocument written = parseFrameText(frameResultToJson(cube.layout, design(cube), cube.name), "result.json");
  // Joint 8 (600, 600, 600) moved by half a voxel along x: still a valid frame (its beams bend
  // nowhere, the one along x gets shorter), but off the grid of joint 1.
  Frame frame = written.layout.frame;
  int moved = -1;
  for (size_t j = 0; j < frame.joints.size(); ++j) {
    if (frame.joints[j].position[0] == 600 && frame.joints[j].position[1] == 600 && frame.joints[j].position[2] == 600)
      moved = static_cast<int>(j);
  }
  ASSERT_GE(moved, 0);
  frame.joints[moved].position[0] = 620;
  frame.joints[moved].position[2] = 620;
  try {
    written.layout = layoutFrame(frame, "moved");
  } catch (const Error& e) {
    FAIL() << e.what();
  }
  int firstBeam = 0;  // the lowest id at the moved joint: the first named
  for (const FrameBeam& beam : frame.beams) {
    if ((beam.joints[0] == moved || beam.joints[1] == moved) && (firstBeam == 0 || beam.id < firstBeam))
      firstBeam = beam.id;
  }
  try {
    exportFrame(written, "puz", 0, "moved.json");
    FAIL() << "exported a frame off the grid";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_NE(std::string(e.what()).find("beam " + std::to_string(firstBeam) + " (joints "), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("is off the voxel grid"), std::string::npos) << e.what();
  }
}

TEST(FrameGeometry, CurvedBeamsEnterTheFaceOfTheirEndTangent) {
  // The cube's top front edge bowed upwards through two path points: it leaves its joints upwards.
  std::string text = testing::readFileText(testing::projectPath("examples/frame/frame_cube.json"));
  FrameDocument cube = parseFrameText(text, "cube.json");
  Frame frame = cube.layout.frame;
  for (FrameBeam& beam : frame.beams) {
    const Vec3& a = frame.joints[beam.joints[0]].position;
    const Vec3& b = frame.joints[beam.joints[1]].position;
    if (a[1] == 600 && b[1] == 600 && a[2] == 0 && b[2] == 0) beam.path = {{a[0] + 50, 900, 0}, {b[0] - 50, 900, 0}};
  }
  const FrameLayout layout = layoutFrame(frame, "bowed cube");
  int bowed = 0;
  for (size_t b = 0; b < frame.beams.size(); ++b) {
    if (frame.beams[b].path.empty()) continue;
    ++bowed;
    EXPECT_EQ(layout.endFace[b][0], 2);  // +y
    EXPECT_EQ(layout.endFace[b][1], 2);
    EXPECT_GT(beamBodyLength(layout, static_cast<int>(b)), 600);
  }
  EXPECT_EQ(bowed, 1);
}

TEST(FrameGeometry, SweptBoxesCollideOnlyWhenMovingInto) {
  OrientedBox a, b;
  a.halfExtents = b.halfExtents = {0.5, 0.5, 0.5};
  b.centre = {1, 0, 0};  // touching a's +x face
  EXPECT_TRUE(sweptBoxesCollide(a, {1, 0, 0}, b));
  EXPECT_FALSE(sweptBoxesCollide(a, {-1, 0, 0}, b));
  EXPECT_FALSE(sweptBoxesCollide(a, {0, 1, 0}, b));  // sliding along the contact
  b.centre = {3, 0.9, 0};                            // ahead, overlapping in y
  EXPECT_TRUE(sweptBoxesCollide(a, {1, 0, 0}, b));
  b.centre = {3, 1.0, 0};  // ahead, only touching in y
  EXPECT_FALSE(sweptBoxesCollide(a, {1, 0, 0}, b));
}

// The designer's message names the key as the result document and `desia check` do (beam 1: the
// result renumbers the beams in removal order), and the input beam it was when that differs.
TEST(FrameDesign, MessageNamesTheKeyAsTheResultDoes) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  const FrameDesignResult result = design(cube);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  const int inputId = cube.layout.frame.beams[result.order[0]].id;
  ASSERT_NE(inputId, 1) << "seed 1 keys another beam than the input's first; pick a seed that does";
  EXPECT_NE(result.message.find("(key: beam 1, input beam " + std::to_string(inputId) + ")"), std::string::npos)
      << result.message;
  const nlohmann::json written = nlohmann::json::parse(frameResultToJson(cube.layout, result));
  EXPECT_EQ(written["beams"][0]["id"], 1);
  EXPECT_EQ(written["beams"][0]["inputId"], inputId);
  const AssemblyDocument document = parseAssemblyText(written.dump(), "result.json");
  const CheckReport report = checkAssembly(document);
  ASSERT_GE(report.result.key, 0);
  EXPECT_EQ(document.assembly.parts[report.result.key].id, 1);
  // Designed again from the result, the key is beam 1 of the new result, and the input beam keeps
  // the id of the first input (the result's inputId), as the part list shows it.
  const FrameDocument reread = parseFrameText(written.dump(), "result.json");
  const FrameDesignResult again = design(reread);
  ASSERT_EQ(again.status, DesignStatus::Success) << again.message;
  const FrameBeam& key = reread.layout.frame.beams[again.order[0]];
  const std::string expected = key.inputId == 1 ? "(key: beam 1)" : "(key: beam 1, input beam " + std::to_string(key.inputId) + ")";
  EXPECT_NE(again.message.find(expected), std::string::npos) << again.message;
  // Step by step: the same naming.
  FrameDesignSession session(cube.layout, {});
  while (!session.complete()) ASSERT_TRUE(session.next()) << session.result().message;
  const int stepKey = cube.layout.frame.beams[session.result().order[0]].id;
  EXPECT_EQ(session.result().message,
            "designed the joints of 12 beams step by step (key: beam 1" +
                (stepKey == 1 ? std::string() : ", input beam " + std::to_string(stepKey)) + ")");
}

// A frame input's cut-point beams are in its check report before any design, as a plate
// structure's are: `cutPoints` (part ids) in the JSON, a line in the text; none for a frame
// without one, designed or not.
TEST(FrameCutPoints, TheCheckOfAnInputNamesItsCutPointBeam) {
  const std::string path = "examples/frame/cut_point.json";
  const AssemblyDocument cut = parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
  ASSERT_EQ(cut.kind, AssemblyKind::Frame);
  ASSERT_EQ(cut.plateCutPoints.size(), 1u);
  EXPECT_EQ(cut.assembly.parts[cut.plateCutPoints[0]].id, 9);
  const CheckReport report = checkAssembly(cut);
  const nlohmann::json json = nlohmann::json::parse(checkReportToJson(cut, report));
  EXPECT_EQ(json["kind"], "frame");
  EXPECT_EQ(json["cutPoints"], nlohmann::json::array({9}));
  const std::string text = checkReportToText(cut, report);
  EXPECT_NE(text.find("cut points of the parts-graph: beam 9 (no joints"), std::string::npos) << text;

  const std::string cubePath = "examples/frame/frame_cube.json";
  const AssemblyDocument cube = parseAssemblyText(testing::readFileText(testing::projectPath(cubePath)), cubePath);
  EXPECT_EQ(nlohmann::json::parse(checkReportToJson(cube, checkAssembly(cube)))["cutPoints"], nlohmann::json::array());
  const FrameDocument cubeFrame = loadFrameExample("frame_cube.json");
  const AssemblyDocument result = parseAssemblyText(frameResultToJson(cubeFrame.layout, design(cubeFrame)), "result.json");
  EXPECT_EQ(nlohmann::json::parse(checkReportToJson(result, checkAssembly(result)))["cutPoints"], nlohmann::json::array());
  EXPECT_EQ(checkReportToText(result, checkAssembly(result)).find("cut points"), std::string::npos);
}

TEST(FrameSession, StepByStepGivesAVerifiedDesignAndGoesBack) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  FrameDesignSession session(cube.layout, {});
  EXPECT_EQ(session.targetBeams(), 12);
  EXPECT_FALSE(session.back()) << "at the root";
  EXPECT_FALSE(session.complete());
  ASSERT_GT(session.childCount(), 0);
  const FrameDesignStep key = session.childPreview(0);
  EXPECT_EQ(key.direction, cubeFaceNormal(2)) << "the key leaves upwards when it can";
  EXPECT_THROW(session.childPreview(session.childCount()), Error);
  // Best child each time, until the design is complete and verified.
  while (!session.complete()) ASSERT_TRUE(session.next()) << session.result().message;
  EXPECT_EQ(session.childCount(), 0);
  EXPECT_EQ(session.steps().size(), 11u);
  EXPECT_EQ(session.steps()[0].beam, key.beam);
  const FrameDesignResult result = session.result();
  ExpectVerifiedResult(cube, result, 12);
  EXPECT_EQ(result.order[0], key.beam);
  // Back one step and the design is open again; choosing forward completes it again.
  ASSERT_TRUE(session.back());
  EXPECT_FALSE(session.complete());
  EXPECT_EQ(session.steps().size(), 10u);
  ASSERT_TRUE(session.next());
  EXPECT_TRUE(session.complete());
  EXPECT_EQ(session.result().labels, result.labels);
  // The same seed and calls, the same design.
  FrameDesignSession again(cube.layout, {});
  while (!again.complete()) ASSERT_TRUE(again.next());
  EXPECT_EQ(frameResultToJson(cube.layout, again.result()), frameResultToJson(cube.layout, result));
  // A frame with a cut-point beam has no session.
  const FrameDocument cut = loadFrameExample("cut_point.json");
  try {
    FrameDesignSession refused(cut.layout, {});
    ADD_FAILURE() << "a cut point was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("beam 9 is a cut point", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace desia

namespace desia {
namespace {

// "Finish automatically from here" on a frame session: the search below the node, the beams
// taken so far first in the order with their directions, verified, reproducible; the session
// does not move.
TEST(FrameSessionFinish, FinishesBelowTheNodeVerifiedAndReproducible) {
  const FrameDocument cube = loadFrameExample("frame_cube.json");
  FrameDesignSession session(cube.layout, {});
  ASSERT_GT(session.childCount(), 1);
  session.chooseChild(1);  // not the search's own key
  ASSERT_GT(session.childCount(), 0);
  session.chooseChild(session.childCount() > 1 ? 1 : 0);
  const std::vector<FrameDesignStep> chosen = session.steps();
  ASSERT_EQ(chosen.size(), 2u);
  DesignLimits limits;
  limits.nodeLimit = 200000;
  const FrameDesignResult first = session.finish(limits);
  ExpectVerifiedResult(cube, first, 12);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(first.order[k], chosen[k].beam);
    EXPECT_EQ(first.directions[k], chosen[k].direction);
  }
  EXPECT_EQ(session.steps().size(), 2u) << "the session stays where it is";
  EXPECT_FALSE(session.complete());
  EXPECT_EQ(frameResultToJson(cube.layout, session.finish(limits)), frameResultToJson(cube.layout, first))
      << "same path, same bytes";
  // The session still walks on as before.
  ASSERT_TRUE(session.next());
  EXPECT_EQ(session.steps().size(), 3u);
  DesignLimits tiny;
  tiny.nodeLimit = 1;
  EXPECT_EQ(session.finish(tiny).status, DesignStatus::LimitReached);
}

}  // namespace
}  // namespace desia
