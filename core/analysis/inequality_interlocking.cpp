// Inequality-based interlocking test (paper Section 3.2, Eq. 2), solved with GLPK.
//
// Two departures from the paper's recipe make the test exact for any contact normals:
// - Eq. 2 only finds motions that separate some contact; motions that slide along every contact
//   (all t_ij = 0 but v != 0: a part in a slot, free along the slot) need a second look, here two
//   LPs maximizing a generic linear functional of the velocities.
// - Round 2 fixes only a reference part, not the key: fixing both freezes any motion that
//   separates a group holding the reference from a group holding the key and other parts, and
//   such an assembly would pass. The key may move; a motion counts when another part moves.
//
// And one makes its verdicts trustworthy on computed normals. Normals computed in
// floating point (a rotation, a cross product) carry 1e-16 errors, and an exact answer on such
// data can differ from the answer the geometry means: three normals of a planar design turned by
// a rotation no longer lie exactly in one plane, so the motion normal to that plane disappears.
// The question every program answers is therefore posed with a tolerance, the same kind of
// tolerance the blocking graphs use (a contact blocks d when d·n exceeds a tolerance):
//
//     is there a motion v, |v_j| <= 1, that penetrates no contact by more than kPenetration
//     ((v_b - v_a)·n >= -kPenetration) and makes the program's objective reach kMotion?
//
// GLPK's floating-point simplex proposes an answer and the answer is accepted only with a
// certificate checked here against every contact: a motion is checked directly, "no motion" by
// weak duality (any y >= 0 bounds the objective over all such motions by Σ|c + Aᵀy| + kPenetration
// Σy). When neither certificate holds (GLPK failed, hit its limits, or was imprecise), the same
// question is decided by GLPK's exact rational simplex on the relaxed rows. The three routes
// answer one well-defined question, so the verdict does not depend on which one decided.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

#include "analysis/linear_program.h"
#include "analysis/motion_certificates.h"
#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/error.h"
#include "desia/model.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

using inequality::certifiesMotion;
using inequality::certifiesNoMotion;
using inequality::coneNoMotionDuals;
using inequality::DifferenceGraph;
using inequality::differenceGraph;
using inequality::graphCertifiesNoMotion;
using inequality::graphMotion;
using inequality::objectiveAt;

// How far a motion of unit speed may push into a contact and still count as sliding along it, and
// the objective a motion must reach (velocities are bounded by 1): desia/tolerances.h.
using tolerance::kMotion;
using tolerance::kPenetration;

// Contacts that involve at least one free part; with both sides fixed a contact says nothing.
std::vector<int> relevantContacts(const Assembly& assembly, const std::vector<bool>& isFree) {
  std::vector<int> relevant;
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    const Contact& contact = assembly.contacts[c];
    if (isFree[contact.a] || isFree[contact.b]) relevant.push_back(c);
  }
  return relevant;
}

// Column of each free part's x velocity (y and z follow), or -1 for a fixed part.
std::vector<int> velocityColumns(const std::vector<bool>& isFree, int* columnCount) {
  std::vector<int> column(isFree.size(), -1);
  int next = 0;
  for (size_t i = 0; i < isFree.size(); ++i) {
    if (isFree[i]) {
      column[i] = next;
      next += 3;
    }
  }
  *columnCount = next;
  return column;
}

// What one linear program looks for: a motion of the free parts (fixed parts have v = 0) in which
// some watched part moves. Watched parts are free; a free part that is not watched (the key in
// round 2) may move along to make room but does not count as a motion by itself.
struct MotionQuery {
  std::vector<bool> isFree;
  std::vector<bool> isWatched;
  bool exactOnly = false;  // skip the floating-point simplex (tests: the routes must agree)
  bool graphCertificates = true;  // let graph algorithms propose answers first (see below)
  bool coneCertificates = true;   // let the cone search certify "no motion" of one part first
  // The contacts that touch a free part, in index order, when the caller knows them (round 1:
  // one part's own contacts, instead of a scan of every contact per part).
  const std::vector<int>* contacts = nullptr;
};

