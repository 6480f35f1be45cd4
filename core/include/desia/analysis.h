// SPDX-License-Identifier: GPL-3.0-or-later
// The analysis layer, which knows parts and contacts only: directional blocking graphs (paper
// Section 3.2), the DBG and inequality (LP) interlocking tests, disassembly plans from contacts, and
// the check of an assembly that combines them.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "desia/model.h"

namespace desia {

// Directional blocking graphs (paper Section 3.1). G(d) has an edge i->j when part j blocks the
// translation of part i along d. Base directions are the directions where the non-directional
// blocking graph changes; one base DBG per direction on a half sphere suffices because
// G(-d) is G(d) reversed.

// Label of a direction: "+x" / "-y" for axes, a rounded vector otherwise.
std::string directionLabel(const Vec3& direction);

struct BaseDirection {
  Vec3 vector{0, 0, 0};   // unit length, canonical sign (first non-zero component positive)
  // "+x", "+y", "+z" for axes, otherwise "(0.707,0.707,0)"; made when asked for, since an
  // assembly can have hundreds of thousands of base directions and few are ever named.
  std::string label() const { return directionLabel(vector); }
};

// The vertices of the arrangement of great circles {d : d·n = 0} on the unit sphere, one of each
// antipodal pair (the 3D analogue of the points of Fig. 3e). For axis-aligned contacts these are
// exactly +x, +y, +z. Degenerate arrangements (all normals parallel, or no contacts) still get
// directions that span the free motions, so a free part is never missed.
std::vector<BaseDirection> computeBaseDirections(const Assembly& assembly);

struct DirectionalBlockingGraph {
  BaseDirection direction;
  DirectedGraph graph;  // nodes are part indices
};

// Infinitesimal blocking: i is blocked by j along d iff some contact normal n from i to j has
// d·n > 0 (moving i along d would penetrate j).
DirectionalBlockingGraph buildBlockingGraph(const Assembly& assembly, const BaseDirection& direction);

// The same graphs for many directions of one assembly. Across many directions, contacts are
// grouped by pair of parts once, and a pair is no longer examined once it blocks both ways
// (hundreds of contacts between two parts then cost a few dot products per direction); across a
// few (voxel assemblies: three) the grouping would cost more than it saves, and is skipped.
class BlockingGraphBuilder {
 public:
  // Keeps a reference to `assembly`, which must outlive the builder.
  BlockingGraphBuilder(const Assembly& assembly, size_t directionCount);
  DirectionalBlockingGraph build(const BaseDirection& direction) const;
  // Rebuilds `graph` in place (its node count must be the assembly's), reusing its memory.
  void buildInto(const BaseDirection& direction, DirectionalBlockingGraph* graph) const;

