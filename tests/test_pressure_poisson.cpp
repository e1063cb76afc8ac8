// The pressure Poisson system, eqs. (9), (16), (17): symmetry, the c -> infinity limit of the compressible
// equation, and agreement of the two linear solvers on a real system.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mps/linear_solver.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/number_density.hpp"
#include "mps/pressure_poisson.hpp"
#include "support/exact_solve.hpp"
#include "support/lattice.hpp"
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

// Eq. (17) with the mixed source (numerics.gas_pressure_memory, pressure_poisson.hpp): gas at rest, compressed
// uniformly by delta, holds p = rho c^2 delta from one step to the next; without the memory term its rows give
// source_relaxation times that (the gas 1/gamma = 100 times too soft at gamma = 0.01). A 21 x 21 block of gas on a
// lattice 0.4 % closer than l0, every particle an unknown (a closed gas), no velocity; every particle is given the
// centre's n* (the block is a piece of a uniformly compressed gas, without the number-density deficit of its edges).
TEST(PressurePoisson, CompressedGasAtRestHoldsRhoCSquaredDeltaWithTheMemoryTerm) {
  const double l0 = 0.005, squeeze = 0.996, rho = 1.2, c = 340.0, dt = 2.5e-4, gamma = 0.01;
  Particles<2> p;
  test_support::forEachLatticePoint<2>(Eigen::Vector2i(-10, -10), Eigen::Vector2i(10, 10), [&](const Eigen::Vector2i& k) {
    p.add(squeeze * l0 * k.cast<double>(), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Gas);
  });
  const MpsConstants constants = referenceConstants(2, l0, 2.1, 3.1);
  NeighbourSearch<2> search(Vec<2>::Constant(-0.06), Vec<2>::Constant(0.06), constants.re_laplacian);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  const std::size_t centre = p.size() / 2;
  const std::vector<double> n_star(p.size(), numberDensityAt<2>(centre, p.position, nl, constants.re_number_density));
  PressureProblem problem;
  problem.takes_part.assign(p.size(), 1);
  problem.unknown.assign(p.size(), 1);
  problem.carries_velocity.assign(p.size(), 1);
  problem.sound_speed.assign(p.size(), c);
  problem.density = rho;
  const double delta = (n_star[centre] - constants.n0) / constants.n0;
  ASSERT_GT(delta, 0.005);
  const double equilibrium = rho * c * c * delta;
  const PressureSourceTerm source{PressureSource::Mixed, gamma};
  auto nextPressure = [&](bool memory) {
    problem.extra_rhs.assign(p.size(), 0.0);
    if (memory)
      for (std::size_t i = 0; i < p.size(); ++i)
        problem.extra_rhs[i] = compressibleMemoryTerm(source, rho * c * c * (n_star[i] - constants.n0) / constants.n0,
                                                      dt, c);
    PressureSystem sys;
    assemblePressureSystem<2>(p, n_star, nl, constants, problem, source, dt, sys);
    return test_support::solveExactly(sys.matrix, sys.rhs);
  };
  const Eigen::VectorXd with = nextPressure(true), without = nextPressure(false);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(with[i], equilibrium, 1e-6 * equilibrium) << "particle " << i;
    EXPECT_NEAR(without[i], gamma * equilibrium, 1e-6 * equilibrium) << "particle " << i;
  }
  EXPECT_EQ(compressibleMemoryTerm(PressureSourceTerm{PressureSource::Standard, 1.0}, 100.0, dt, c), 0.0);
  EXPECT_EQ(compressibleMemoryTerm(source, 100.0, dt, std::numeric_limits<double>::infinity()), 0.0);
}

