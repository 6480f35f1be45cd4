// SPDX-License-Identifier: GPL-3.0-or-later
// Metamorphic tests of the verdicts (issue 14): turning a design or writing its normals at another
// scale changes nothing a verdict depends on, so every contact document must keep its verdict and
// key under the 24 right-angle rotations (computed with cos/sin, so 1e-17 residues appear as in
// any computed geometry), under random rotations, and with its normals scaled. Documents go
// through the JSON writer and reader as a user's would. The unrotated verdicts themselves are
// pinned by independent means: the DBG test, exact on orthogonal contacts (Section 3.2), and an
// enumeration of each part's free directions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <set>

#include "analysis/linear_program.h"
#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

using Matrix = std::array<Vec3, 3>;

Matrix axisRotation(int axis, int quarterTurns) {
  const double t = quarterTurns * M_PI / 2, c = std::cos(t), s = std::sin(t);
  switch (axis) {
    case 0: return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    case 1: return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
    default: return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  }
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  }
  return r;
}

Vec3 apply(const Matrix& m, const Vec3& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }

// The 24 rotations of the cube, each the product of two quarter-turn rotations in floating point.
std::vector<Matrix> rightAngleRotations() {
  std::vector<Matrix> found;
  std::set<std::array<long, 9>> seen;
  for (int a1 = 0; a1 < 3; ++a1) {
    for (int k1 = 0; k1 < 4; ++k1) {
      for (int a2 = 0; a2 < 3; ++a2) {
        for (int k2 = 0; k2 < 4; ++k2) {
          const Matrix r = multiply(axisRotation(a2, k2), axisRotation(a1, k1));
          std::array<long, 9> key{};
          for (int i = 0; i < 9; ++i) key[i] = std::lround(r[i / 3][i % 3]);
          if (seen.insert(key).second) found.push_back(r);
        }
      }
    }
  }
  return found;
}

// Rotations from random unit quaternions (a fixed linear congruential sequence: the same on every
// platform, unlike the standard library's distributions).
std::vector<Matrix> randomRotations(int count) {
  uint64_t state = 20260101;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2 - 1;
  };
  std::vector<Matrix> rotations;
  while (static_cast<int>(rotations.size()) < count) {
    double q[4] = {next(), next(), next(), next()};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n < 0.1 || n > 1) continue;
    const double a = q[0] / n, b = q[1] / n, c = q[2] / n, d = q[3] / n;
    rotations.push_back({{{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                          {2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)},
                          {2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d}}});
  }
  return rotations;
}

struct Transform {
  std::string name;
  std::function<Vec3(const Vec3&, size_t contact)> normal;
};

std::vector<Transform> transforms() {
  std::vector<Transform> list;
  const std::vector<Matrix> turns = rightAngleRotations();
  EXPECT_EQ(turns.size(), 24u);
  for (size_t i = 0; i < turns.size(); ++i) {
    list.push_back({"right-angle rotation " + std::to_string(i), [r = turns[i]](const Vec3& n, size_t) { return apply(r, n); }});
  }
  const std::vector<Matrix> random = randomRotations(8);
  for (size_t i = 0; i < random.size(); ++i) {
    list.push_back({"random rotation " + std::to_string(i), [r = random[i]](const Vec3& n, size_t) { return apply(r, n); }});
  }
  for (double scale : {1e-6, 1e6, 1e-150, 1e150}) {
    list.push_back({"normals scaled by " + std::to_string(scale), [scale](const Vec3& n, size_t) { return scaled(n, scale); }});
  }
  list.push_back({"each normal at its own scale", [](const Vec3& n, size_t c) { return scaled(n, std::pow(10.0, double(c % 7) * 50 - 150)); }});
  return list;
}

// A contact document turned by `transform`, written as JSON and read back.
AssemblyDocument transformed(const AssemblyDocument& document, const Transform& transform) {
  AssemblyDocument copy = document;
  for (size_t c = 0; c < copy.assembly.contacts.size(); ++c) {
    copy.assembly.contacts[c].normal = transform.normal(copy.assembly.contacts[c].normal, c);
  }
  return parseJsonDocument(documentToJson(copy), transform.name);
}