 private:
  struct PairContacts {
    int a = 0, b = 0;           // a < b
    std::vector<Vec3> normals;  // oriented from a towards b, distinct
  };
  const Assembly& assembly_;
  bool grouped_ = false;
  std::vector<PairContacts> pairs_;
};

std::vector<DirectionalBlockingGraph> buildBaseBlockingGraphs(const Assembly& assembly);

// The two interlocking tests of paper Section 3.2.

enum class Verdict { Interlocking, Deadlocked, NotInterlocking };
const char* verdictName(Verdict verdict);  // "interlocking", "deadlocked", "not-interlocking"

// A part or part group that can move, and how (a failure's evidence).
struct Witness {
  std::vector<int> parts;             // internal indices, sorted
  std::vector<Vec3> velocities;       // one per part (DBG: all equal to the direction)
  std::string direction;              // label of the common direction, empty for a mixed motion
};

struct InterlockingResult {
  Verdict verdict = Verdict::NotInterlocking;
  std::string reason;                 // one sentence explaining the verdict
  int key = -1;                       // internal index of the key, or -1
  std::vector<Vec3> keyDirections;    // free directions of the key (base directions, signed)
  bool hasWitness = false;
  Witness witness;
};

// DBG-based test: every base DBG is strongly connected, or has two SCCs one of which is the same
// single part (the key) in all of them. Exact for axis-aligned contacts; only necessary otherwise.
InterlockingResult testInterlockingByGraphs(const Assembly& assembly,
                                            const std::vector<DirectionalBlockingGraph>& graphs);
// The same test building each DBG only when it is examined (hundreds of thousands of base
// directions for hundreds of distinct normals: they are never all held at once).
InterlockingResult testInterlockingByGraphs(const Assembly& assembly, const std::vector<BaseDirection>& directions);

// Inequality-based test (Eq. 2) with GLPK. Exact for any contact normals: motions that slide along
// every contact (all t_ij = 0 but v != 0) are found by a second LP on a generic functional, and
// round 2 fixes only a reference part, so groups moving with the key are caught too.
// Verdicts are checked: every motion against every contact, every "no motion" by a dual bound,
// and programs that GLPK cannot settle are decided by its exact rational simplex. A motion may
// push into a contact by tolerance::kPenetration of its speed (computed normals carry rounding
// residue). Throws Error(TooLarge) when even the exact simplex stops at its limits. `directions`
// (the base directions, see computeBaseDirections) only name the key's free directions.
struct InequalityOptions {
  // Decide every program by the exact rational simplex alone (slow; tests use it to show that the
  // certified floating-point route answers the same question).
  bool exactOnly = false;
  // Let graph algorithms propose the answer of a motion program whose rows are all difference
  // constraints (contacts with axis-aligned normals: every voxel assembly), each answer accepted
  // only with the same checked certificate as GLPK's (a motion checked against every contact, "no
  // motion" by the dual bound), GLPK deciding as before whenever none checks. Same verdicts, much
  // less time on large voxel assemblies; off only to compare with GLPK alone (tests).
  bool graphCertificates = true;
  // Let a search of the contact normals' cones certify "no motion" for a program of one free part
  // (round 1, where every part but the key is blocked): -c as a non-negative combination of at
  // most three rows, checked by the same dual bound as GLPK's duals, GLPK deciding whenever none
  // is found. Same verdicts; off only to compare with GLPK alone (tests).
  bool coneCertificates = true;
};
InterlockingResult testInterlockingByInequalities(const Assembly& assembly);
InterlockingResult testInterlockingByInequalities(const Assembly& assembly, const std::vector<BaseDirection>& directions,
                                                  const InequalityOptions& options = {});

// Lower level pieces of the inequality test, exposed for tests.
struct MotionSearch {
  bool movable = false;
  std::vector<Vec3> velocities;  // per part (zero for fixed parts)
  // Every program of the search was settled by a certificate built from graphs (see
  // InequalityOptions::graphCertificates), not by GLPK. For tests: it shows the shortcut applied.
  bool decidedByGraphs = false;
  // Every program of the search was settled by a cone certificate (InequalityOptions::
  // coneCertificates): the free part is blocked, and GLPK never ran. For tests.
  bool decidedByCones = false;
};
// Is there a non-zero motion of the parts flagged free (the others fixed) that violates no contact?
// Expects clean normals (cleanedNormal; every reader makes them so), unlike the whole test above.
MotionSearch findFreeMotion(const Assembly& assembly, const std::vector<bool>& isFree,
                            const InequalityOptions& options = {});
// The same question about watched parts: a motion counts only when a watched part moves, and free
// parts that are not watched may move along (round 2 fixes a reference part and does not watch
// the key). Every watched part must be free.
MotionSearch findMotionOfWatchedParts(const Assembly& assembly, const std::vector<bool>& isFree,
                                      const std::vector<bool>& isWatched, const InequalityOptions& options = {});
// Round 1 of the inequality test: the parts that can move alone (every other part fixed), in index
// order, each with its motion; it stops once `enough` are found (the test needs two at most).
struct PartsMovableAlone {
  std::vector<int> parts;
  std::vector<MotionSearch> motions;
};
PartsMovableAlone findPartsMovableAlone(const Assembly& assembly, const InequalityOptions& options = {},
                                        int enough = 1 << 30);

// Disassembly planning (paper Section 3.3): a sequence of single-part removals.

// One straight translation of `steps` units along `direction` (a unit axis for voxels).
struct Move {
  Vec3 direction{0, 0, 0};
  int steps = 0;
  double length = 0;  // mesh plans: a finite move's length in mm (steps = 0); 0 otherwise
};

struct Removal {
  int part = -1;           // internal index
  std::vector<Move> path;  // the last move takes the part clear of the remaining parts
};

// One move of a set of parts together (the unit BurrTools counts): a translation by `steps` whole
// units along the unit axis `direction`, or, when `out`, to infinity along it, after which the
// moved parts form a sub-assembly of their own and each side is taken apart on its own.
struct GroupMove {
  std::vector<int> parts;  // internal indices, ascending
  Vec3 direction{0, 0, 0};
  int steps = 0;           // 0 when `out`
  bool out = false;
  double length = 0;       // mesh plans: a finite move's length in mm; 0 otherwise
};

struct DisassemblyPlan {
  bool complete = false;  // all parts removed (the last part stays in place, empty path)
  // `removals` lists single-part removals in order, each with its own path (the last part: none).
  // A plan that needed parts moved together (voxel plans only) lists in `removals` the order in
  // which parts come free, with empty paths, and sets singlePartPaths = false: `moves` is the plan.
  std::vector<Removal> removals;
  bool singlePartPaths = true;
  // Voxel plans: every move in order, separations included (`out`), and the disassembly level in
  // BurrTools' notation: moves of the first separation (the final move out included), then of
  // the separations below it, in pre-order, where a sub-assembly needs more than one move for
  // one of its separations. levelMinimal: found by breadth-first search, so no plan has fewer
  // moves before the first separation, and each later entry is the fewest for its sub-assembly
  // as the separations before it left it (as BurrTools counts); false when the level is that of
  // a plan found otherwise.
  std::vector<GroupMove> moves;
  std::vector<int> level;
  bool levelMinimal = false;
  bool movesFollowRemovals = true;  // `moves` are the removals' paths, else a plan of their own
  // Parts still together when the plan stopped, per sub-assembly (`stuck` lists them all).
  std::vector<std::vector<int>> unseparated;
  std::string limit;  // which search limit stopped the plan, in words ("" = none)
  std::vector<int> stuck;           // parts left when no further removal exists (complete == false)
  bool searchLimitReached = false;  // some search gave up at its work limit: "stuck" is not proven
  // Work done (voxel plans only): part searches run (cached failures are not run again) and voxel
  // collision tests made, for tests and benchmarks that pin down how the planner scales.
  int64_t searches = 0;
  int64_t voxelTests = 0;
  int64_t groupStates = 0;  // positions visited by the search for moves of several parts
};

// Assemblies known only by their contacts: a part is removable when it is locally free along a
// base direction in the DBG of the remaining parts (no sweep is possible without geometry).
DisassemblyPlan planContactDisassembly(const Assembly& assembly);

// The check of an assembly known by its parts and contacts (paper Sections 3 and 4): the DBG test,
// the LP test or both, and a disassembly plan from a planner the kind of assembly supplies.

enum class CheckMethod { Graphs, Inequalities, Both };
// Parses "dbg", "lp" or "both"; throws BadInput otherwise.
CheckMethod parseCheckMethod(const std::string& name);
const char* checkMethodName(CheckMethod method);

// Reports keep every base DBG up to this many base directions; beyond it (hundreds of distinct
// normals give hundreds of thousands) only their count, unless all graphs are asked for.
constexpr size_t kReportedGraphLimit = 128;

struct CheckOptions {
  CheckMethod method = CheckMethod::Graphs;
  bool planDisassembly = true;
  bool allGraphs = false;  // keep every base DBG in the report, however many
};

// Plate and frame results carry their removal plan; the contacts alone cannot tell whether the
// real shapes let each part out, so checkDocument (document.h) moves them.
struct ShapeRemovalCheck {
  std::string checked;  // what was moved, e.g. "each plate swept along its direction, in the planned order"
  std::string failure;  // why a part cannot leave ("" = every part left)
};

struct CheckReport {
  CheckMethod method = CheckMethod::Graphs;
  InterlockingResult result;                          // the combined verdict
  std::optional<InterlockingResult> graphResult;      // when the DBG test ran
  std::optional<InterlockingResult> inequalityResult; // when the LP test ran
  size_t baseDirectionCount = 0;                      // number of base directions (and DBGs)
  std::vector<DirectionalBlockingGraph> graphs;       // base DBGs of the full assembly, or none
                                                      // when over kReportedGraphLimit
  std::optional<DisassemblyPlan> disassembly;         // absent when not planned
  std::optional<ShapeRemovalCheck> shapeRemoval;      // plate and frame results (checkDocument)
};

// Plans the disassembly of an assembly: planContactDisassembly for contacts alone, or a kind's
// planner that moves the real shapes (voxels).
using DisassemblyPlanner = std::function<DisassemblyPlan(const Assembly&)>;

// The interlocking tests of `options.method` on the assembly's contacts and, when
// options.planDisassembly, the plan `planner` makes.
CheckReport checkContacts(const Assembly& assembly, const CheckOptions& options = {},
                          const DisassemblyPlanner& planner = planContactDisassembly);

}  // namespace desia
