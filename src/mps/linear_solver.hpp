// Sparse linear solvers for the symmetric positive definite pressure system (pressure_poisson.hpp).
//   iccg: Eigen's conjugate gradient preconditioned with incomplete Cholesky (threads via OpenMP SpMV).
//   amg : hypre's conjugate gradient preconditioned with BoomerAMG (algebraic multigrid).
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <memory>
#include <vector>

#include "case/case_config.hpp"

namespace mistfall {

struct LinearSolveResult {
  int iterations = 0;
  double relative_residual = 0.0;  // |b - A x| / |b|  (0 when b = 0)
  bool converged = false;
  double setup_seconds = 0.0;  // handing the matrix over and building the preconditioner (wall)
  double solve_seconds = 0.0;  // the iterations and the residual check (wall)
  bool reused = false;         // the preconditioner of an earlier system was used (no setup)
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // x holds the initial guess on entry and the solution on exit. `row_keys` (optional) names what each row is
  // (e.g. the id of the unknown's particle, which it keeps for its life): a solver may precondition this system
  // with what it built for an earlier one whose rows were mostly the same (see reuse below); without keys it
  // never does. The amg solver cuts its smoother's blocks from consecutive rows, so rows numbered by place
  // (the particles sorted by place) smooth best; the result depends on the row order, not on the thread count.
  virtual LinearSolveResult solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x, const std::vector<std::int64_t>* row_keys = nullptr) = 0;
  // Drops whatever is kept from earlier systems: the next solve starts afresh. The simulation calls it at every
  // checkpoint, so that a resumed run meets the same state as the unbroken one.
  virtual void forget() {}
  virtual const char* name() const = 0;
};

// Reuse of the preconditioner (amg): the AMG hierarchy of the last set-up system preconditions the next systems
// (the fine level always uses the new matrix, so the tolerance is met; only the number of iterations may grow),
// for at most `max_reuse` systems and while the iterations stay within `slack` of those after the set-up. Rows
// may come and go between the systems (a particle joins or leaves the system) while at least `kept_rows` (a
// fraction of the larger system) of the new rows have a row with the same key in the set-up system: the
// interpolation to the finest level follows the kept rows to their new place, and a new row interpolates as its
// kept neighbours do (weighted by its couplings to them); the cycle stays symmetric positive definite, as
// conjugate gradients need. max_reuse = 0: a new hierarchy for every system; kept_rows = 1: only for systems of
// exactly the same rows.
struct PreconditionerReuse {
  int max_reuse = 0;
  int slack = 1;
  double kept_rows = 1.0;
};

std::unique_ptr<LinearSolver> makeLinearSolver(PressureSolverKind kind, double tolerance, int max_iterations,
                                               PreconditionerReuse reuse = {});

// Relative residual |b - A x| / |b| computed directly (0 when b = 0 and x solves it).
double relativeResidual(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                        const Eigen::VectorXd& x);

}  // namespace mistfall