namespace {

// A 2D five-point Laplacian with a small diagonal shift (eq. (17)'s form) on the cells (x, y) of an n x n grid
// that `inside` keeps (the others are Dirichlet 0); the rows' keys are the cells' numbers, as particle ids are.
struct GridSystem {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  Eigen::VectorXd rhs;
  std::vector<std::int64_t> keys;
};

template <class Inside>
GridSystem gridSystem(int n, Inside inside) {
  GridSystem g;
  std::vector<int> row(n * n, -1);
  for (int c = 0; c < n * n; ++c)
    if (inside(c % n, c / n)) row[c] = static_cast<int>(g.keys.size()), g.keys.push_back(c);
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t r = 0; r < g.keys.size(); ++r) {
    const int c = static_cast<int>(g.keys[r]), x = c % n, y = c / n;
    entries.emplace_back(r, r, 4.01);
    const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& q : next)
      if (q[0] >= 0 && q[0] < n && q[1] >= 0 && q[1] < n && row[q[1] * n + q[0]] >= 0)
        entries.emplace_back(r, row[q[1] * n + q[0]], -1.0);
  }
  g.matrix.resize(static_cast<Eigen::Index>(g.keys.size()), static_cast<Eigen::Index>(g.keys.size()));
  g.matrix.setFromTriplets(entries.begin(), entries.end());
  g.matrix.makeCompressed();
  g.rhs.resize(g.matrix.rows());
  for (Eigen::Index r = 0; r < g.rhs.size(); ++r) g.rhs[r] = std::sin(0.37 * static_cast<double>(g.keys[r]));
  return g;
}

}  // namespace

// The amg solver's reuse of its hierarchy for a system whose rows changed (linear_solver.hpp): rows that come and
// go (particles joining and leaving the gas system) keep the kept hierarchy while enough rows are kept, and the
// solution still meets the tolerance; too many new rows, or kept_rows = 1, mean a new setup.
TEST(PressurePoisson, AmgReusesItsHierarchyWhileMostRowsAreKept) {
  constexpr int n = 70;
  const GridSystem first = gridSystem(n, [](int x, int) { return x < n - 2; });
  // 3 % of the rows changed: a column of cells leaves, another comes in, a few in the middle become Dirichlet
  const GridSystem moved = gridSystem(n, [](int x, int y) { return x != 0 && x < n - 1 && !(x == 30 && y % 3 == 0); });
  const GridSystem other = gridSystem(n, [](int x, int y) { return (x + y) % 5 != 0; });  // 20 % of the rows gone
  struct Row {
    double kept_rows;
    const GridSystem* second;
    bool reused;
  };
  for (const Row& row : {Row{0.9, &moved, true}, Row{1.0, &moved, false}, Row{0.9, &other, false}}) {
    SCOPED_TRACE(testing::Message() << "kept_rows " << row.kept_rows << ", second system of "
                                    << row.second->keys.size() << " rows");
    auto solver = makeLinearSolver(PressureSolverKind::HypreAmg, 1e-10, 500, PreconditionerReuse{8, 10, row.kept_rows});
    Eigen::VectorXd x = Eigen::VectorXd::Zero(first.rhs.size());
    const auto setup = solver->solve(first.matrix, first.rhs, x, &first.keys);
    EXPECT_FALSE(setup.reused);
    const GridSystem& s = *row.second;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(s.rhs.size());
    const auto result = solver->solve(s.matrix, s.rhs, y, &s.keys);
    EXPECT_EQ(result.reused, row.reused);
    // the kept coarse levels no longer see the changed rows: more iterations, boundedly (9 -> 17 here)
    EXPECT_LE(result.iterations, 2 * setup.iterations + 2);
    EXPECT_TRUE(result.converged);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> exact(Eigen::SparseMatrix<double>(s.matrix));
    const Eigen::VectorXd reference = exact.solve(s.rhs);
    EXPECT_LT((y - reference).norm(), 1e-8 * reference.norm());
    // ... and the same system again keeps the hierarchy (as fitted), converging as well
    Eigen::VectorXd z = Eigen::VectorXd::Zero(s.rhs.size());
    const auto again = solver->solve(s.matrix, s.rhs, z, &s.keys);
    EXPECT_TRUE(again.reused);
    EXPECT_LT((z - reference).norm(), 1e-8 * reference.norm());
  }
}
