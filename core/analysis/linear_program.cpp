// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/linear_program.h"

#include <glpk.h>

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

}  // namespace

LinearProgramSolution solveLinearProgram(const LinearProgramSpec& spec, SimplexMethod method) {
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

}  // namespace desia
