// The gas-liquid coupling, eqs. (5)-(8) and (17) (docs/two-phase.md): the roles of the particles, the liquid
// system with one pressure per bubble (eq. (17) on the bubble), a tank of still water with air above it (the
// liquid must not see the open gas at all; the gas must stay above the water, every particle accounted for) and a
// rising bubble.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/gradient.hpp"
#include "mps/number_density.hpp"
#include "mps/phase_coupling.hpp"
#include "io/checkpoint.hpp"
#include "mps/bubble_pressure.hpp"
#include "mps/pressure_poisson.hpp"
#include "support/exact_solve.hpp"
#include "support/run_case.hpp"
#include "support/tank_case.hpp"
#include "support/coarse_bubble_case.hpp"
#include "support/same_particles.hpp"
#include "mps/solver.hpp"

using namespace mistfall;
using test_support::solveExactly;
namespace fs = std::filesystem;

namespace {

// The tank of support/tank_case.hpp with gas of c = 340 m/s, optionally without the air or the bubble.
std::string tankCase(bool air, bool bubble) { return test_support::tankCase("two_phase_tank", air, bubble, "340.0"); }

struct TankRun : test_support::SolverRun<2> {
  explicit TankRun(const std::string& text) : SolverRun(text, "two_phase_tank.toml") {}
};

// The liquid system of a tank with a bubble, assembled as the solver does: one density, every bubble particle an
// unknown of the liquid's equation (9), then the bubble's unknowns merged with eq. (17)'s shift for gas sound
// speed c (bubble_pressure.hpp).
struct BubbleSystem {
  TankRun s{tankCase(false, true)};
  GasRegions regions;
  CouplingRoles roles;
  std::vector<double> n;
  std::vector<std::int32_t> group_of;
  std::size_t bubble_particles = 0;
  BubbleSystem() {
    s.solver->currentBubbles();  // builds the neighbour list at the initial positions
    const auto& p = s.state.particles;
    findGasRegions<2>(p, s.solver->neighbours(), s.solver->constants().re_number_density, 0.005, regions);
    assignCouplingRoles<2>(p, regions, roles);
    n.resize(p.size());
    group_of.assign(p.size(), -1);
    auto counts = [&](std::int32_t j) { return roles.in_liquid_system[j] != 0; };
    for (std::size_t i = 0; i < p.size(); ++i) {
      n[i] = numberDensityAt<2>(i, p.position, s.solver->neighbours(), s.solver->constants().re_number_density,
                                counts) *
             (1.0 + 1e-3 * std::sin(37.0 * i));  // a non-trivial n* field
      if (roles.enclosed_gas[i]) group_of[i] = regions.region_of[i], ++bubble_particles;
    }
  }
  LumpedPressureSystem assemble(double gas_sound_speed, double dt) const {
    const auto& p = s.state.particles;
    PressureProblem pr;
    const std::size_t count = p.size();
    pr.takes_part.assign(count, 0);
    pr.unknown.assign(count, 0);
    pr.carries_velocity = roles.in_liquid_system;
    pr.density = 1000.0;
    pr.sound_speed.assign(count, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < count; ++i) {
      pr.takes_part[i] = roles.in_liquid_system[i] && p.kind[i] != ParticleKind::Dummy;
      pr.unknown[i] = roles.enclosed_gas[i] || (pr.takes_part[i] && n[i] >= 0.97 * s.solver->constants().n0);
    }
    PressureSystem sys;
    assemblePressureSystem<2>(p, n, s.solver->neighbours(), s.solver->constants(), pr, PressureSourceTerm{}, dt, sys);
    std::vector<double> shift(regions.regionCount(), 0.0);
    for (std::size_t i = 0; i < count; ++i)
      if (group_of[i] >= 0) shift[group_of[i]] += 1000.0 / (1.2 * dt * dt * gas_sound_speed * gas_sound_speed);
    LumpedPressureSystem lumped;
    lumpPressureGroups(sys, group_of, shift, lumped);
    return lumped;
  }
};

std::string coarseBubbleCase() { return test_support::coarseBubbleCase(); }

// The first fluid particle of `phase` (of either, without one).
std::size_t firstFluid(const Particles<2>& p, std::optional<Phase> phase = std::nullopt) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid && (!phase || p.phase[i] == *phase)) return i;
  return p.size();
}