enum class Objective {
  SeparatingContacts,  // Eq. 2's question: can a contact between watched or fixed parts separate?
  GenericFunctional,   // max Σ c_i·v_i over watched parts, for a fixed generic c (see below)
};

// Deterministic "generic" weights in ±[0.5, 1.5]: a non-zero cone of motions projected on the
// watched velocities is orthogonal to such a vector only with probability zero, so max c·v > 0
// or max -c·v > 0 exactly when a watched part can move, sliding motions included (where every
// t_c of Eq. 2 stays 0). A small linear congruential sequence keeps native and WebAssembly equal.
std::vector<double> genericWeights(int count) {
  std::vector<double> weights(count);
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (double& w : weights) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
    w = ((state >> 7) & 1 ? 1.0 : -1.0) * (0.5 + unit);
  }
  return weights;
}

bool involvesUnwatchedFreePart(const Contact& contact, const MotionQuery& query) {
  auto unwatchedFree = [&](int part) { return query.isFree[part] && !query.isWatched[part]; };
  return unwatchedFree(contact.a) || unwatchedFree(contact.b);
}

// One motion program: a row s_c = (v_b - v_a)·n_c >= 0 per contact that touches a free part,
// velocities bounded to [-1, 1] (scaling keeps a motion a motion).
//
// Eq. 2 maximizes Σ t_c with t_c <= s_c and 0 <= t_c <= 1; its optimum is positive exactly when
// some s_c can be positive. Maximizing Σ s_c over the same constraints answers the same question
// without the t columns (3N instead of 3N + C variables), and GLPK gets there in far fewer
// pivots (seconds fewer on an assembly of a thousand parts that falls apart).
struct MotionProgram {
  LinearProgramSpec spec;           // rows and columns; the objective is set per question
  std::vector<int> velocityColumn;  // per part, -1 when fixed
  std::vector<double> separation;   // Eq. 2's objective: Σ s_c over contacts between watched or fixed parts
  std::vector<double> functional;   // the generic weights on the watched velocities (0 elsewhere)
};

// The rows are the same for every question asked of one query, so they are built once.
MotionProgram buildMotionProgram(const Assembly& assembly, const MotionQuery& query) {
  MotionProgram program;
  int velocityCount = 0;
  program.velocityColumn = velocityColumns(query.isFree, &velocityCount);
  program.separation.assign(velocityCount, 0.0);
  program.functional.assign(velocityCount, 0.0);
  const std::vector<double> weights = genericWeights(velocityCount);
  for (int part = 0; part < assembly.partCount(); ++part) {
    if (!query.isWatched[part]) continue;
    for (int k = 0; k < 3; ++k) {
      const int column = program.velocityColumn[part] + k;
      program.functional[column] = weights[column];
    }
  }
  LinearProgramSpec& spec = program.spec;
  for (int c : query.contacts ? *query.contacts : relevantContacts(assembly, query.isFree)) {
    const Contact& contact = assembly.contacts[c];
    const int row = spec.rowCount();
    spec.rowLower.push_back(0.0);
    const bool separationCounts = !involvesUnwatchedFreePart(contact, query);
    for (const auto& [part, sign] : {std::pair<int, double>{contact.b, 1.0}, std::pair<int, double>{contact.a, -1.0}}) {
      if (program.velocityColumn[part] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        const int column = program.velocityColumn[part] + k;
        spec.addEntry(row, column, sign * contact.normal[k]);
        if (separationCounts) program.separation[column] += sign * contact.normal[k];
      }
    }
  }
  for (int j = 0; j < velocityCount; ++j) spec.addColumn(-1.0, 1.0, 0.0);
  return program;
}

void setObjective(MotionProgram* program, Objective objective, double functionalSign) {
  std::vector<double>& cost = program->spec.objective;
  for (size_t j = 0; j < cost.size(); ++j) {
    cost[j] = objective == Objective::SeparatingContacts ? program->separation[j] : functionalSign * program->functional[j];
  }
}

