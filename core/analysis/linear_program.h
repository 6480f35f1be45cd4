// SPDX-License-Identifier: GPL-3.0-or-later
// A small front end to GLPK for the inequality test (paper Section 3.2, Eq. 2): one linear program
// in, one plain answer out, never a process abort and never an unbounded run.
#pragma once

#include <string>
#include <vector>

namespace desia {

// maximize objective·x  subject to  rowLower[r] <= (A x)[r],  columnLower <= x <= columnUpper.
struct LinearProgramSpec {
  std::vector<double> columnLower, columnUpper, objective;  // one entry per column
  std::vector<double> rowLower;                              // one entry per row
  std::vector<int> entryRow, entryColumn;                    // the non-zeros of A, 0-based
  std::vector<double> entryValue;

  int columnCount() const { return static_cast<int>(objective.size()); }
  int rowCount() const { return static_cast<int>(rowLower.size()); }
  void addColumn(double lower, double upper, double cost) {
    columnLower.push_back(lower);
    columnUpper.push_back(upper);
    objective.push_back(cost);
  }
  void addEntry(int row, int column, double value) {
    if (value == 0.0) return;
    entryRow.push_back(row);
    entryColumn.push_back(column);
    entryValue.push_back(value);
  }
};

enum class SimplexMethod {
  Dual,          // GLPK's dual simplex with its presolver: fastest on the motion programs
  Primal,        // primal simplex without presolver: a second, differently-pivoting opinion
  ExactRational  // GLPK's exact simplex in rational arithmetic (glp_exact) on the double data
};

// A simplex basis as plain data (GLPK's status of each row and column), to start another solve of
// the same rows from it.
struct LinearProgramBasis {
  std::vector<int> rowStatus, columnStatus;
  bool empty() const { return rowStatus.empty() && columnStatus.empty(); }
};

struct LinearProgramSolution {
  bool optimal = false;       // an optimum was found; otherwise `failure` says why
  std::string failure;
  double objectiveValue = 0;
  std::vector<double> columnValues;
  std::vector<double> rowDuals;  // GLPK's row duals (for a maximization, <= 0 on active lower bounds)
  LinearProgramBasis basis;      // the final basis (programs solved whole by floating point only)
  bool fromBasis = false;        // solved from the given basis (solveLinearProgramFrom), not from scratch
};

// Solves with a deterministic iteration limit that grows with the program's size and a wall-clock
// backstop. GLPK's own fatal errors (it calls abort() after printing) are caught through its
// error hook and come back as a failure; its environment is then reset.
LinearProgramSolution solveLinearProgram(const LinearProgramSpec& spec, SimplexMethod method);
// The same, started from `start`, the optimal basis of the same rows and bounds under another
// objective: still primal feasible, so the primal simplex goes on from it without the presolver
// (which would discard it). A program split into blocks, or a basis GLPK cannot factorize, is
// solved from scratch by `method` instead.
LinearProgramSolution solveLinearProgramFrom(const LinearProgramSpec& spec, SimplexMethod method,
                                             const LinearProgramBasis& start);

}  // namespace desia
