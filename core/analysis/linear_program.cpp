// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/linear_program.h"

#include <glpk.h>

#include <algorithm>
#include <csetjmp>

namespace desia {
namespace {

// Enough pivots for any motion program that is not cycling (they take a few per row), bounded so
// that a cycling simplex (seen on degenerate programs) stops deterministically.
int iterationLimit(const LinearProgramSpec& spec) { return 1000 + 50 * (spec.rowCount() + spec.columnCount()); }
// A wall-clock backstop behind the iteration limit, per GLPK call.
constexpr int kTimeLimitMs = 20000;

// Everything the guarded section reads and writes. It lives in the caller's frame and holds only
// plain data, so a longjmp out of GLPK skips no destructor.
struct GlpkRun {
  const LinearProgramSpec* spec = nullptr;
  SimplexMethod method = SimplexMethod::Dual;
  const int* ia = nullptr;
  const int* ja = nullptr;
  const double* ar = nullptr;
  int nonZeros = 0;
  double* columnValues = nullptr;
  double* rowDuals = nullptr;
  const int* startRowStatus = nullptr;     // a basis to start from, or null
  const int* startColumnStatus = nullptr;
  int* rowStatus = nullptr;                // the final basis (floating-point methods)
  int* columnStatus = nullptr;
  int returnCode = 0;
  int solutionStatus = 0;
  double objectiveValue = 0;
};

struct GlpkGuard {
  std::jmp_buf jump;
};

// GLPK calls this instead of aborting when it detects an error; returning would abort.
extern "C" void onGlpkError(void* info) { std::longjmp(static_cast<GlpkGuard*>(info)->jump, 1); }

void initParameters(glp_smcp* parameters, const LinearProgramSpec& spec, SimplexMethod method) {
  glp_init_smcp(parameters);
  parameters->msg_lev = GLP_MSG_OFF;
  parameters->it_lim = iterationLimit(spec);
  parameters->tm_lim = kTimeLimitMs;
  // Dual simplex (falling back to primal inside GLPK): V = 0 is dual degenerate here, and on the
  // benchmark assemblies the dual method needs 2-3x fewer pivots than the primal one.
  parameters->meth = method == SimplexMethod::Primal ? GLP_PRIMAL : GLP_DUALP;
  parameters->presolve = method == SimplexMethod::Dual ? GLP_ON : GLP_OFF;
}

// The GLPK calls proper. No C++ object with a destructor may live in this frame (see GlpkRun).
void runGlpk(GlpkRun* run) {
  const LinearProgramSpec& spec = *run->spec;
  const int rows = spec.rowCount();
  const int columns = spec.columnCount();
  glp_prob* problem = glp_create_prob();
  glp_set_obj_dir(problem, GLP_MAX);
  glp_add_cols(problem, columns);
  for (int j = 0; j < columns; ++j) {
    const double lo = spec.columnLower[j], hi = spec.columnUpper[j];
    glp_set_col_bnds(problem, j + 1, lo == hi ? GLP_FX : GLP_DB, lo, hi);
    glp_set_obj_coef(problem, j + 1, spec.objective[j]);
  }
  if (rows > 0) glp_add_rows(problem, rows);
  for (int r = 0; r < rows; ++r) glp_set_row_bnds(problem, r + 1, GLP_LO, spec.rowLower[r], 0.0);
  glp_load_matrix(problem, run->nonZeros, run->ia, run->ja, run->ar);

  glp_smcp parameters;
  initParameters(&parameters, spec, run->method);
  if (run->startRowStatus) {
    for (int r = 0; r < rows; ++r) glp_set_row_stat(problem, r + 1, run->startRowStatus[r]);
    for (int j = 0; j < columns; ++j) glp_set_col_stat(problem, j + 1, run->startColumnStatus[j]);
    parameters.meth = GLP_PRIMAL;
    parameters.presolve = GLP_OFF;
  }
  if (run->method == SimplexMethod::ExactRational) {
    // Start the rational simplex from the floating-point one's basis: usually optimal already,
    // so the exact run only confirms it. glp_exact needs at least one row.
    glp_simplex(problem, &parameters);
    if (rows == 0) {
      run->returnCode = GLP_EFAIL;
    } else {
      run->returnCode = glp_exact(problem, &parameters);
      if (run->returnCode == GLP_EBADB) {
        glp_std_basis(problem);
        run->returnCode = glp_exact(problem, &parameters);
      }
    }
  } else {
    run->returnCode = glp_simplex(problem, &parameters);
  }
  run->solutionStatus = glp_get_status(problem);
  run->objectiveValue = glp_get_obj_val(problem);
  for (int j = 0; j < columns; ++j) run->columnValues[j] = glp_get_col_prim(problem, j + 1);
  for (int r = 0; r < rows; ++r) run->rowDuals[r] = glp_get_row_dual(problem, r + 1);
  if (run->rowStatus) {
    for (int r = 0; r < rows; ++r) run->rowStatus[r] = glp_get_row_stat(problem, r + 1);
    for (int j = 0; j < columns; ++j) run->columnStatus[j] = glp_get_col_stat(problem, j + 1);
  }
  glp_delete_prob(problem);
}

// Runs GLPK with its error hook set. False when GLPK raised an error: its whole environment
// (the problem included) is freed then, as GLPK's manual prescribes after such a jump.
bool runGlpkGuarded(GlpkRun* run) {
  GlpkGuard guard;
  if (setjmp(guard.jump) != 0) {
    glp_error_hook(nullptr, nullptr);
    glp_free_env();
    return false;
  }
  glp_term_out(GLP_OFF);
  glp_error_hook(onGlpkError, &guard);
  runGlpk(run);
  glp_error_hook(nullptr, nullptr);
  return true;
}

const char* returnCodeName(int code) {
  switch (code) {
    case GLP_EITLIM: return "iteration limit reached";
    case GLP_ETMLIM: return "time limit reached";
    case GLP_ENOPFS: return "presolver found no feasible solution";
    case GLP_ENODFS: return "presolver found no dual feasible solution";
    case GLP_ESING: return "singular basis";
    case GLP_ECOND: return "ill-conditioned basis";
    case GLP_EFAIL: return "solver failure";
    default: return "solver failure";
  }
}

LinearProgramSolution solveWhole(const LinearProgramSpec& spec, SimplexMethod method,
                                 const LinearProgramBasis* start = nullptr) {
  LinearProgramSolution solution;
  solution.columnValues.assign(spec.columnCount(), 0.0);
  solution.rowDuals.assign(spec.rowCount(), 0.0);
  if (spec.columnCount() == 0) {
    solution.optimal = true;
    return solution;
  }
  // GLPK's arrays are 1-based.
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (size_t k = 0; k < spec.entryValue.size(); ++k) {
    ia.push_back(spec.entryRow[k] + 1);
    ja.push_back(spec.entryColumn[k] + 1);
    ar.push_back(spec.entryValue[k]);
  }
  GlpkRun run;
  run.spec = &spec;
  run.method = method;
  run.ia = ia.data();
  run.ja = ja.data();
  run.ar = ar.data();
  run.nonZeros = static_cast<int>(ar.size()) - 1;
  run.columnValues = solution.columnValues.data();
  run.rowDuals = solution.rowDuals.data();
  if (start) {
    run.startRowStatus = start->rowStatus.data();
    run.startColumnStatus = start->columnStatus.data();
  }
  if (method != SimplexMethod::ExactRational) {
    solution.basis.rowStatus.assign(spec.rowCount(), 0);
    solution.basis.columnStatus.assign(spec.columnCount(), 0);
    run.rowStatus = solution.basis.rowStatus.data();
    run.columnStatus = solution.basis.columnStatus.data();
  }
  if (!runGlpkGuarded(&run)) {
    solution.failure = "GLPK reported an error";
    return solution;
  }
  if (run.returnCode != 0) {
    solution.failure = std::string(returnCodeName(run.returnCode)) + " (GLPK code " + std::to_string(run.returnCode) + ")";
    return solution;
  }
  if (run.solutionStatus != GLP_OPT) {
    solution.failure = "no optimum (GLPK status " + std::to_string(run.solutionStatus) + ")";
    return solution;
  }
  solution.optimal = true;
  solution.objectiveValue = run.objectiveValue;
  return solution;
}

// The basis has a status per row and column, each one GLPK knows (GLP_BS .. GLP_NS); anything else
// would make GLPK raise an error (and free its whole environment) rather than start from it.
bool fitsProgram(const LinearProgramBasis& basis, const LinearProgramSpec& spec) {
  if (static_cast<int>(basis.rowStatus.size()) != spec.rowCount() ||
      static_cast<int>(basis.columnStatus.size()) != spec.columnCount())
    return false;
  auto known = [](int status) { return status >= GLP_BS && status <= GLP_NS; };
  return std::all_of(basis.rowStatus.begin(), basis.rowStatus.end(), known) &&
         std::all_of(basis.columnStatus.begin(), basis.columnStatus.end(), known);
}

// --- Independent blocks ------------------------------------------------------------------------
//
// A program whose rows fall into groups sharing no column is block diagonal: each block is a
// program of its own, the optimum is the sum of theirs, and the optimal columns and row duals of
// the blocks together are optimal for the whole. Motion programs of assemblies whose contact
// normals lie along the axes split this way into one block per axis (a row is one contact's
// normal component), and GLPK's working memory, which dominates desia check of a 4,000-plate
// design, is that of the largest block instead of the whole. Blocks are only formed from groups
// of at least kBlockRows rows, so small programs are solved whole, as before.
constexpr int kBlockRows = 4096;

struct Block {
  std::vector<int> rows, columns;  // of the whole program, in increasing order
};

// Union-find root of a column, with path halving (no recursion).
int rootOf(std::vector<int>& parent, int column) {
  while (parent[column] != column) {
    parent[column] = parent[parent[column]];
    column = parent[column];
  }
  return column;
}

// The program's independent groups of rows and columns (in order of their first column), merged
// in that order into blocks of at least kBlockRows rows. Rows without entries belong to no block.
std::vector<Block> independentBlocks(const LinearProgramSpec& spec) {
  const int columns = spec.columnCount();
  std::vector<int> parent(columns);
  for (int j = 0; j < columns; ++j) parent[j] = j;
  std::vector<int> firstColumnOfRow(spec.rowCount(), -1);
  for (size_t k = 0; k < spec.entryValue.size(); ++k) {
    int& first = firstColumnOfRow[spec.entryRow[k]];
    if (first < 0) {
      first = spec.entryColumn[k];
    } else {
      const int a = rootOf(parent, first), b = rootOf(parent, spec.entryColumn[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the group's first column
    }
  }
  std::vector<int> rowsOfGroup(columns, 0);
  for (int r = 0; r < spec.rowCount(); ++r) {
    if (firstColumnOfRow[r] >= 0) ++rowsOfGroup[rootOf(parent, firstColumnOfRow[r])];
  }
  // Groups in order of their first column, each assigned to the block open when it is met.
  std::vector<int> blockOfGroup(columns, -1);
  std::vector<Block> blocks;
  int openRows = kBlockRows;  // a new block opens at the first group
  for (int j = 0; j < columns; ++j) {
    const int root = rootOf(parent, j);
    if (root != j) continue;
    if (openRows >= kBlockRows) {
      blocks.emplace_back();
      openRows = 0;
    }
    blockOfGroup[j] = static_cast<int>(blocks.size()) - 1;
    openRows += rowsOfGroup[j];
  }
  // A last block short of kBlockRows (it may have no row at all, which glp_exact refuses) joins
  // the one before it.
  if (blocks.size() > 1 && openRows < kBlockRows) {
    const int last = static_cast<int>(blocks.size()) - 1;
    for (int& block : blockOfGroup) {
      if (block == last) block = last - 1;
    }
    blocks.pop_back();
  }
  if (blocks.size() <= 1) return blocks;
  for (int j = 0; j < columns; ++j) blocks[blockOfGroup[rootOf(parent, j)]].columns.push_back(j);
  for (int r = 0; r < spec.rowCount(); ++r) {
    if (firstColumnOfRow[r] >= 0) blocks[blockOfGroup[rootOf(parent, firstColumnOfRow[r])]].rows.push_back(r);
  }
  return blocks;
}

// The block as a program of its own (its rows and columns renumbered in order).
LinearProgramSpec blockProgram(const LinearProgramSpec& spec, const Block& block,
                               const std::vector<std::vector<int>>& entriesOfRow, std::vector<int>* localColumn) {
  LinearProgramSpec part;
  for (size_t c = 0; c < block.columns.size(); ++c) {
    const int j = block.columns[c];
    (*localColumn)[j] = static_cast<int>(c);
    part.addColumn(spec.columnLower[j], spec.columnUpper[j], spec.objective[j]);
  }
  for (size_t local = 0; local < block.rows.size(); ++local) {
    const int r = block.rows[local];
    part.rowLower.push_back(spec.rowLower[r]);
    for (int k : entriesOfRow[r]) part.addEntry(static_cast<int>(local), (*localColumn)[spec.entryColumn[k]], spec.entryValue[k]);
  }
  return part;
}

}  // namespace

LinearProgramSolution solveLinearProgram(const LinearProgramSpec& spec, SimplexMethod method) {
  const std::vector<Block> blocks = independentBlocks(spec);
  if (blocks.size() <= 1) return solveWhole(spec, method);
  std::vector<std::vector<int>> entriesOfRow(spec.rowCount());
  for (size_t k = 0; k < spec.entryValue.size(); ++k) entriesOfRow[spec.entryRow[k]].push_back(static_cast<int>(k));
  LinearProgramSolution whole;
  whole.columnValues.assign(spec.columnCount(), 0.0);
  whole.rowDuals.assign(spec.rowCount(), 0.0);
  std::vector<int> localColumn(spec.columnCount(), -1);
  for (const Block& block : blocks) {
    const LinearProgramSolution part = solveWhole(blockProgram(spec, block, entriesOfRow, &localColumn), method);
    if (!part.optimal) {
      whole.failure = part.failure;
      return whole;
    }
    whole.objectiveValue += part.objectiveValue;
    for (size_t c = 0; c < block.columns.size(); ++c) whole.columnValues[block.columns[c]] = part.columnValues[c];
    for (size_t r = 0; r < block.rows.size(); ++r) whole.rowDuals[block.rows[r]] = part.rowDuals[r];
  }
  whole.optimal = true;
  return whole;
}

LinearProgramSolution solveLinearProgramFrom(const LinearProgramSpec& spec, SimplexMethod method,
                                             const LinearProgramBasis& start) {
  if (method == SimplexMethod::ExactRational || !fitsProgram(start, spec) || independentBlocks(spec).size() > 1) {
    return solveLinearProgram(spec, method);
  }
  LinearProgramSolution warm = solveWhole(spec, method, &start);
  warm.fromBasis = true;
  if (warm.optimal) return warm;
  return solveWhole(spec, method);  // a single block, as checked above
}

}  // namespace desia
