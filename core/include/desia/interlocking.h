// SPDX-License-Identifier: GPL-3.0-or-later
// The two interlocking tests of paper Section 3.2.
#pragma once

#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/blocking_graph.h"

namespace desia {

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

}  // namespace desia