// The message of the DivergenceError the run's next step throws ("" and a failure when it does not diverge).
std::string nextStepDivergence(TankRun& run) {
  try {
    run.solver->step(1.0);
  } catch (const DivergenceError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no divergence";
  return "";
}

}  // namespace

TEST(TwoPhaseRoles, BubbleJoinsTheLiquidSystemOpenAirDoesNot) {
  TankRun s(tankCase(true, true));
  s.solver->currentBubbles();
  const auto& p = s.state.particles;
  GasRegions regions;
  findGasRegions<2>(p, s.solver->neighbours(), s.solver->constants().re_number_density, 0.005, regions);
  CouplingRoles roles;
  assignCouplingRoles<2>(p, regions, roles);
  markGasSideWalls<2>(p, s.solver->neighbours(), s.solver->constants().re_number_density, roles);
  std::size_t bubble_gas = 0, air = 0, liquid_walls = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double y = p.position[i][1];
    if (isGas(p.kind[i], p.phase[i])) {
      const bool in_bubble = y < 0.06;
      EXPECT_EQ(!in_bubble, roles.open_gas[i] != 0) << "gas particle at y = " << y;
      EXPECT_EQ(in_bubble, roles.in_liquid_system[i] != 0);
      EXPECT_EQ(in_bubble, roles.enclosed_gas[i] != 0);
      (in_bubble ? bubble_gas : air) += 1;
    } else if (p.kind[i] == ParticleKind::Fluid) {
      EXPECT_TRUE(roles.in_liquid_system[i]);
      // Liquid within re = 2.1 l0 of gas (the top two rows under the air, the rings around the bubble) is a wall
      // of the gas system; no other liquid.
      bool near_bubble = false;
      for (std::size_t j = 0; j < p.size(); ++j)
        near_bubble |= roles.enclosed_gas[j] && (p.position[j] - p.position[i]).norm() < 2.1 * 0.005;
      EXPECT_EQ(y > 0.06 - 2.1 * 0.005 || near_bubble, roles.gas_side_wall[i] != 0) << "liquid at y = " << y;
      liquid_walls += roles.gas_side_wall[i] && !near_bubble;
    } else if (p.kind[i] == ParticleKind::Dummy) {
      EXPECT_FALSE(roles.gas_side_wall[i]);
    }
  }
  EXPECT_GT(bubble_gas, 15u);
  EXPECT_EQ(air, 20u * 6u);
  EXPECT_EQ(liquid_walls, 20u * 2u);
  EXPECT_EQ(roles.gas_count, air + bubble_gas);
  EXPECT_EQ(roles.enclosed_count, bubble_gas);
  EXPECT_EQ(roles.entrained_count, 0u);
  // Below a bubble's resolution the same gas is entrained: moved as liquid, and counted (diagnostics.csv's
  // entrained_gas).
  CouplingRoles small;
  assignCouplingRoles<2>(p, regions, small, bubble_gas + 1);
  EXPECT_EQ(small.enclosed_count, 0u);
  EXPECT_EQ(small.entrained_count, bubble_gas);
  EXPECT_EQ(small.gas_count, air + bubble_gas);
}

TEST(TwoPhasePressure, BubbleSystemIsSymmetricWithOneUnknownPerBubble) {
  BubbleSystem b;
  ASSERT_GT(b.bubble_particles, 15u);
  const auto sys = b.assemble(340.0, 1e-3);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> transpose = sys.matrix.transpose();
  EXPECT_LT((sys.matrix - transpose).norm(), 1e-12 * sys.matrix.norm());
  // One row per liquid / wall unknown and one for the bubble (the tank has one enclosed region).
  ASSERT_EQ(1u, b.regions.regionCount());
  EXPECT_EQ(sys.first_group_row + 1, sys.matrix.rows());
  for (Eigen::Index r = 0; r < sys.matrix.rows(); ++r) EXPECT_GT(sys.matrix.coeff(r, r), 0.0) << "row " << r;
}

