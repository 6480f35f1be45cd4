// SPDX-License-Identifier: GPL-3.0-or-later
// The inequality test's graph certificates (InequalityOptions::graphCertificates, issue 10): on
// programs whose rows are difference constraints (axis-aligned contacts), graph algorithms propose
// each program's answer and the same checks as for GLPK's answers accept it. Each test runs the
// shortcut and GLPK alone on the same input and requires the same answers, and that the shortcut
// really decided (so that a silent fallback to GLPK cannot make these tests pass vacuously). The
// cone certificates of one free part (InequalityOptions::coneCertificates) are tested at the end.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <iostream>
#include <random>
#include <string>

#include "desia/analysis.h"
#include "desia/plate.h"
#include "plate_test_support.h"
#include "test_support.h"

namespace desia {
namespace {

InequalityOptions glpkAlone() {
  InequalityOptions options;
  options.graphCertificates = false;
  options.coneCertificates = false;
  return options;
}

// A motion must push into no contact (up to rounding) and move some free part.
void ExpectValidMotion(const Assembly& assembly, const std::vector<bool>& isFree, const MotionSearch& search,
                       const std::string& what) {
  ASSERT_EQ(search.velocities.size(), static_cast<size_t>(assembly.partCount())) << what;
  double fastest = 0;
  for (int i = 0; i < assembly.partCount(); ++i) {
    const Vec3& v = search.velocities[i];
    const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!isFree[i]) {
      EXPECT_EQ(speed, 0.0) << what << ": fixed part " << assembly.parts[i].id << " moves";
    }
    fastest = std::max(fastest, speed);
  }
  EXPECT_GT(fastest, 0.5) << what;
  for (const Contact& c : assembly.contacts) {
    const Vec3& a = search.velocities[c.a];
    const Vec3& b = search.velocities[c.b];
    const double separation = (b[0] - a[0]) * c.normal[0] + (b[1] - a[1]) * c.normal[1] + (b[2] - a[2]) * c.normal[2];
    EXPECT_GE(separation, -1e-9) << what << ": parts " << assembly.parts[c.a].id << " and " << assembly.parts[c.b].id;
  }
}

// One motion program both ways: same answer, the shortcut decided it, its motion is valid.
void ExpectSameAnswer(const Assembly& assembly, const std::vector<bool>& isFree, const std::string& what,
                      const std::vector<bool>* isWatched = nullptr) {
  const std::vector<bool>& watched = isWatched ? *isWatched : isFree;
  const MotionSearch byGraphs = findMotionOfWatchedParts(assembly, isFree, watched);
  const MotionSearch byGlpk = findMotionOfWatchedParts(assembly, isFree, watched, glpkAlone());
  EXPECT_TRUE(byGraphs.decidedByGraphs) << what;
  EXPECT_FALSE(byGlpk.decidedByGraphs) << what;
  ASSERT_EQ(byGraphs.movable, byGlpk.movable) << what;
  if (byGraphs.movable) ExpectValidMotion(assembly, isFree, byGraphs, what);
}

// The whole test both ways: same verdict, key and key directions; a witness is a valid motion.
void ExpectSameVerdict(const Assembly& assembly, const std::string& what) {
  const std::vector<BaseDirection> directions = computeBaseDirections(assembly);
  const InterlockingResult byGraphs = testInterlockingByInequalities(assembly, directions);
  const InterlockingResult byGlpk = testInterlockingByInequalities(assembly, directions, glpkAlone());
  ASSERT_EQ(verdictName(byGraphs.verdict), verdictName(byGlpk.verdict))
      << what << "\ngraphs: " << byGraphs.reason << "\nglpk: " << byGlpk.reason;
  EXPECT_EQ(byGraphs.key, byGlpk.key) << what;
  EXPECT_EQ(testing::labelsOf(byGraphs.keyDirections), testing::labelsOf(byGlpk.keyDirections)) << what;
  EXPECT_EQ(byGraphs.hasWitness, byGlpk.hasWitness) << what;
  if (byGraphs.hasWitness && !byGraphs.witness.direction.empty()) {
    // A witness moving its parts together is a motion as it stands (a mixed one is normalized
    // part by part: its directions, not a motion).
    MotionSearch motion;
    motion.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
    std::vector<bool> moving(assembly.partCount(), false);
    for (size_t k = 0; k < byGraphs.witness.parts.size(); ++k) {
      motion.velocities[byGraphs.witness.parts[k]] = byGraphs.witness.velocities[k];
      moving[byGraphs.witness.parts[k]] = true;
    }
    ExpectValidMotion(assembly, moving, motion, what + " (witness)");
  }
}

// Every program the inequality test poses: each part alone, and all but one reference part free
// (every part watched; the key free but not watched, as in round 2; the key held too, which on an
// interlocking assembly leaves nothing movable: the "no motion" certificate on the whole).
void ExpectSameAnswersOnEveryProgram(const Assembly& assembly, int key, const std::string& what) {
  const int n = assembly.partCount();
  for (int i = 0; i < n; ++i) {
    std::vector<bool> isFree(n, false);
    isFree[i] = true;
    ExpectSameAnswer(assembly, isFree, what + ", part " + std::to_string(assembly.parts[i].id) + " alone");
  }
  const int reference = key == 0 ? 1 : 0;
  std::vector<bool> isFree(n, true);
  isFree[reference] = false;
  ExpectSameAnswer(assembly, isFree, what + ", all but the reference");
  if (key >= 0) {
    std::vector<bool> isWatched = isFree;
    isWatched[key] = false;  // round 2 as the test poses it: the key may move along
    ExpectSameAnswer(assembly, isFree, what + ", all but the reference, the key not watched", &isWatched);
    isFree[key] = false;
    ExpectSameAnswer(assembly, isFree, what + ", all but the reference and the key");
  }
}

// Parts grown breadth-first from random seeds until they fill a side^3 cube (as the benchmark's
// 1500-part cube is made, smaller).
VoxelGrid randomPartition(int side, int parts, uint32_t seed) {
  VoxelGrid grid(side, side, side);
  std::mt19937 random(seed);
  std::vector<std::deque<int64_t>> frontier(parts);
  for (int label = 1; label <= parts;) {
    const int64_t voxel = static_cast<int64_t>(random() % static_cast<uint32_t>(grid.voxelCount()));
    if (grid.labelAt(voxel) != 0) continue;
    grid.setLabelAt(voxel, label);
    frontier[label - 1].push_back(voxel);
    ++label;
  }
  const int steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (bool grew = true; grew;) {
    grew = false;
    for (int label = 1; label <= parts; ++label) {
      std::deque<int64_t>& queue = frontier[label - 1];
      while (!queue.empty()) {
        const Int3 c = grid.coordinates(queue.front());
        bool claimed = false;
        for (const auto& step : steps) {
          const int x = c.x + step[0], y = c.y + step[1], z = c.z + step[2];
          if (!grid.inside(x, y, z) || grid.label(x, y, z) != 0) continue;
          grid.setLabel(x, y, z, label);
          queue.push_back(grid.index(x, y, z));
          claimed = grew = true;
          break;
        }
        if (claimed) break;
        queue.pop_front();
      }
    }
  }
  return grid;
}

const char* const kReferenceFiles[] = {"result_puz/Cube_4x4x4_K9.puz",    "result_puz/Cube_4x4x4_K9_01.puz",
                                       "result_puz/Cube_Hollow_4x4x4_K7", "result_puz/cube_5x5x5_K16.puz",
                                       "result_puz/cartoon_dog.puz",       "result_puz/bunny_15x14x11_K80.puz"};

TEST(GraphCertificates, ReferencePuzzlesEveryProgramAndVerdict) {
  for (const char* file : kReferenceFiles) {
    const AssemblyDocument document = testing::loadReference(file);
    const InterlockingResult result = testInterlockingByInequalities(document.assembly);
    ASSERT_EQ(result.verdict, Verdict::Interlocking) << file;
    ExpectSameAnswersOnEveryProgram(document.assembly, result.key, file);
    ExpectSameVerdict(document.assembly, file);
  }
}

TEST(GraphCertificates, PuzzleVariantsAndRandomPartitions) {
  std::mt19937 random(10);
  int variants = 0;
  for (const char* file : {"result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_Hollow_4x4x4_K7", "result_puz/cube_5x5x5_K16.puz",
                           "result_puz/cartoon_dog.puz"}) {
    const VoxelGrid original = testing::loadReference(file).voxels;
    for (int variant = 0; variant < 15; ++variant) {
      VoxelGrid grid = original;
      for (int trades = 0, attempt = 0; trades < 1 + variant % 3 && attempt < 200; ++attempt) {
        trades += testing::tradeOneVoxel(grid, random) ? 1 : 0;
      }
      const Assembly assembly = assemblyFromVoxels(grid);
      const std::string what = std::string(file) + " variant " + std::to_string(variant);
      ExpectSameVerdict(assembly, what);
      ExpectSameAnswersOnEveryProgram(assembly, testInterlockingByInequalities(assembly).key, what);
      ++variants;
    }
  }
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    const VoxelGrid grid = randomPartition(4 + static_cast<int>(seed % 3), 3 + static_cast<int>(seed * 3 % 11), seed);
    validateVoxelParts(grid, "random partition");
    const Assembly assembly = assemblyFromVoxels(grid);
    const std::string what = "random partition " + std::to_string(seed);
    ExpectSameVerdict(assembly, what);
    ExpectSameAnswersOnEveryProgram(assembly, -1, what);
  }
  EXPECT_EQ(variants, 60);
}

