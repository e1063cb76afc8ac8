// Sparse linear solvers for the symmetric positive definite pressure system (pressure_poisson.hpp).
//   iccg: Eigen's conjugate gradient preconditioned with incomplete Cholesky (threads via OpenMP SpMV).
//   amg : hypre's conjugate gradient preconditioned with BoomerAMG (algebraic multigrid).
#pragma once

#include <Eigen/Sparse>
#include <memory>

#include "case/case_config.hpp"

namespace mistfall {

struct LinearSolveResult {
  int iterations = 0;
  double relative_residual = 0.0;  // |b - A x| / |b|  (0 when b = 0)
  bool converged = false;
  double setup_seconds = 0.0;  // handing the matrix over and building the preconditioner (wall)
  double solve_seconds = 0.0;  // the iterations and the residual check (wall)
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // x holds the initial guess on entry and the solution on exit.
  virtual LinearSolveResult solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x) = 0;
  virtual const char* name() const = 0;
};

std::unique_ptr<LinearSolver> makeLinearSolver(PressureSolverKind kind, double tolerance, int max_iterations);

// Relative residual |b - A x| / |b| computed directly (0 when b = 0 and x solves it).
double relativeResidual(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                        const Eigen::VectorXd& x);

}  // namespace mistfall