TEST(TwoPhasePressure, CompressibleBubbleTendsToIncompressibleAsSoundSpeedGrows) {
  // Eq. (17) on the bubble: only the bubble's diagonal changes, by N rho_l / (rho_g dt^2 c^2), and the solution
  // approaches the incompressible one (c = inf: the same matrix without the shift) as 1/c^2.
  BubbleSystem b;
  const double dt = 1e-3;
  const auto inc = b.assemble(std::numeric_limits<double>::infinity(), dt);
  const Eigen::VectorXd p_inf = solveExactly(inc.matrix, inc.rhs);
  std::vector<double> gaps;
  for (double c : {1e3, 1e4, 1e5, 1e6}) {  // from 1e3 m/s the shift is small against the bubble's coupling
    const auto sys = b.assemble(c, dt);
    const Eigen::SparseMatrix<double, Eigen::RowMajor> diff = sys.matrix - inc.matrix;
    const double expected = b.bubble_particles * 1000.0 / (1.2 * dt * dt * c * c);
    const Eigen::Index bubble = sys.first_group_row;
    EXPECT_NEAR(expected, diff.coeff(bubble, bubble), 1e-9 * expected + 1e-12 * inc.matrix.coeff(bubble, bubble));
    EXPECT_NEAR(std::abs(diff.coeff(bubble, bubble)), diff.norm(), 1e-9 * diff.norm() + 1e-12);
    EXPECT_EQ(0.0, (sys.rhs - inc.rhs).norm());
    gaps.push_back((solveExactly(sys.matrix, sys.rhs) - p_inf).norm() / p_inf.norm());
  }
  // 1/c^2: a tenfold c shrinks the gap a hundredfold (89 from 1e3 to 1e4 m/s, where the asymptote begins).
  for (std::size_t k = 1; k < gaps.size(); ++k) EXPECT_NEAR(100.0, gaps[k - 1] / gaps[k], 15.0) << "c step " << k;
  EXPECT_LT(gaps.back(), 1e-6);
}