TEST(GraphCertificates, RoundOneOnALargerPartitionFindsTheSameParts) {
  // 300 parts: every part's program both ways, no early stop.
  const Assembly assembly = assemblyFromVoxels(randomPartition(12, 300, 2018));
  const PartsMovableAlone byGraphs = findPartsMovableAlone(assembly);
  const PartsMovableAlone byGlpk = findPartsMovableAlone(assembly, glpkAlone());
  EXPECT_EQ(byGraphs.parts, byGlpk.parts);
  EXPECT_FALSE(byGraphs.parts.empty());
  for (size_t k = 0; k < byGraphs.parts.size(); ++k) {
    EXPECT_TRUE(byGraphs.motions[k].decidedByGraphs);
    std::vector<bool> isFree(assembly.partCount(), false);
    isFree[byGraphs.parts[k]] = true;
    ExpectValidMotion(assembly, isFree, byGraphs.motions[k], "part " + std::to_string(byGraphs.parts[k] + 1));
  }
  // The round-2 program of the benchmark (two parts fixed): both ways.
  std::vector<bool> isFree(assembly.partCount(), true);
  isFree[0] = isFree[1] = false;
  ExpectSameAnswer(assembly, isFree, "all but parts 1 and 2");
}

TEST(GraphCertificates, GroupSlidingAsABlockNeedsTheFlowInsideItsComponent) {
  // A frame (part 1) holds a channel along x, open at both ends; in it part 2 wraps around part 3
  // (a voxel of 2 on both sides of 3 along x), so 2 and 3 are one block along x that slides.
  // Eq. 2's objective counts the contacts between 2 and 3, which cannot separate: its "no motion"
  // certificate routes their flow inside the block, then the generic functional finds the slide.
  const VoxelGrid grid = testing::gridFromLayers({
      {"1 1 1", "1 1 1", "1 1 1", "1 1 1"},
      {"1 1 1", "2 3 2", "2 2 2", "1 1 1"},
      {"1 1 1", "1 1 1", "1 1 1", "1 1 1"},
  });
  const Assembly assembly = assemblyFromVoxels(grid);
  const std::vector<bool> isFree{false, true, true};
  ExpectSameAnswer(assembly, isFree, "parts 2 and 3 in the channel");
  const MotionSearch search = findFreeMotion(assembly, isFree);
  ASSERT_TRUE(search.movable);
  EXPECT_EQ(std::abs(search.velocities[1][0]), 1.0);
  EXPECT_EQ(search.velocities[1], search.velocities[2]);
  ExpectSameVerdict(assembly, "channel");
}