MotionSearch motionFrom(const Assembly& assembly, const MotionProgram& program, const std::vector<double>& x) {
  MotionSearch search;
  search.movable = true;
  search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  for (int i = 0; i < assembly.partCount(); ++i) {
    if (program.velocityColumn[i] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const double v = x[program.velocityColumn[i] + k];
      search.velocities[i][k] = std::abs(v) < tolerance::kVelocityNoise ? 0.0 : v;
    }
  }
  return search;
}

// Decides one motion program (see the file comment): graph certificates when the rows allow them,
// a cone certificate of "no motion" when one part is free, then GLPK's dual simplex, then its primal simplex, each accepted only with a checked
// certificate, then the exact rational simplex.
MotionSearch decideMotionProgram(const Assembly& assembly, const MotionQuery& query, MotionProgram program,
                                 const DifferenceGraph* graph, LinearProgramBasis* basis) {
  const MotionSearch none;  // no velocities: findFreeMotion fills in the zeros
  if (program.spec.columnCount() == 0) return none;
  if (graph && !query.exactOnly) {
    MotionSearch decided;
    if (auto x = graphMotion(*graph, program.spec)) {
      decided = motionFrom(assembly, program, *x);
    } else if (!graphCertifiesNoMotion(*graph, program.spec)) {
      graph = nullptr;  // neither certificate: GLPK decides
    }
    if (graph) {
      decided.decidedByGraphs = true;
      return decided;
    }
  }
  if (query.coneCertificates && !query.exactOnly && coneNoMotionDuals(program.spec)) {
    MotionSearch decided;
    decided.decidedByCones = true;
    return decided;
  }
  std::string failures;
  // From the last objective's basis first when there is one; then, as for the first objective,
  // GLPK's dual simplex with its presolver and its primal simplex, each a differently-pivoting opinion.
  struct Attempt {
    SimplexMethod method;
    bool fromBasis;
  };
  std::vector<Attempt> attempts;
  if (!basis->empty()) attempts.push_back({SimplexMethod::Dual, true});
  attempts.push_back({SimplexMethod::Dual, false});
  attempts.push_back({SimplexMethod::Primal, false});
  for (const Attempt& attempt : attempts) {
    if (query.exactOnly) break;
    LinearProgramSolution solution = attempt.fromBasis ? solveLinearProgramFrom(program.spec, attempt.method, *basis)
                                                       : solveLinearProgram(program.spec, attempt.method);
    if (solution.optimal && !solution.basis.empty()) *basis = solution.basis;
    if (!solution.optimal) {
      failures += (failures.empty() ? "" : "; ") + solution.failure;
      continue;
    }
    if (certifiesMotion(program.spec, &solution.columnValues)) return motionFrom(assembly, program, solution.columnValues);
    if (certifiesNoMotion(program.spec, solution.rowDuals)) return none;
  }
  for (double& lower : program.spec.rowLower) lower = -kPenetration;
  LinearProgramSolution exact = solveLinearProgram(program.spec, SimplexMethod::ExactRational);
  if (!exact.optimal) {
    throw Error(ErrorCode::TooLarge,
                "the inequality test could not decide a linear program of " + std::to_string(program.spec.rowCount()) +
                    " contacts and " + std::to_string(program.spec.columnCount()) + " velocities within its limits (" +
                    failures + "; exact simplex: " + exact.failure + "); use --method dbg");
  }
  if (exact.objectiveValue < kMotion) return none;
  return motionFrom(assembly, program, exact.columnValues);
}