TEST(TwoPhaseTank, LiquidIgnoresOpenAirAndAirStaysAbove) {
  // Eqs. (5)-(8): the liquid does not see open gas. The same tank with and without air must give the same liquid
  // motion bit for bit (the time step is dt_max in both). The air stays above the water, no particle is lost.
  TankRun with_air(tankCase(true, false));
  TankRun without(tankCase(false, false));
  const auto& pa = with_air.state.particles;
  const auto& pw = without.state.particles;
  std::size_t gas0 = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) gas0 += isGas(pa.kind[i], pa.phase[i]);
  ASSERT_EQ(gas0, 120u);
  // The liquid particles of each run, in array order (after the steps: a step may reorder the arrays, the same
  // way for the liquid of both runs, spatial_order.hpp).
  std::vector<std::size_t> liquid_a, liquid_w;
  auto listLiquid = [&] {
    liquid_a.clear(), liquid_w.clear();
    for (std::size_t i = 0; i < pa.size(); ++i)
      if (pa.kind[i] == ParticleKind::Fluid && pa.phase[i] == Phase::Liquid) liquid_a.push_back(i);
    for (std::size_t i = 0; i < pw.size(); ++i)
      if (pw.kind[i] == ParticleKind::Fluid) liquid_w.push_back(i);
  };
  listLiquid();
  ASSERT_EQ(liquid_a.size(), liquid_w.size());
  double max_gas_speed = 0;
  int gas_iterations = 0;
  for (int step = 0; step < 100; ++step) {
    const auto& ra = with_air.solver->step(1.0);
    const auto& rw = without.solver->step(1.0);
    ASSERT_EQ(ra.dt, rw.dt);
    gas_iterations = std::max(gas_iterations, ra.gas_ppe_iterations);
    EXPECT_EQ(rw.gas_ppe_iterations, 0);
    for (std::size_t i = 0; i < pa.size(); ++i)
      if (isGas(pa.kind[i], pa.phase[i])) max_gas_speed = std::max(max_gas_speed, pa.velocity[i].norm());
  }
  EXPECT_GT(gas_iterations, 0);  // the gas system was solved
  listLiquid();
  ASSERT_EQ(liquid_a.size(), liquid_w.size());
  for (std::size_t k = 0; k < liquid_a.size(); ++k) {
    ASSERT_EQ(pa.position[liquid_a[k]], pw.position[liquid_w[k]]) << "liquid particle " << k;
    ASSERT_EQ(pa.pressure[liquid_a[k]], pw.pressure[liquid_w[k]]);
  }
  // Mass of each phase: every particle still there, none escaped, none changed phase.
  std::size_t gas = 0, liquid = 0;
  double lowest_gas = 1.0, highest_liquid = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    ASSERT_NE(pa.kind[i], ParticleKind::Escaped);
    if (pa.kind[i] != ParticleKind::Fluid) continue;
    if (pa.phase[i] == Phase::Gas) ++gas, lowest_gas = std::min(lowest_gas, pa.position[i][1]);
    else ++liquid, highest_liquid = std::max(highest_liquid, pa.position[i][1]);
  }
  EXPECT_EQ(gas, gas0);
  EXPECT_EQ(liquid, liquid_a.size());
  EXPECT_GT(lowest_gas, highest_liquid);  // the air has not mixed into the water
  EXPECT_LT(max_gas_speed, 0.1) << "still air over still water";
}

// What set the time step (StepReport.liquid_dt, dt_set_by_gas; diagnostics.csv's gas_set_dt, liquid_dt_steps): a
// table of the fastest liquid and gas particles' speeds. dt is the Courant limit of the faster, the liquid's own dt
// that of the liquid alone, and the gas "sets" dt only when it is the faster and below dt_max's reach.
TEST(TwoPhaseTimeStep, ReportsWhetherTheGasSetTheStep) {
  struct Row {
    double liquid_speed, gas_speed;
    bool set_by_gas;
  };
  for (const Row& row : {Row{0.0, 0.0, false}, Row{2.0, 0.5, false}, Row{0.5, 4.0, true}, Row{0.5, 0.6, false}}) {
    TankRun run(tankCase(true, false));
    auto& p = run.state.particles;
    const double l0 = run.config.numerics.particle_spacing, courant = run.config.numerics.courant;
    const double dt_max = run.config.numerics.dt_max;
    bool liquid_set = false, gas_set = false;
    for (std::size_t i = 0; i < p.size(); ++i) {  // one particle of each phase at its speed
      if (p.kind[i] != ParticleKind::Fluid) continue;
      bool& done = p.phase[i] == Phase::Gas ? gas_set : liquid_set;
      if (done) continue;
      p.velocity[i] = Vec<2>{p.phase[i] == Phase::Gas ? row.gas_speed : row.liquid_speed, 0.0};
      done = true;
    }
    const auto& report = run.solver->step(1.0);
    const double liquid_dt = row.liquid_speed > 0 ? std::min(dt_max, courant * l0 / row.liquid_speed) : dt_max;
    const double fastest = std::max(row.liquid_speed, row.gas_speed);
    const double dt = fastest > 0 ? std::min(dt_max, courant * l0 / fastest) : dt_max;
    EXPECT_DOUBLE_EQ(liquid_dt, report.liquid_dt) << row.liquid_speed << " " << row.gas_speed;
    EXPECT_DOUBLE_EQ(dt, report.dt);
    EXPECT_EQ(row.set_by_gas, report.dt_set_by_gas);
  }
}