TEST(GraphCertificates, ExampleDocumentsKeepTheirVerdicts) {
  // Plates and frames (right-angled designs have axis-aligned normals too), the Fig. 4 graph and
  // the hostile contact documents of issue 14: the same verdict, key and key directions.
  int compared = 0, byGraphs = 0;
  for (const char* path :
       {"examples/plate/cube.json", "examples/plate/table.json", "examples/plate/bookshelf.json",
        "examples/plate/cabinet.json", "examples/plate/chair_repaired.json", "examples/plate/mitred_box.json",
        "examples/plate/dodecahedron.json", "examples/frame/frame_cube_result.json", "examples/frame/frame_chair_result.json",
        "examples/frame/scaffold_92_result.json", "examples/frame/flower_result.json",
        "examples/contacts/figure4_two_parts_move_at_once.json", "tests/data/contacts/fig4_huge_normal.json",
        "tests/data/contacts/lp_glpk_abort_1e-200.json", "tests/data/contacts/lp_simplex_cycles.json",
        "tests/data/contacts/lp_tiny_component_exit3.json"}) {
    AssemblyDocument document;
    try {
      document = parseAssemblyText(testing::readFileText(testing::projectPath(path)), path);
    } catch (const std::exception&) {
      continue;  // not an assembly by itself (a design input)
    }
    if (document.assembly.partCount() < 3) continue;
    const Assembly clean = withCleanedNormals(document.assembly);
    ExpectSameVerdict(clean, path);
    std::vector<bool> isFree(clean.partCount(), true);
    isFree[0] = false;
    byGraphs += findFreeMotion(clean, isFree).decidedByGraphs ? 1 : 0;
    ++compared;
  }
  EXPECT_GE(compared, 8);
  std::cout << "[          ] " << compared << " documents compared, round 2 decided by graphs on " << byGraphs << "\n";
}

