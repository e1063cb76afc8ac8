// Eigen conjugate gradient with incomplete Cholesky preconditioning (the "iccg" pressure solver).
#include <omp.h>

#include <Eigen/IterativeLinearSolvers>

#include "mps/linear_solver.hpp"

namespace mistfall {

double relativeResidual(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                        const Eigen::VectorXd& x) {
  const double nb = b.norm();
  const double nr = (b - a * x).norm();
  return nb > 0.0 ? nr / nb : nr;
}

namespace {

class EigenIccgSolver final : public LinearSolver {
 public:
  EigenIccgSolver(double tolerance, int max_iterations) {
    cg_.setTolerance(tolerance);
    cg_.setMaxIterations(max_iterations);
  }

  LinearSolveResult solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                          Eigen::VectorXd& x, const std::vector<std::int64_t>*) override {
    LinearSolveResult result;
    if (a.rows() == 0) {
      result.converged = true;
      return result;
    }
    if (b.norm() == 0.0) {
      x.setZero(a.rows());
      result.converged = true;
      return result;
    }
    const double t0 = omp_get_wtime();
    cg_.compute(a);
    const double t1 = omp_get_wtime();
    result.setup_seconds = t1 - t0;
    if (cg_.info() != Eigen::Success) {
      result.converged = false;
      result.relative_residual = relativeResidual(a, b, x);
      return result;
    }
    x = cg_.solveWithGuess(b, x);
    result.iterations = static_cast<int>(cg_.iterations());
    result.relative_residual = relativeResidual(a, b, x);
    result.converged = cg_.info() == Eigen::Success;
    result.solve_seconds = omp_get_wtime() - t1;
    return result;
  }

  const char* name() const override { return "iccg"; }

 private:
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
      cg_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeHypreAmgSolver(double tolerance, int max_iterations, PreconditionerReuse reuse);

std::unique_ptr<LinearSolver> makeLinearSolver(PressureSolverKind kind, double tolerance, int max_iterations,
                                               PreconditionerReuse reuse) {
  switch (kind) {
    case PressureSolverKind::EigenIccg: return std::make_unique<EigenIccgSolver>(tolerance, max_iterations);
    case PressureSolverKind::HypreAmg: return makeHypreAmgSolver(tolerance, max_iterations, reuse);
  }
  return nullptr;
}

}  // namespace mistfall