AssemblyDocument asContactDocument(const AssemblyDocument& voxelDocument, const std::string& name) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Contacts;
  document.name = name;
  document.assembly = voxelDocument.assembly;
  return document;
}

std::string signature(const Assembly& assembly, const InterlockingResult& result) {
  return std::string(verdictName(result.verdict)) + " key=" + (result.key >= 0 ? std::to_string(assembly.parts[result.key].id) : "-");
}

// A motion witness of the LP test is a real motion: no contact pushed into, some part moving.
void ExpectWitnessIsMotion(const Assembly& assembly, const InterlockingResult& result, const std::string& context) {
  if (!result.hasWitness) return;
  std::vector<Vec3> velocity(assembly.partCount(), Vec3{0, 0, 0});
  for (size_t i = 0; i < result.witness.parts.size(); ++i) velocity[result.witness.parts[i]] = result.witness.velocities[i];
  ASSERT_FALSE(result.witness.parts.empty()) << context;
  for (const Contact& contact : assembly.contacts) {
    const Vec3& va = velocity[contact.a];
    const Vec3& vb = velocity[contact.b];
    const double separation = dot({vb[0] - va[0], vb[1] - va[1], vb[2] - va[2]}, contact.normal);
    EXPECT_GE(separation, -1e-6) << context << ": the witness pushes part " << assembly.parts[contact.a].id << " into part "
                                 << assembly.parts[contact.b].id;
  }
}

struct Case {
  std::string name;
  AssemblyDocument document;
};

// Contact documents: the examples, the inputs of issue 14, and the original authors' voxel
// puzzles written as contacts (one per touching pair and axis side), with variants in which a few
// voxels changed hands (mostly not interlocking: a false "interlocking" there is the worst error).
std::vector<Case> contactCases() {
  std::vector<Case> cases;
  for (const char* file : {"examples/contacts/figure4_two_parts_move_at_once.json", "tests/data/contacts/lp_tiny_component_exit3.json",
                           "tests/data/contacts/lp_glpk_abort_1e-200.json", "tests/data/contacts/lp_simplex_cycles.json",
                           "tests/data/contacts/fig4_huge_normal.json"}) {
    cases.push_back({file, parseAssemblyText(testing::readFileText(testing::projectPath(file)), file)});
  }
  // Joint designs of the plate examples as `desia design plate` writes them: the table's cut joints
  // (contacts of the jointed plates) and planned joints (the joint model's contacts), the
  // 45-degree mitres of the box among them.
  const std::vector<std::pair<const char*, JointRealization>> plateCases{
      {"examples/plate/table.json", JointRealization::Cut},
      {"examples/plate/table.json", JointRealization::Planned},
      {"examples/plate/mitred_box.json", JointRealization::Planned},
      {"examples/plate/bookshelf.json", JointRealization::Planned},
      {"examples/plate/cabinet.json", JointRealization::Planned}};
  for (const auto& [file, realization] : plateCases) {
    const AssemblyDocument design = parseAssemblyText(testing::readFileText(testing::projectPath(file)), file);
    PlateDesignOptions options;
    options.realization = realization;
    const PlateDesignResult plan = designPlateJoints(design.plates, computePlateContacts(design.plates, design.plateOptions), options);
    AssemblyDocument document = parseJsonDocument(plateDesignToJson(design, plan), std::string(file) + " plan");
    document.plates.clear();  // keep it a contact document: the transforms turn its normals
    document.plateResult.reset();  // and its plan: the transforms would turn the contacts, not the plan
    document.fabricationPlates.clear();
    cases.push_back({std::string(file) + " plan (" + jointRealizationName(realization) + ")", document});
  }
  std::mt19937 random(14);
  for (const char* file : {"result_puz/Cube_4x4x4_K9_01.puz", "result_puz/Cube_Hollow_4x4x4_K7", "result_puz/Cube_4x4x4_K9.puz",
                           "result_puz/cube_5x5x5_K16.puz", "result_puz/cartoon_dog.puz"}) {
    const AssemblyDocument puzzle = testing::loadReference(file);
    cases.push_back({file, asContactDocument(puzzle, file)});
    for (int variant = 0; variant < 3; ++variant) {
      VoxelGrid grid = puzzle.voxels;
      for (int trades = 0, attempt = 0; trades < 1 + variant && attempt < 500; ++attempt) trades += testing::tradeOneVoxel(grid, random) ? 1 : 0;
      const std::string name = std::string(file) + " variant " + std::to_string(variant);
      cases.push_back({name, asContactDocument(documentFromVoxels(grid), name)});
    }
  }
  return cases;
}

