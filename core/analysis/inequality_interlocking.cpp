// SPDX-License-Identifier: GPL-3.0-or-later
// Inequality-based interlocking test (paper Section 3.2, Eq. 2), solved with GLPK.
//
// Eq. 2 alone misses motions that slide along every contact (all t_ij = 0 with v != 0: a part
// in a slot, free along the slot). A motion with A V = 0 lies in the null space of the contact
// matrix, so after a zero LP optimum we also test that null space (as TopoLite does).
#include <glpk.h>

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseQR>
#include <algorithm>
#include <memory>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/interlocking.h"

namespace desia {
namespace {

constexpr double kMotionEpsilon = 1e-7;

struct GlpkProblemDeleter {
  void operator()(glp_prob* problem) const { glp_delete_prob(problem); }
};
using GlpkProblem = std::unique_ptr<glp_prob, GlpkProblemDeleter>;

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

// Eq. 2: max Σ t_c  s.t. (v_b - v_a)·n_c - t_c >= 0, 0 <= t_c <= 1, fixed parts have v = 0.
// Velocities are bounded to [-1, 1] (scaling a motion keeps it a motion) for a well-posed LP.
MotionSearch solveEquationTwo(const Assembly& assembly, const std::vector<int>& contacts, const std::vector<int>& velocityColumn,
                              int velocityCount) {
  GlpkProblem lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MAX);
  const int rows = static_cast<int>(contacts.size());
  const int cols = velocityCount + rows;
  glp_add_cols(lp.get(), cols);
  for (int j = 1; j <= velocityCount; ++j) glp_set_col_bnds(lp.get(), j, GLP_DB, -1.0, 1.0);
  for (int r = 0; r < rows; ++r) {
    glp_set_col_bnds(lp.get(), velocityCount + r + 1, GLP_DB, 0.0, 1.0);
    glp_set_obj_coef(lp.get(), velocityCount + r + 1, 1.0);
  }
  glp_add_rows(lp.get(), rows);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  auto add = [&](int row, int col, double value) {
    if (value == 0.0) return;
    ia.push_back(row);
    ja.push_back(col);
    ar.push_back(value);
  };
  for (int r = 0; r < rows; ++r) {
    const Contact& contact = assembly.contacts[contacts[r]];
    glp_set_row_bnds(lp.get(), r + 1, GLP_LO, 0.0, 0.0);
    for (int k = 0; k < 3; ++k) {
      if (velocityColumn[contact.b] >= 0) add(r + 1, velocityColumn[contact.b] + k + 1, contact.normal[k]);
      if (velocityColumn[contact.a] >= 0) add(r + 1, velocityColumn[contact.a] + k + 1, -contact.normal[k]);
    }
    add(r + 1, velocityCount + r + 1, -1.0);
  }
  glp_load_matrix(lp.get(), static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());

  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.presolve = GLP_ON;
  const int status = glp_simplex(lp.get(), &parameters);
  // An empty problem after presolve reports GLP_ENOPFS/GLP_ENODFS only for infeasible input;
  // v = 0, t = 0 is always feasible, so anything but success is a solver failure.
  if (status != 0 || glp_get_status(lp.get()) != GLP_OPT) {
    throw Error(ErrorCode::Internal, "GLPK failed on the interlocking linear program (status " +
                                         std::to_string(status) + ")");
  }
  MotionSearch search;
  search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  search.movable = glp_get_obj_val(lp.get()) > kMotionEpsilon;
  if (search.movable) {
    for (int i = 0; i < assembly.partCount(); ++i) {
      if (velocityColumn[i] < 0) continue;
      for (int k = 0; k < 3; ++k) search.velocities[i][k] = glp_get_col_prim(lp.get(), velocityColumn[i] + k + 1);
    }
  }
  return search;
}

// A non-zero V with A V = 0 (every contact slides), from a rank-revealing sparse QR of A.
MotionSearch findSlidingMotion(const Assembly& assembly, const std::vector<int>& contacts,
                               const std::vector<int>& velocityColumn, int velocityCount) {
  MotionSearch search;
  search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  if (velocityCount == 0) return search;
  const int rows = static_cast<int>(contacts.size());
  Eigen::VectorXd motion;
  if (rows == 0) {
    motion = Eigen::VectorXd::Unit(velocityCount, 0);
  } else {
    std::vector<Eigen::Triplet<double>> entries;
    for (int r = 0; r < rows; ++r) {
      const Contact& contact = assembly.contacts[contacts[r]];
      for (int k = 0; k < 3; ++k) {
        if (velocityColumn[contact.b] >= 0) entries.emplace_back(r, velocityColumn[contact.b] + k, contact.normal[k]);
        if (velocityColumn[contact.a] >= 0) entries.emplace_back(r, velocityColumn[contact.a] + k, -contact.normal[k]);
      }
    }
    // QR needs rows >= cols; zero rows do not change the null space.
    Eigen::SparseMatrix<double> matrix(std::max(rows, velocityCount), velocityCount);
    matrix.setFromTriplets(entries.begin(), entries.end());
    matrix.makeCompressed();
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(1e-10);
    qr.compute(matrix);
    if (qr.info() != Eigen::Success) throw Error(ErrorCode::Internal, "sparse QR failed in the null-space test");
    const int rank = static_cast<int>(qr.rank());
    if (rank >= velocityCount) return search;
    // A P = Q R with R = [R11 R12; 0 0]: y = [-R11^{-1} R12 e_1; e_1] solves R y = 0, V = P y.
    Eigen::MatrixXd r = Eigen::MatrixXd(qr.matrixR()).topRows(rank);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(velocityCount);
    y(rank) = 1.0;
    if (rank > 0) {
      Eigen::VectorXd rhs = -r.col(rank);
      y.head(rank) = r.leftCols(rank).triangularView<Eigen::Upper>().solve(rhs);
    }
    motion = qr.colsPermutation() * y;
    // Guard against a rank decision that numerical noise got wrong.
    Eigen::VectorXd residual = matrix * motion;
    if (residual.lpNorm<Eigen::Infinity>() > 1e-6 * std::max(1.0, motion.lpNorm<Eigen::Infinity>())) return search;
  }
  motion /= motion.lpNorm<Eigen::Infinity>();
  search.movable = true;
  for (int i = 0; i < assembly.partCount(); ++i) {
    if (velocityColumn[i] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      double v = motion(velocityColumn[i] + k);
      search.velocities[i][k] = std::abs(v) < 1e-12 ? 0.0 : v;
    }
  }
  return search;
}

std::vector<int> movingParts(const MotionSearch& search) {
  std::vector<int> parts;
  for (int i = 0; i < static_cast<int>(search.velocities.size()); ++i) {
    if (norm(search.velocities[i]) > 1e-6) parts.push_back(i);
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
    if (norm({v[0] - first[0], v[1] - first[1], v[2] - first[2]}) > 1e-6) common = false;
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

// Base directions along which the part alone is free (no contact normal points into the motion).
std::vector<Vec3> freeDirectionsOfPart(const Assembly& assembly, int part) {
  std::vector<Vec3> free;
  for (const BaseDirection& base : computeBaseDirections(assembly)) {
    for (const Vec3& d : {base.vector, negated(base.vector)}) {
      bool blocked = false;
      for (const Contact& contact : assembly.contacts) {
        if (contact.a == part && dot(d, contact.normal) > kDirectionTolerance) blocked = true;
        if (contact.b == part && dot(d, contact.normal) < -kDirectionTolerance) blocked = true;
      }
      if (!blocked) free.push_back(d);
    }
  }
  return free;
}

}  // namespace

MotionSearch findFreeMotion(const Assembly& assembly, const std::vector<bool>& isFree) {
  int velocityCount = 0;
  const std::vector<int> column = velocityColumns(isFree, &velocityCount);
  const std::vector<int> contacts = relevantContacts(assembly, isFree);
  MotionSearch search = solveEquationTwo(assembly, contacts, column, velocityCount);
  if (search.movable) return search;
  return findSlidingMotion(assembly, contacts, column, velocityCount);
}

InterlockingResult testInterlockingByInequalities(const Assembly& assembly) {
  const int n = assembly.partCount();
  InterlockingResult result;
  if (n < 3) {
    result.reason = "an interlocking assembly needs at least three parts; this one has " + std::to_string(n);
    return result;
  }
  // Round 1: which parts can move alone?
  std::vector<int> movableAlone;
  std::vector<MotionSearch> motions;
  for (int i = 0; i < n; ++i) {
    std::vector<bool> isFree(n, false);
    isFree[i] = true;
    MotionSearch search = findFreeMotion(assembly, isFree);
    if (search.movable) {
      movableAlone.push_back(i);
      motions.push_back(std::move(search));
    }
  }
  if (movableAlone.size() > 1) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(motions[1]);
    result.reason = "more than one part can move alone (parts " + std::to_string(assembly.parts[movableAlone[0]].id) +
                    " and " + std::to_string(assembly.parts[movableAlone[1]].id) + "): " +
                    describeMotion(assembly, result.witness);
    return result;
  }
  // Round 2: fix the key (if any) and a reference part; any remaining motion breaks interlocking.
  const int key = movableAlone.empty() ? -1 : movableAlone[0];
  const int reference = key == 0 ? 1 : 0;
  std::vector<bool> isFree(n, true);
  isFree[reference] = false;
  if (key >= 0) isFree[key] = false;
  MotionSearch search = findFreeMotion(assembly, isFree);
  if (search.movable) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(search);
    result.reason = (key >= 0 ? "with the key fixed, " : "") + describeMotion(assembly, result.witness);
    return result;
  }
  if (key < 0) {
    result.verdict = Verdict::Deadlocked;
    result.reason = "the linear program admits no motion: no part or part group can move";
    return result;
  }
  result.verdict = Verdict::Interlocking;
  result.key = key;
  result.keyDirections = freeDirectionsOfPart(assembly, key);
  if (result.keyDirections.empty()) result.keyDirections.push_back(normalized(motions[0].velocities[key]));
  std::ostringstream reason;
  reason << "only the key (part " << assembly.parts[key].id << ") can move, along";
  for (const Vec3& d : result.keyDirections) reason << ' ' << directionLabel(d);
  result.reason = reason.str();
  return result;
}

}  // namespace desia