// Is there a motion in which a watched part moves? Eq. 2's question first (its solution separates contacts,
// the clearest witness), then the generic functional in both signs for sliding motions.
MotionSearch findWatchedMotion(const Assembly& assembly, const MotionQuery& query) {
  MotionProgram program = buildMotionProgram(assembly, query);
  std::optional<DifferenceGraph> graph;
  if (query.graphCertificates && !query.exactOnly) graph = differenceGraph(program.spec);
  const DifferenceGraph* graphOrNull = graph ? &*graph : nullptr;
  setObjective(&program, Objective::SeparatingContacts, 1.0);
  // The three programs share their rows: each GLPK solve starts from the last one's basis.
  LinearProgramBasis basis;
  MotionSearch search = decideMotionProgram(assembly, query, program, graphOrNull, &basis);
  bool byGraphs = search.decidedByGraphs;
  bool byCones = search.decidedByCones;
  for (double sign : {1.0, -1.0}) {
    if (search.movable) break;
    setObjective(&program, Objective::GenericFunctional, sign);
    search = decideMotionProgram(assembly, query, program, graphOrNull, &basis);
    byGraphs = byGraphs && search.decidedByGraphs;
    byCones = byCones && search.decidedByCones;
  }
  search.decidedByGraphs = byGraphs;
  search.decidedByCones = byCones;
  return search;
}

// The parts that really take part in a motion: speeds within three orders of magnitude of the
// fastest (the tolerated penetration lets the others creep by kPenetration).
std::vector<int> movingParts(const MotionSearch& search) {
  double fastest = 0;
  for (const Vec3& v : search.velocities) fastest = std::max(fastest, norm(v));
  std::vector<int> parts;
  for (int i = 0; i < static_cast<int>(search.velocities.size()); ++i) {
    if (norm(search.velocities[i]) > tolerance::kMovingSpeedFraction * fastest) parts.push_back(i);
  }
  return parts;
}

Witness witnessFromMotion(const MotionSearch& search) {
  Witness witness;
  witness.parts = movingParts(search);
  bool common = !witness.parts.empty();
  Vec3 first = witness.parts.empty() ? Vec3{0, 0, 0} : normalized(search.velocities[witness.parts[0]]);
  for (int part : witness.parts) {
    Vec3 v = normalized(search.velocities[part]);
    witness.velocities.push_back(v);
    if (norm({v[0] - first[0], v[1] - first[1], v[2] - first[2]}) > tolerance::kSameVelocityDirection) common = false;
  }
  if (common) witness.direction = directionLabel(first);
  return witness;
}

std::string describeMotion(const Assembly& assembly, const Witness& witness) {
  std::ostringstream out;
  out << "part" << (witness.parts.size() > 1 ? "s " : " ");
  for (size_t i = 0; i < witness.parts.size(); ++i) out << (i ? ", " : "") << assembly.parts[witness.parts[i]].id;
  if (!witness.direction.empty()) {
    out << " can move along " << witness.direction;
  } else {
    out << " can move at once in different directions";
  }
  return out.str();
}

// Base directions (both signs) along which the part alone is free.
std::vector<Vec3> freeDirectionsOfPart(const Assembly& assembly, const std::vector<BaseDirection>& directions, int part) {
  std::vector<int> touching;
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    if (assembly.contacts[c].a == part || assembly.contacts[c].b == part) touching.push_back(c);
  }
  std::vector<Vec3> free;
  for (const BaseDirection& base : directions) {
    for (const Vec3& d : {base.vector, negated(base.vector)}) {
      bool blocked = false;
      for (int c : touching) {
        const Contact& contact = assembly.contacts[c];
        const double along = dot(d, contact.normal);
        if ((contact.a == part && along > tolerance::kDirection) ||
            (contact.b == part && along < -tolerance::kDirection)) {
          blocked = true;
          break;
        }
      }
      if (!blocked) free.push_back(d);
    }
  }
  return free;
}