// On orthogonal contacts the DBG test is exact: the unrotated LP verdict must be the DBG's.
bool isOrthogonal(const Assembly& assembly) { return hasOnlyAxisAlignedContacts(assembly); }

TEST(VerdictRobustness, EveryContactDocumentKeepsItsVerdictWhenTurnedOrScaled) {
  CheckOptions options;
  options.method = CheckMethod::Both;
  options.planDisassembly = false;
  const std::vector<Transform> turns = transforms();
  int interlocking = 0, notInterlocking = 0, checked = 0;
  for (const Case& item : contactCases()) {
    const CheckReport base = checkAssembly(item.document, options);
    const Assembly& assembly = item.document.assembly;
    const std::string lpBase = signature(assembly, *base.inequalityResult);
    const std::string dbgBase = signature(assembly, *base.graphResult);
    if (isOrthogonal(assembly)) {
      EXPECT_EQ(lpBase, dbgBase) << item.name << ": the LP test disagrees with the exact DBG test";
    }
    ExpectWitnessIsMotion(assembly, *base.inequalityResult, item.name);
    (base.inequalityResult->verdict == Verdict::Interlocking ? interlocking : notInterlocking) += 1;
    for (const Transform& transform : turns) {
      const AssemblyDocument turned = transformed(item.document, transform);
      CheckReport report;
      ASSERT_NO_THROW(report = checkAssembly(turned, options)) << item.name << ", " << transform.name;
      EXPECT_EQ(signature(turned.assembly, *report.inequalityResult), lpBase) << item.name << ", " << transform.name << " (lp)\n"
                                                                             << report.inequalityResult->reason;
      EXPECT_EQ(signature(turned.assembly, *report.graphResult), dbgBase) << item.name << ", " << transform.name << " (dbg)\n"
                                                                          << report.graphResult->reason;
      ExpectWitnessIsMotion(turned.assembly, *report.inequalityResult, item.name + ", " + transform.name);
      ++checked;
    }
  }
  // The cases cover both outcomes, so a test that always said one thing would fail.
  EXPECT_GE(interlocking, 5);
  EXPECT_GE(notInterlocking, 10);
  EXPECT_GE(checked, 37 * 28);
}

// The file comment of inequality_interlocking.cpp claims that the certified floating-point route
// and the exact rational simplex answer one question; here every program goes the exact way.
TEST(VerdictRobustness, ExactSimplexAloneGivesTheSameVerdictsAsTheCertifiedRoute) {
  int compared = 0;
  for (const Case& item : contactCases()) {
    const Assembly& assembly = item.document.assembly;
    if (assembly.partCount() > 10) continue;  // the rational simplex is slow; small cases suffice
    const std::vector<BaseDirection> directions = computeBaseDirections(assembly);
    const InterlockingResult certified = testInterlockingByInequalities(assembly, directions);
    const InterlockingResult exact = testInterlockingByInequalities(assembly, directions, {/*exactOnly=*/true});
    EXPECT_EQ(signature(assembly, exact), signature(assembly, certified)) << item.name << "\nexact: " << exact.reason
                                                                          << "\ncertified: " << certified.reason;
    ExpectWitnessIsMotion(assembly, exact, item.name + " (exact)");
    for (const Matrix& rotation : randomRotations(2)) {
      const AssemblyDocument turned = transformed(item.document, {"turned", [&](const Vec3& n, size_t) { return apply(rotation, n); }});
      const InterlockingResult turnedExact = testInterlockingByInequalities(turned.assembly, computeBaseDirections(turned.assembly), {true});
      EXPECT_EQ(signature(turned.assembly, turnedExact), signature(assembly, certified)) << item.name << " turned (exact)";
    }
    ++compared;
  }
  EXPECT_GE(compared, 15);
}

