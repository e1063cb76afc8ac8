// The pressure systems' linear solves (MpsSolver, solver.hpp): the rows' particles and ids for the solver's reuse of
// its preconditioner (linear_solver.hpp), the stage timers, and the error when a solve does not converge.
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>

#include "mps/solver.hpp"

namespace mistfall {

template <int D>
void MpsSolver<D>::solveSystem(const std::vector<double>& guess, const char* which, int& iterations) {
  const auto rows = system_.particle_of.size();
  pressure_unknowns_.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) pressure_unknowns_[r] = guess[system_.particle_of[r]];
  solveLinear(system_.matrix, system_.rhs, pressure_unknowns_, which, iterations);
}

template <int D>
void MpsSolver<D>::solveLinear(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                               Eigen::VectorXd& x, const char* which, int& iterations) {
  const bool gas = std::string_view(which) == "gas";
  // What each row is: the particle of the unknown (system_), or -1 - g for bubble g's merged unknown (lumped_).
  row_ids_.assign(static_cast<std::size_t>(a.rows()), -1);
  const auto& particle_of = system_.particle_of;
  if (!gas && static_cast<Eigen::Index>(lumped_.column_of_row.size()) == static_cast<Eigen::Index>(particle_of.size()) &&
      lumped_.matrix.rows() == a.rows()) {
    for (std::size_t r = 0; r < particle_of.size(); ++r) {
      const auto column = lumped_.column_of_row[r];
      row_ids_[column] = column < lumped_.first_group_row ? particle_of[r] : -1 - (column - lumped_.first_group_row);
    }
  } else if (static_cast<Eigen::Index>(particle_of.size()) == a.rows()) {
    row_ids_.assign(particle_of.begin(), particle_of.end());
  }
  // The amg solver's smoother blocks are cut from the rows in their own order: rows are numbered in particle order,
  // and the particle arrays are kept sorted by the neighbour search's cells (spatial_order.hpp), so consecutive
  // rows are neighbours in space (a bubble's merged unknown comes last).
  // The rows' keys for the reuse of the preconditioner: the particles' ids, which they keep for their life.
  row_keys_.resize(row_ids_.size());
  for (std::size_t r = 0; r < row_ids_.size(); ++r)
    row_keys_[r] = row_ids_[r] >= 0 ? static_cast<std::int64_t>(state_.particles.id[row_ids_[r]]) : row_ids_[r];
  checkDiagonal(a, which);
  LinearSolver& solver = gas ? *gas_solver_ : *liquid_solver_;
  const auto result = solver.solve(a, b, x, &row_keys_);
  timer_.add(gas ? Stage::GasSetup : Stage::LiquidSetup, result.setup_seconds);
  timer_.add(gas ? Stage::GasSolve : Stage::LiquidSolve, result.solve_seconds);
  solve_seconds_ += result.setup_seconds + result.solve_seconds;
  iterations = result.iterations;
  if (!result.converged && !(result.relative_residual <= 1e3 * config_.numerics.solver_tolerance)) {
    std::ostringstream msg;
    msg << which << " pressure solve (" << solver.name() << ") did not converge: relative residual "
        << result.relative_residual << " after " << result.iterations << " iterations ("
        << "numerics.solver_tolerance = " << config_.numerics.solver_tolerance << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
  report_.ppe_residual = std::max(report_.ppe_residual, result.relative_residual);
}

// A row whose diagonal is zero has nothing of its system within reach: the solve returns NaN and the run would end on
// a non-finite particle somewhere else. Traced on the stiff joined 1.25 mm bubble without respacing_limit (forty-ninth
// session, docs/validation.md): two of its gas particles re-spaced 7 l0 into the floor and a wall kept their rows,
// empty. The row's particle is named instead, before the solve.
template <int D>
void MpsSolver<D>::checkDiagonal(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const char* which) const {
  for (Eigen::Index r = 0; r < a.outerSize(); ++r) {
    double diagonal = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, r); it; ++it)
      if (it.col() == r) diagonal = it.value();
    if (diagonal != 0.0 && std::isfinite(diagonal)) continue;
    const std::int32_t of = r < static_cast<Eigen::Index>(row_ids_.size()) ? row_ids_[r] : -1;
    std::ostringstream msg;
    msg << which << " pressure system: the row of "
        << (of >= 0 ? describeParticle(static_cast<std::size_t>(of)) : "bubble " + std::to_string(-1 - of) + "'s unknown")
        << ", has " << (diagonal == 0.0 ? "no diagonal" : "a non-finite diagonal")
        << ": nothing of the system within its reach (a particle inside a wall?)";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
}

template <int D>
void MpsSolver<D>::forgetReusedState() {
  liquid_solver_->forget();
  gas_solver_->forget();
  reorder_pending_ = true;
}

#define MISTFALL_INSTANTIATE(D) \
  template void MpsSolver<D>::solveSystem(const std::vector<double>&, const char*, int&); \
  template void MpsSolver<D>::solveLinear(const Eigen::SparseMatrix<double, Eigen::RowMajor>&, const Eigen::VectorXd&, Eigen::VectorXd&, const char*, int&); \
  template void MpsSolver<D>::forgetReusedState();
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall
