// The pressure Poisson system, eqs. (9), (16), (17): symmetry, the c -> infinity limit of the compressible
// equation, and agreement of the two linear solvers on a real system.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mps/linear_solver.hpp"
#include "mps/number_density.hpp"
#include "mps/pressure_poisson.hpp"
#include "support/exact_solve.hpp"
#include "support/run_case.hpp"

using namespace mistfall;
using test_support::solveExactly;

namespace {

// The hydrostatic tank after a few steps: a realistic n* field with a free surface and walls.
struct TankSystem {
  CaseConfig config = test_support::loadShippedCase("hydrostatic.toml");
  SimulationState<2> state;
  std::unique_ptr<MpsSolver<2>> solver;
  std::vector<char> surface;
  TankSystem() {
    state.particles = buildParticles<2>(config);
    solver = std::make_unique<MpsSolver<2>>(config, state);
    for (int i = 0; i < 5; ++i) solver->step(1.0);
    surface = freeSurfaceFlags(state.particles, config.numerics.surface_threshold, solver->constants().n0);
  }
  PressureSystem assemble(double sound_speed, double dt) const {
    PhaseProperties liquid = config.physics.liquid;
    liquid.sound_speed = sound_speed;
    PressureSystem sys;
    assemblePressureSystem<2>(state.particles, state.particles.number_density, solver->neighbours(),
                              solver->constants(), singlePhaseProblem(state.particles, liquid, surface),
                              PressureSourceTerm{PressureSource::Standard, 1.0}, dt, sys);
    return sys;
  }
};

Eigen::VectorXd solveWith(PressureSolverKind kind, const PressureSystem& sys) {
  auto solver = makeLinearSolver(kind, 1e-10, 5000);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sys.rhs.size());
  const auto r = solver->solve(sys.matrix, sys.rhs, x);
  EXPECT_TRUE(r.converged) << solver->name() << " residual " << r.relative_residual;
  return x;
}


}  // namespace

TEST(PressurePoisson, MatrixIsSymmetricWithPositiveDiagonal) {
  TankSystem t;
  const auto sys = t.assemble(std::numeric_limits<double>::infinity(), 1e-3);
  ASSERT_GT(sys.matrix.rows(), 100);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> transpose = sys.matrix.transpose();
  EXPECT_LT((sys.matrix - transpose).norm(), 1e-12 * sys.matrix.norm());
  for (Eigen::Index r = 0; r < sys.matrix.rows(); ++r) EXPECT_GT(sys.matrix.coeff(r, r), 0.0);
}

TEST(PressurePoisson, CompressibleEquationTendsToIncompressibleAsSoundSpeedGrows) {
  TankSystem t;
  const double dt = 1e-3;
  const auto incompressible = t.assemble(std::numeric_limits<double>::infinity(), dt);
  const Eigen::VectorXd p_inf = solveExactly(incompressible);
  double previous = std::numeric_limits<double>::infinity();
  std::vector<double> gaps;
  for (double c : {10.0, 100.0, 1000.0, 1e5}) {
    const auto sys = t.assemble(c, dt);
    // Same sparsity, same off-diagonal; the diagonal differs by exactly 1/(dt^2 c^2), eq. (17).
    ASSERT_EQ(sys.matrix.nonZeros(), incompressible.matrix.nonZeros());
    const Eigen::SparseMatrix<double, Eigen::RowMajor> diff = sys.matrix - incompressible.matrix;
    for (Eigen::Index r = 0; r < diff.rows(); ++r)
      EXPECT_NEAR(diff.coeff(r, r), 1.0 / (dt * dt * c * c),
                  1e-9 / (dt * dt * c * c) + 1e-14 * incompressible.matrix.coeff(r, r));
    const Eigen::VectorXd p_c = solveExactly(sys);
    const double gap = (p_c - p_inf).norm() / p_inf.norm();
    std::printf("c = %8.0f m/s: |p_c - p_inf| / |p_inf| = %.3e\n", c, gap);
    EXPECT_LT(gap, previous) << "c = " << c;
    previous = gap;
    gaps.push_back(gap);
  }
  // Asymptotically the shift E/(dt^2 c^2) perturbs the solution by O(1/c^2): c from 1e3 to 1e5 cuts it 1e4x.
  EXPECT_NEAR(gaps[2] / gaps[3], 1e4, 0.2e4);
  EXPECT_LT(gaps[3], 1e-5);
}

TEST(PressurePoisson, IccgAndAmgAgree) {
  TankSystem t;
  const auto sys = t.assemble(std::numeric_limits<double>::infinity(), 1e-3);
  const Eigen::VectorXd a = solveWith(PressureSolverKind::EigenIccg, sys);
  const Eigen::VectorXd b = solveWith(PressureSolverKind::HypreAmg, sys);
  EXPECT_LT((a - b).norm(), 1e-7 * a.norm());
  EXPECT_LT(relativeResidual(sys.matrix, sys.rhs, b), 1e-9);
}