TEST(GraphCertificates, OtherNormalsStayWithGlpk) {
  // A tilted contact makes the rows no difference constraints: GLPK decides, as before.
  Assembly assembly;
  assembly.parts = {{1, ""}, {2, ""}};
  const double s = 1 / std::sqrt(2.0);
  assembly.contacts = {{1, 0, {0, 1, 0}, 1}, {1, 0, {0, -1, 0}, 1}, {1, 0, {0, 0, 1}, 1}, {1, 0, {s, 0, -s}, 1}};
  const MotionSearch search = findFreeMotion(assembly, {false, true});
  EXPECT_FALSE(search.decidedByGraphs);
  EXPECT_TRUE(search.movable);
  // The same part among axis-aligned contacts only: the graphs decide.
  assembly.contacts.back() = {1, 0, {0, 0, -1}, 1};
  const MotionSearch axisAligned = findFreeMotion(assembly, {false, true});
  EXPECT_TRUE(axisAligned.decidedByGraphs);
  EXPECT_TRUE(axisAligned.movable);  // the slot along x
  EXPECT_EQ(std::abs(axisAligned.velocities[1][0]), 1.0);
}


// --- Cone certificates (InequalityOptions::coneCertificates) -----------------------------------
//
// One free part among fixed ones: its "no motion" found as -c in the cone of at most three contact
// rows. Each test compares with GLPK alone and with the exact rational simplex, and counts the
// programs the cones really decided, so that a silent fallback cannot make it pass.

InequalityOptions exactAlone() {
  InequalityOptions options;
  options.exactOnly = true;
  return options;
}

Vec3 turned(const std::array<Vec3, 3>& r, const Vec3& v) {
  return {r[0][0] * v[0] + r[0][1] * v[1] + r[0][2] * v[2], r[1][0] * v[0] + r[1][1] * v[1] + r[1][2] * v[2],
          r[2][0] * v[0] + r[2][1] * v[1] + r[2][2] * v[2]};
}

Vec3 unitVector(std::mt19937& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Vec3 v{normal(random), normal(random), normal(random)};
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}

// Part 2 among contacts with the fixed part 1: random normals, some sets flat (a sliding motion
// normal to their plane), some with opposite pairs (a slot), repeated rows, either part as `a`.
Assembly randomlyHeldPart(std::mt19937& random, int variant) {
  Assembly assembly;
  assembly.parts = {{1, ""}, {2, ""}};
  const int count = 1 + static_cast<int>(random() % 9);
  for (int k = 0; k < count; ++k) {
    Vec3 n = unitVector(random);
    if (variant % 4 == 1) {  // flat: every normal in the plane z = 0
      const double length = std::hypot(n[0], n[1]);
      n = {n[0] / length, n[1] / length, 0.0};
    }
    const bool partTwoIsB = random() % 2 == 0;
    // A contact's normal points from a into b: part 2 may not move against it as b, along it as a.
    assembly.contacts.push_back(partTwoIsB ? Contact{0, 1, n, 1} : Contact{1, 0, {-n[0], -n[1], -n[2]}, 1});
    if (variant % 4 == 2) assembly.contacts.push_back({0, 1, {-n[0], -n[1], -n[2]}, 1});  // its opposite too
    if (variant % 4 == 3) assembly.contacts.push_back(assembly.contacts.back());           // the same row twice
  }
  return assembly;
}

TEST(ConeCertificates, OnePartAmongRandomNormalsAnswersAsGlpkAndTheExactSimplex) {
  std::mt19937 random(2026);
  int blocked = 0, decidedByCones = 0, movable = 0;
  for (int variant = 0; variant < 400; ++variant) {
    const Assembly assembly = randomlyHeldPart(random, variant);
    const std::vector<bool> isFree{false, true};
    const std::string what = "variant " + std::to_string(variant);
    const MotionSearch withCones = findFreeMotion(assembly, isFree);
    const MotionSearch byGlpk = findFreeMotion(assembly, isFree, glpkAlone());
    const MotionSearch exact = findFreeMotion(assembly, isFree, exactAlone());
    ASSERT_EQ(withCones.movable, byGlpk.movable) << what;
    ASSERT_EQ(withCones.movable, exact.movable) << what;
    EXPECT_FALSE(byGlpk.decidedByCones) << what;
    if (withCones.movable) {
      EXPECT_FALSE(withCones.decidedByCones) << what;  // cones only ever certify "no motion"
      ExpectValidMotion(assembly, isFree, withCones, what);
      ++movable;
    } else {
      ++blocked;
      decidedByCones += withCones.decidedByCones ? 1 : 0;
    }
  }
  // Both answers are common, and the cones settle nearly every blocked part (a cone too thin to
  // certify within the tolerance is left to GLPK).
  EXPECT_GE(blocked, 80);
  EXPECT_GE(movable, 80);
  EXPECT_GE(decidedByCones, blocked * 9 / 10);
  std::cout << "[          ] " << blocked << " blocked (" << decidedByCones << " by cones), " << movable << " movable\n";
}

TEST(ConeCertificates, ATetrahedronsFourNormalsHoldItUnderAnyRotationAndThreeDoNot) {
  // Four normals pointing out of a regular tetrahedron's faces span space positively: the part is
  // held. Drop one and it can leave. Turned as a modelling tool would, both stay so.
  const double s = 1 / std::sqrt(3.0);
  const std::vector<Vec3> faces{{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  for (int turn = 0; turn < 50; ++turn) {
    const std::array<Vec3, 3> r = testing::rotation(angle(random), angle(random), angle(random));
    for (size_t kept = 3; kept <= 4; ++kept) {
      Assembly assembly;
      assembly.parts = {{1, ""}, {2, ""}};
      for (size_t k = 0; k < kept; ++k) assembly.contacts.push_back({0, 1, turned(r, faces[k]), 1});
      const MotionSearch search = findFreeMotion(assembly, {false, true});
      const std::string what = "turn " + std::to_string(turn) + ", " + std::to_string(kept) + " faces";
      EXPECT_EQ(search.movable, kept == 3) << what;
      EXPECT_EQ(search.decidedByCones, kept == 4) << what;
      EXPECT_EQ(findFreeMotion(assembly, {false, true}, glpkAlone()).movable, kept == 3) << what;
    }
  }
}

TEST(ConeCertificates, JointedSlantedPlatesKeepEveryRoundOneAnswerAndVerdict) {
  // The contacts of jointed plates leaning 15 degrees and at 41.8 degrees (slanted dovetails,
  // tenons, step tenons): every part alone with and without cones, then the whole test, as
  // designed and turned.
  int programs = 0, decidedByCones = 0;
  for (const char* name : {"leaning_box.json", "slanted_box.json"}) {
    const AssemblyDocument input = testing::loadPlateExample(name);
    PlateDesignOptions options;
    options.realization = JointRealization::Milled;
    const PlateDesignResult design = designPlateJoints(input.plates, computePlateContacts(input.plates, {}), options);
    ASSERT_EQ(design.status, DesignStatus::Success) << name << ": " << design.message;
    Assembly turnedAssembly = design.jointAssembly;
    const std::array<Vec3, 3> r = testing::rotation(0.3, -1.1, 2.0);
    for (Contact& contact : turnedAssembly.contacts) contact.normal = turned(r, contact.normal);
    for (const Assembly& assembly : {withCleanedNormals(design.jointAssembly), withCleanedNormals(turnedAssembly)}) {
      const int n = assembly.partCount();
      for (int i = 0; i < n; ++i) {
        std::vector<bool> isFree(n, false);
        isFree[i] = true;
        const MotionSearch withCones = findFreeMotion(assembly, isFree);
        const MotionSearch byGlpk = findFreeMotion(assembly, isFree, glpkAlone());
        EXPECT_EQ(withCones.movable, byGlpk.movable) << name << ", part " << assembly.parts[i].id;
        decidedByCones += withCones.decidedByCones ? 1 : 0;
        ++programs;
      }
      const InterlockingResult withCones = testInterlockingByInequalities(assembly, computeBaseDirections(assembly));
      const InterlockingResult byGlpk =
          testInterlockingByInequalities(assembly, computeBaseDirections(assembly), glpkAlone());
      EXPECT_EQ(verdictName(withCones.verdict), verdictName(byGlpk.verdict)) << name;
      EXPECT_EQ(withCones.verdict, Verdict::Interlocking) << name << ": " << withCones.reason;
      EXPECT_EQ(withCones.key, byGlpk.key) << name;
      EXPECT_EQ(withCones.reason, byGlpk.reason) << name;
    }
  }
  // Every part but the key is blocked in an interlocking assembly.
  EXPECT_GE(decidedByCones, programs * 3 / 4);
  std::cout << "[          ] " << programs << " one-part programs, " << decidedByCones << " decided by cones\n";
}
}  // namespace
}  // namespace desia