// A time step below numerics.dt_min stops the run with a message that names the fastest particle (its id, phase
// and role), so that a divergence says whether the water or which air set it off.
TEST(TwoPhaseTimeStep, DivergenceNamesTheFastestParticle) {
  for (const Phase phase : {Phase::Liquid, Phase::Gas}) {
    TankRun run(tankCase(true, false));
    auto& p = run.state.particles;
    const std::size_t shot = firstFluid(p, phase);
    ASSERT_LT(shot, p.size());
    p.velocity[shot] = Vec<2>{1e6, 0.0};  // dt = 0.2 l0 / 1e6 m/s = 1e-9 s < dt_min = 1e-8 s
    const std::string id = "particle id " + std::to_string(p.id[shot]) + ", ";
    const std::string what = nextStepDivergence(run);
    EXPECT_NE(what.find(id + (phase == Phase::Gas ? "open gas" : "liquid")), std::string::npos) << what;
  }
}

// A particle with nothing of its pressure system within reach gives its row no diagonal, and the solve would return
// NaN, the run ending on a non-finite particle elsewhere (traced: a stiff joined bubble's gas re-spaced 7 l0 into the
// floor, docs/validation.md). The step stops before the solve, naming the row's particle.
TEST(TwoPhaseTimeStep, AnEmptyRowStopsTheStepNamingItsParticle) {
  // The tank's water over a floor 10 l0 thick, of which the rows below the first few are dummies: they count in the
  // number density but hold no pressure.
  const std::string text = "[case]\nname = \"sunk\"\ndimension = 2\n[domain]\nmin = [-0.05, -0.05]\n"
                           "max = [0.15, 0.12]\n[numerics]\nparticle_spacing = 0.005\ndt_max = 5e-4\n[output]\n"
                           "end_time = 1.0\n[[region]]\nname = \"water\"\nmaterial = \"water\"\nmin = [0.0, 0.0]\n"
                           "max = [0.1, 0.06]\n" + test_support::tankWalls(0.1, 0.09, 0.05);
  TankRun run(text);
  auto& p = run.state.particles;
  const std::size_t sunk = firstFluid(p);
  ASSERT_LT(sunk, p.size());
  p.position[sunk] = Vec<2>{0.05, -0.03};  // 6 l0 into the floor, 4 l0 above its bottom, between its lattice points
  const std::string id = "particle id " + std::to_string(p.id[sunk]) + ", liquid";  // the step re-orders the arrays
  const std::string what = nextStepDivergence(run);
  EXPECT_NE(what.find("liquid pressure system: the row of " + id), std::string::npos) << what;
  EXPECT_NE(what.find("no diagonal"), std::string::npos) << what;
}

// The coarse bubble for 0.15 s: the bubble stays one body with bounded pressure and rises, the water
// surface far from it stays flat, and no particle of either phase is lost.
TEST(TwoPhaseBubble, CoarseBubbleRisesAsOneBodyWithBoundedPressure) {
  TankRun s(coarseBubbleCase());
  auto& p = s.state.particles;
  const std::size_t liquid = p.count(ParticleKind::Fluid, Phase::Liquid), gas = p.count(ParticleKind::Fluid, Phase::Gas);
  const auto start = s.solver->currentBubbles();
  ASSERT_EQ(1u, start.size());
  const std::size_t bubble_particles = start[0].particles;
  EXPECT_EQ(62u, bubble_particles);
  const double depth = 0.15 - start[0].centroid[1];
  const double hydrostatic = 1000.0 * 9.81 * depth;  // 564 Pa at the centre
  std::vector<double> height{start[0].centroid[1]};
  for (int k = 1; k <= 15; ++k) {
    const double t = 0.01 * k;
    while (s.state.time < t - 1e-12) s.solver->step(t);
    const auto bubbles = s.solver->currentBubbles();
    ASSERT_EQ(1u, bubbles.size()) << "t = " << t;
    EXPECT_EQ(bubble_particles, bubbles[0].particles) << "t = " << t;
    EXPECT_GT(bubbles[0].mean_pressure, 0.2 * hydrostatic) << "t = " << t;
    EXPECT_LT(bubbles[0].mean_pressure, 2.0 * hydrostatic) << "t = " << t;
    height.push_back(bubbles[0].centroid[1]);
  }
  // It rises at every 0.03 s after the start-up, by more than 1 cm in 0.15 s (measured 1.6 cm; the resolved
  // run, cases/bubble_rise.toml, rises at 0.22 m/s, docs/two-phase.md).
  for (int k = 6; k <= 15; k += 3) EXPECT_GT(height[k], height[k - 3]) << "t = " << 0.01 * k;
  EXPECT_GT(height[15] - height[0], 0.01);
  // The free surface near the side walls (more than 3 bubble radii away) stays flat within a particle size.
  double top_left = -1.0, top_right = -1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Liquid) continue;
    if (p.position[i][0] < 0.03) top_left = std::max(top_left, p.position[i][1]);
    if (p.position[i][0] > 0.17) top_right = std::max(top_right, p.position[i][1]);
  }
  EXPECT_NEAR(0.1475, top_left, 0.005);  // the top row starts at 0.1475
  EXPECT_NEAR(0.1475, top_right, 0.005);
  // Mass of each phase: every particle still in the domain, none changed phase.
  EXPECT_EQ(liquid, p.count(ParticleKind::Fluid, Phase::Liquid));
  EXPECT_EQ(gas, p.count(ParticleKind::Fluid, Phase::Gas));
  EXPECT_EQ(0u, p.count(ParticleKind::Escaped));
}

// A run stopped and resumed from its checkpoint continues bit for bit: the bubble flags (delta_gl) that keep a
// bubble enclosed through small gaps travel in the checkpoint with the particles, and so do the reference pressures
// of a bubble started at the water's pressure (numerics.bubble_initial_pressure, with the memory term).
struct ResumeCase {
  const char* name;
  const char* numerics;  // appended to the coarse bubble's [numerics]
};

class TwoPhaseResume : public ::testing::TestWithParam<ResumeCase> {};

TEST_P(TwoPhaseResume, ResumeFromCheckpointIsBitIdentical) {
  const std::string text = test_support::coarseBubbleCase(GetParam().numerics);
  TankRun whole(text);  // stops at 0.03 too (an output time), so both take the same steps
  while (whole.state.time < 0.03 - 1e-12) whole.solver->step(0.03);
  while (whole.state.time < 0.06 - 1e-12) whole.solver->step(0.06);
  TankRun first(text);
  while (first.state.time < 0.03 - 1e-12) first.solver->step(0.03);
  const fs::path file = fs::temp_directory_path() / "mistfall_two_phase_resume.ckpt";
  writeCheckpoint<2>(file, first.state);
  TankRun second(text);
  second.state = readCheckpoint<2>(file);
  fs::remove(file);
  second.solver = std::make_unique<MpsSolver<2>>(second.config, second.state);
  EXPECT_GT(std::count(second.state.particles.enclosed.begin(), second.state.particles.enclosed.end(), 1), 50);
  EXPECT_EQ(first.state.gas_reference_pressure, second.state.gas_reference_pressure);
  while (second.state.time < 0.06 - 1e-12) second.solver->step(0.06);
  EXPECT_EQ(whole.state.step, second.state.step);
  test_support::expectSameParticles(whole.state.particles, second.state.particles);
}

INSTANTIATE_TEST_SUITE_P(
    Bubbles, TwoPhaseResume,
    ::testing::Values(ResumeCase{"soft", ""},
                      ResumeCase{"stiff_from_the_water_pressure", "scheme = \"stabilised\"\ncollision_distance = 0.8\n"
                                                                  "gas_pressure_memory = true\n"}),
    [](const ::testing::TestParamInfo<ResumeCase>& info) { return info.param.name; });