InterlockingResult testWithCleanNormals(const Assembly& assembly, const std::vector<BaseDirection>& directions,
                                        const InequalityOptions& options) {
  const int n = assembly.partCount();
  InterlockingResult result;
  if (n < 3) {
    result.reason = "an interlocking assembly needs at least three parts; this one has " + std::to_string(n);
    return result;
  }
  // Round 1: which parts can move alone? The verdict names at most the first two.
  const PartsMovableAlone alone = findPartsMovableAlone(assembly, options, 2);
  const std::vector<int>& movableAlone = alone.parts;
  const std::vector<MotionSearch>& motions = alone.motions;
  if (movableAlone.size() > 1) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(motions[1]);
    result.reason = "more than one part can move alone (parts " + std::to_string(assembly.parts[movableAlone[0]].id) +
                    " and " + std::to_string(assembly.parts[movableAlone[1]].id) + "): " +
                    describeMotion(assembly, result.witness);
    return result;
  }
  // Round 2: fix a reference part other than the key; the key may move, but no other part may.
  const int key = movableAlone.empty() ? -1 : movableAlone[0];
  const int reference = key == 0 ? 1 : 0;
  MotionQuery query{std::vector<bool>(n, true), std::vector<bool>(n, true), options.exactOnly,
                    options.graphCertificates, options.coneCertificates};
  query.isFree[reference] = query.isWatched[reference] = false;
  if (key >= 0) query.isWatched[key] = false;
  const MotionSearch search = findWatchedMotion(assembly, query);
  if (search.movable) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(search);
    result.reason = (key >= 0 ? "besides the key, " : "") + describeMotion(assembly, result.witness);
    return result;
  }
  if (key < 0) return deadlockedResult("the linear program admits no motion: no part or part group can move");
  std::vector<Vec3> keyDirections = freeDirectionsOfPart(assembly, directions, key);
  if (keyDirections.empty()) keyDirections.push_back(normalized(motions[0].velocities[key]));
  return interlockingResult(assembly, key, std::move(keyDirections));
}

}  // namespace

MotionSearch findFreeMotion(const Assembly& assembly, const std::vector<bool>& isFree, const InequalityOptions& options) {
  MotionSearch search = findWatchedMotion(assembly, {isFree, isFree, options.exactOnly, options.graphCertificates, options.coneCertificates});
  if (search.velocities.empty()) search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  return search;
}

MotionSearch findMotionOfWatchedParts(const Assembly& assembly, const std::vector<bool>& isFree,
                                      const std::vector<bool>& isWatched, const InequalityOptions& options) {
  MotionSearch search = findWatchedMotion(assembly, {isFree, isWatched, options.exactOnly, options.graphCertificates, options.coneCertificates});
  if (search.velocities.empty()) search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  return search;
}

PartsMovableAlone findPartsMovableAlone(const Assembly& assembly, const InequalityOptions& options, int enough) {
  const int n = assembly.partCount();
  std::vector<std::vector<int>> contactsOf(n);
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    const Contact& contact = assembly.contacts[c];
    contactsOf[contact.a].push_back(c);
    if (contact.b != contact.a) contactsOf[contact.b].push_back(c);
  }
  PartsMovableAlone alone;
  MotionQuery query{std::vector<bool>(n, false), std::vector<bool>(n, false), options.exactOnly,
                    options.graphCertificates, options.coneCertificates};
  for (int i = 0; i < n && static_cast<int>(alone.parts.size()) < enough; ++i) {
    query.isFree[i] = query.isWatched[i] = true;
    query.contacts = &contactsOf[i];
    MotionSearch search = findWatchedMotion(assembly, query);
    query.isFree[i] = query.isWatched[i] = false;
    if (search.movable) {
      alone.parts.push_back(i);
      alone.motions.push_back(std::move(search));
    }
  }
  return alone;
}

InterlockingResult testInterlockingByInequalities(const Assembly& assembly, const std::vector<BaseDirection>& directions,
                                                  const InequalityOptions& options) {
  if (hasCleanNormals(assembly)) return testWithCleanNormals(assembly, directions, options);
  return testWithCleanNormals(withCleanedNormals(assembly), directions, options);
}

InterlockingResult testInterlockingByInequalities(const Assembly& assembly) {
  if (hasCleanNormals(assembly)) return testWithCleanNormals(assembly, computeBaseDirections(assembly), {});
  const Assembly clean = withCleanedNormals(assembly);
  return testWithCleanNormals(clean, computeBaseDirections(clean), {});
}

}  // namespace desia