// An independent answer to round 1 of the LP test: a part alone is free iff some direction d has
// d·m <= 0 for all its oriented normals m; such a d, if any, lies where two contact planes meet,
// along a reversed normal, or (normals all parallel) in the plane orthogonal to them.
bool freeAloneByEnumeration(const Assembly& assembly, int part) {
  std::vector<Vec3> oriented;
  for (const Contact& contact : assembly.contacts) {
    if (contact.a == part) oriented.push_back(contact.normal);
    if (contact.b == part) oriented.push_back(negated(contact.normal));
  }
  std::vector<Vec3> candidates{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (size_t i = 0; i < oriented.size(); ++i) {
    candidates.push_back(negated(oriented[i]));
    candidates.push_back(cross(oriented[i], {1, 0, 0}));
    candidates.push_back(cross(oriented[i], {0, 1, 0}));
    for (size_t j = i + 1; j < oriented.size(); ++j) candidates.push_back(cross(oriented[i], oriented[j]));
  }
  for (const Vec3& c : candidates) {
    if (norm(c) < 1e-9) continue;
    for (const Vec3& d : {normalized(c), negated(normalized(c))}) {
      bool free = true;
      for (const Vec3& m : oriented) free = free && dot(d, m) <= 1e-9;
      if (free) return true;
    }
  }
  return false;
}

TEST(VerdictRobustness, PartsFreeAloneMatchAnEnumerationOfDirections) {
  for (const Case& item : contactCases()) {
    const Assembly& assembly = item.document.assembly;
    for (int part = 0; part < assembly.partCount(); ++part) {
      std::vector<bool> isFree(assembly.partCount(), false);
      isFree[part] = true;
      EXPECT_EQ(findFreeMotion(assembly, isFree).movable, freeAloneByEnumeration(assembly, part))
          << item.name << ", part " << assembly.parts[part].id;
    }
  }
}

TEST(VerdictRobustness, HostileDocumentsOfIssue14GetVerdictsNotErrors) {
  // Each made GLPK fail, abort or cycle; each has two parts free alone (the enumeration agrees).
  for (const char* file : {"tests/data/contacts/lp_tiny_component_exit3.json", "tests/data/contacts/lp_glpk_abort_1e-200.json",
                           "tests/data/contacts/lp_simplex_cycles.json"}) {
    const AssemblyDocument document = parseAssemblyText(testing::readFileText(testing::projectPath(file)), file);
    for (CheckMethod method : {CheckMethod::Inequalities, CheckMethod::Both}) {
      CheckOptions options;
      options.method = method;
      const CheckReport report = checkAssembly(document, options);
      const InterlockingResult& lp = *report.inequalityResult;
      EXPECT_EQ(report.result.verdict, Verdict::NotInterlocking) << file << ": " << report.result.reason;
      EXPECT_NE(lp.reason.find("more than one part can move alone"), std::string::npos) << file << ": " << lp.reason;
    }
    int freeAlone = 0;
    for (int part = 0; part < document.assembly.partCount(); ++part) freeAlone += freeAloneByEnumeration(document.assembly, part) ? 1 : 0;
    EXPECT_GE(freeAlone, 2) << file;
  }
}

TEST(VerdictRobustness, HugeNormalsMeanTheSameAsUnitOnes) {
  const AssemblyDocument huge =
      parseAssemblyText(testing::readFileText(testing::projectPath("tests/data/contacts/fig4_huge_normal.json")), "huge");
  const AssemblyDocument unit = parseAssemblyText(
      testing::readFileText(testing::projectPath("examples/contacts/figure4_two_parts_move_at_once.json")), "fig4");
  ASSERT_EQ(huge.assembly.contacts.size(), unit.assembly.contacts.size());
  EXPECT_EQ(huge.assembly.contacts[0].normal, (Vec3{0, 1, 0}));
  for (CheckMethod method : {CheckMethod::Graphs, CheckMethod::Inequalities}) {
    CheckOptions options;
    options.method = method;
    EXPECT_EQ(checkAssembly(huge, options).result.verdict, checkAssembly(unit, options).result.verdict);
  }
  const Vec3 diagonal = cleanedNormal({1e300, 1e300, 0}).value();
  EXPECT_NEAR(diagonal[0], std::sqrt(0.5), 1e-15);
  EXPECT_EQ(diagonal[0], diagonal[1]);
  EXPECT_EQ(diagonal[2], 0.0);
  EXPECT_EQ(cleanedNormal({6.123233995736766e-17, -1, 1e-200}).value(), (Vec3{0, -1, 0}));
  EXPECT_FALSE(cleanedNormal({0, 0, 0}).has_value());
  EXPECT_FALSE(cleanedNormal({NAN, 1, 0}).has_value());
}

TEST(VerdictRobustness, DeeplyNestedDocumentsAreRefusedWithThePath) {
  for (const auto& [section, open, inner, close] :
       std::vector<std::array<std::string, 4>>{{"plates", "[", "", "]"}, {"frame", "{\"a\":", "1", "}"}}) {
    std::string text = "{\"kind\":\"" + std::string(section == "plates" ? "plate" : "frame") +
                       "\",\"parts\":[{\"id\":1}],\"contacts\":[],\"" + section + "\":";
    for (int i = 0; i < 100000; ++i) text += open;
    text += inner;
    for (int i = 0; i < 100000; ++i) text += close;
    text += "}";
    try {
      parseAssemblyText(text, "deep.json");
      ADD_FAILURE() << section << ": a document nested 100,000 levels deep was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::BadInput);
      EXPECT_NE(std::string(e.what()).find("deep.json:1:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(section), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("nested more than 256 levels"), std::string::npos) << e.what();
    }
  }
  // 200 levels are fine (the limit is not a guess at what documents need).
  std::string text = "{\"kind\":\"contacts\",\"parts\":[{\"id\":1}],\"contacts\":[],\"plates\":";
  for (int i = 0; i < 200; ++i) text += "[";
  for (int i = 0; i < 200; ++i) text += "]";
  EXPECT_NO_THROW(parseAssemblyText(text + "}", "ok.json"));
}

}  // namespace
}  // namespace desia

namespace desia {
namespace {

// maximize x subject to x - y >= 0 and x, y in [-1, 1]: optimum 1 at x = y = 1.
LinearProgramSpec smallProgram() {
  LinearProgramSpec spec;
  spec.addColumn(-1, 1, 1);
  spec.addColumn(-1, 1, 0);
  spec.rowLower.push_back(0);
  spec.addEntry(0, 0, 1);
  spec.addEntry(0, 1, -1);
  return spec;
}

TEST(LinearProgramGuard, GlpkErrorsComeBackAsFailuresAndGlpkKeepsWorking) {
  // A duplicate matrix entry makes GLPK call its error hook (it would abort the process); a
  // 1e-250 coefficient used to make its scaling abort ("invalid scale factor").
  LinearProgramSpec duplicate = smallProgram();
  duplicate.addEntry(0, 0, 2);
  LinearProgramSpec tiny = smallProgram();
  tiny.entryValue[1] = -1e-250;
  for (SimplexMethod method : {SimplexMethod::Dual, SimplexMethod::Primal, SimplexMethod::ExactRational}) {
    const LinearProgramSolution failed = solveLinearProgram(duplicate, method);
    EXPECT_FALSE(failed.optimal);
    EXPECT_EQ(failed.failure, "GLPK reported an error");
    const LinearProgramSolution fine = solveLinearProgram(smallProgram(), method);
    ASSERT_TRUE(fine.optimal) << fine.failure;
    EXPECT_EQ(fine.objectiveValue, 1.0);
    EXPECT_NO_FATAL_FAILURE(solveLinearProgram(tiny, method));
  }
}

TEST(LinearProgramGuard, ExactSimplexSolvesTheRelaxedRowsExactly) {
  LinearProgramSpec spec = smallProgram();
  spec.columnUpper[1] = 0.25;  // x - y >= -1e-12 with y <= 0.25: x stays bounded by 1 anyway
  spec.objective = {0, 1};     // maximize y
  spec.rowLower[0] = -0.5;     // x >= y - 0.5, x <= 1: y <= 0.25 binds first
  const LinearProgramSolution exact = solveLinearProgram(spec, SimplexMethod::ExactRational);
  ASSERT_TRUE(exact.optimal) << exact.failure;
  EXPECT_EQ(exact.objectiveValue, 0.25);
}

// Three independent groups of 4,500 rows each (rows interleaved), as axis-aligned contacts make
// them, and a few columns in no row: the solver splits such programs into blocks. Whatever it
// does, its answer must be optimal for the whole program, which is checked here independently of
// GLPK: the columns satisfy every row and bound and reach the objective value, and the row duals
// bound the objective from above by the same value (weak duality: c·x <= Σ|c + Aᵀy| for y >= 0).
TEST(LinearProgramGuard, AProgramOfIndependentBlocksIsSolvedOptimallyAsAWhole) {
  constexpr int kGroups = 3, kColumnsPerGroup = 1500, kRowsPerGroup = 4500, kLooseColumns = 7;
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> weight(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, kColumnsPerGroup - 1);
  LinearProgramSpec spec;
  for (int j = 0; j < kGroups * kColumnsPerGroup + kLooseColumns; ++j) spec.addColumn(-1, 1, weight(random));
  for (int r = 0; r < kGroups * kRowsPerGroup; ++r) {
    const int group = r % kGroups;
    const int a = group * kColumnsPerGroup + pick(random);
    int b = group * kColumnsPerGroup + pick(random);
    if (b == a) b = group * kColumnsPerGroup + (pick(random) + 1) % kColumnsPerGroup;
    if (b == a) continue;
    spec.rowLower.push_back(0.0);
    const int row = spec.rowCount() - 1;
    spec.addEntry(row, a, 1.0);
    spec.addEntry(row, b, r % 5 == 0 ? -0.5 : -1.0);  // not only difference constraints
  }
  for (SimplexMethod method : {SimplexMethod::Dual, SimplexMethod::Primal}) {
    LinearProgramSolution solution = solveLinearProgram(spec, method);
    ASSERT_TRUE(solution.optimal) << solution.failure;
    std::vector<double> rowValue(spec.rowCount(), 0.0);
    for (size_t k = 0; k < spec.entryValue.size(); ++k)
      rowValue[spec.entryRow[k]] += spec.entryValue[k] * solution.columnValues[spec.entryColumn[k]];
    for (int r = 0; r < spec.rowCount(); ++r) ASSERT_GE(rowValue[r], spec.rowLower[r] - 1e-9) << "row " << r;
    double value = 0;
    for (int j = 0; j < spec.columnCount(); ++j) {
      ASSERT_LE(std::abs(solution.columnValues[j]), 1.0 + 1e-12);
      value += spec.objective[j] * solution.columnValues[j];
    }
    EXPECT_NEAR(value, solution.objectiveValue, 1e-6);
    double bestBound = HUGE_VAL;
    for (double sign : {1.0, -1.0}) {
      std::vector<double> reduced = spec.objective;
      for (size_t k = 0; k < spec.entryValue.size(); ++k)
        reduced[spec.entryColumn[k]] += spec.entryValue[k] * std::max(0.0, sign * solution.rowDuals[spec.entryRow[k]]);
      double bound = 0;
      for (double c : reduced) bound += std::abs(c);
      bestBound = std::min(bestBound, bound);
    }
    EXPECT_NEAR(bestBound, value, 1e-6) << "the row duals do not prove the columns optimal";
    EXPECT_GT(value, 1.0);  // the loose columns alone reach their weights
  }
}

// Motion-like programs (rows of a few entries >= 0, velocities in [-1, 1]) solved for one objective,
// then for another from the first one's basis: the same optimum as a solve from scratch. A basis
// of the wrong size, every row and column declared basic (too many basic variables), or a status
// GLPK does not know: solved from scratch instead, still optimal.
TEST(LinearProgramGuard, ASolveFromAnotherObjectivesBasisReachesTheSameOptimum) {
  std::mt19937 random(27);
  std::uniform_real_distribution<double> weight(-1.0, 1.0);
  int warmStarts = 0;
  for (int trial = 0; trial < 60; ++trial) {
    LinearProgramSpec clean;
    const int columns = 6 + trial % 30, rows = 3 * columns;
    for (int j = 0; j < columns; ++j) clean.addColumn(-1, 1, weight(random));
    std::uniform_int_distribution<int> column(0, columns - 1);
    for (int r = 0; r < rows; ++r) {
      clean.rowLower.push_back(0.0);
      std::set<int> used;  // GLPK refuses a row with the same column twice
      for (int k = 0; k < 2 + r % 3; ++k) {
        const int j = column(random);
        if (used.insert(j).second) clean.addEntry(r, j, weight(random));
      }
    }
    const LinearProgramSolution first = solveLinearProgram(clean, SimplexMethod::Dual);
    ASSERT_TRUE(first.optimal) << first.failure;
    ASSERT_EQ(first.basis.rowStatus.size(), static_cast<size_t>(clean.rowCount()));
    for (double& c : clean.objective) c = weight(random);
    const LinearProgramSolution cold = solveLinearProgram(clean, SimplexMethod::Dual);
    ASSERT_TRUE(cold.optimal) << cold.failure;
    LinearProgramBasis wrongSize = first.basis;
    wrongSize.rowStatus.pop_back();
    LinearProgramBasis allBasic = first.basis;
    std::fill(allBasic.rowStatus.begin(), allBasic.rowStatus.end(), 1);  // GLP_BS
    std::fill(allBasic.columnStatus.begin(), allBasic.columnStatus.end(), 1);
    LinearProgramBasis unknown = first.basis;
    unknown.columnStatus[0] = 99;
    for (const LinearProgramBasis* start : std::array<const LinearProgramBasis*, 4>{&first.basis, &wrongSize, &allBasic, &unknown}) {
      const LinearProgramSolution warm = solveLinearProgramFrom(clean, SimplexMethod::Dual, *start);
      ASSERT_TRUE(warm.optimal) << "trial " << trial << ": " << warm.failure;
      if (start == &first.basis) {
        warmStarts += warm.fromBasis ? 1 : 0;
      } else {  // refused before GLPK runs (size), by glp_simplex (a singular basis) or by its error hook
        EXPECT_FALSE(warm.fromBasis) << "trial " << trial;
      }
      EXPECT_NEAR(warm.objectiveValue, cold.objectiveValue, 1e-9) << "trial " << trial;
      std::vector<double> rowValue(clean.rowCount(), 0.0);
      for (size_t k = 0; k < clean.entryValue.size(); ++k)
        rowValue[clean.entryRow[k]] += clean.entryValue[k] * warm.columnValues[clean.entryColumn[k]];
      for (int r = 0; r < clean.rowCount(); ++r) ASSERT_GE(rowValue[r], -1e-9) << "trial " << trial << ", row " << r;
    }
  }
  EXPECT_EQ(warmStarts, 60);
}

}  // namespace
}  // namespace desia
