// The particle shifting of the stabilised scheme (numerics.particle_shifting, src/mps/particle_shifting.hpp):
//  * a particle at rest is not shifted, whatever its neighbourhood (the still tanks stay exact);
//  * on a full lattice nothing is shifted at any speed, and on a free-surface row's (cut) lattice nothing either
//    once the normal part is removed;
//  * a particle whose neighbour crowds it from one side moves away from it, by A l0 |u| dt D0/n0 |first moment|;
//  * numerics.shift_limit cuts a close pair's shift to its length and counts it; with shifting_kernel = "wendland" a
//    close pair's shift is bounded whatever its distance;
//  * a water particle on an even interface with air is not shifted into the air when the air counts in the sum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/particle_shifting.hpp"
#include "mps/solver.hpp"
#include "support/shaped_lattice.hpp"

using namespace mistfall;
using namespace mistfall::test_support;

namespace {

auto all = [](std::int32_t) { return true; };

template <int D>
void checkNoShiftAtRestOrOnALattice(Shape shape) {
  const auto x = lattice<D>(shape);
  const MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<D>(x, c.re_laplacian);
  Vec<D> normal = Vec<D>::Zero();
  normal[D - 1] = -1.0;  // the pressure gradient's direction under a free surface
  for (const auto kernel : {NumericsConfig::ShiftingKernel::Mps, NumericsConfig::ShiftingKernel::Wendland}) {
    auto shift = [&](const Vec<D>& u, const Vec<D>& n) {
      return shiftingDisplacement<D>(0, x, nl, c, 2.0, u, 1e-3, n, all, kernel);
    };
    EXPECT_EQ(shift(Vec<D>::Zero(), Vec<D>::Zero()).norm(), 0.0);
    const Vec<D> moving = Vec<D>::Constant(0.5);
    if (shape == Shape::Full) EXPECT_LT(shift(moving, Vec<D>::Zero()).norm(), 1e-15);
    if (shape == Shape::CutAbove) {
      EXPECT_GT(shift(moving, Vec<D>::Zero()).norm(), 1e-7);
      EXPECT_LT(shift(moving, normal).norm(), 1e-15);
    }
  }
}

class ShiftingOnLattices : public ::testing::TestWithParam<Neighbourhood> {};
INSTANTIATE_TEST_SUITE_P(Shapes, ShiftingOnLattices, ::testing::ValuesIn(kShapes), shapeName);

}  // namespace

TEST_P(ShiftingOnLattices, NoneAtRestNoneOnALattice2D) { checkNoShiftAtRestOrOnALattice<2>(GetParam().shape); }
TEST_P(ShiftingOnLattices, NoneAtRestNoneOnALattice3D) { checkNoShiftAtRestOrOnALattice<3>(GetParam().shape); }

// A full 2D lattice whose neighbour at +x sits at 0.6 l0: the particle, moving at 0.3 m/s with dt = 1 ms, is shifted
// towards -x by A l0 |u| dt D0/n0 times the first moment.
TEST(ParticleShifting, MovesAwayFromACrowdingNeighbourByTheFormula) {
  auto x = lattice<2>(Shape::Full);
  for (auto& r : x)
    if ((r - Vec<2>(kL0, 0.0)).norm() < 1e-12) r = Vec<2>(0.6 * kL0, 0.0);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  const Vec<2> u(0.0, 0.3);
  const Vec<2> shift = shiftingDisplacement<2>(0, x, nl, c, 2.0, u, 1e-3, Vec<2>::Zero(), all);
  Vec<2> first = Vec<2>::Zero();
  for (std::size_t j = 1; j < x.size(); ++j) {
    const double r = x[j].norm();
    if (r < c.re_number_density) first += x[j] * ((c.re_number_density / r - 1.0) / (r * r));
  }
  EXPECT_LT(shift.x(), 0.0);
  EXPECT_NEAR(shift.x(), -2.0 * kL0 * 0.3 * 1e-3 * 2.0 / c.n0 * first.x(), 1e-12 * kL0);
  EXPECT_NEAR(shift.y(), 0.0, 1e-15);
}

// numerics.shifting_kernel = "wendland": a full 2D lattice whose neighbour at +x sits at d instead of l0 (moving at
// 0.3 m/s, dt = 1 ms, A = 2). The shift is -A h |u| dt l0^2 (f(d) - f(l0)) along x, f(r) = 5 alpha q (1 - q/2)^3 / h
// the kernel's |dW/dr| (q = r / h, h = re / 2), the rest of the lattice summing to -f(l0): at most 1.055 alpha l0^2
// A |u| dt for any d, where the MPS weight's first moment grows as 1/d^2 (at d = 0.01 l0 over 10^4 times more).
TEST(ParticleShifting, TheWendlandShiftOfACloseNeighbourIsBoundedWhereTheMpsOneIsNot) {
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const double h = 0.5 * c.re_number_density, alpha = 7.0 / (4.0 * std::numbers::pi * h * h), a = 2.0, step = 0.3e-3;
  auto f = [&](double r) {
    const double q = r / h;
    return 5.0 * alpha * q * std::pow(1.0 - 0.5 * q, 3) / h;
  };
  const double bound = 1.055 * alpha * kL0 * kL0 * a * step;
  for (const double d : {0.9, 0.6, 0.3, 0.1, 0.01}) {
    auto x = lattice<2>(Shape::Full);
    for (auto& r : x)
      if ((r - Vec<2>(kL0, 0.0)).norm() < 1e-12) r = Vec<2>(d * kL0, 0.0);
    const auto nl = neighboursOf<2>(x, c.re_laplacian);
    auto shift = [&](NumericsConfig::ShiftingKernel kernel) {
      return shiftingDisplacement<2>(0, x, nl, c, a, Vec<2>(0.0, 0.3), 1e-3, Vec<2>::Zero(), all, kernel);
    };
    const Vec<2> wendland = shift(NumericsConfig::ShiftingKernel::Wendland);
    const Vec<2> mps = shift(NumericsConfig::ShiftingKernel::Mps);
    EXPECT_NEAR(wendland.x(), -a * h * step * kL0 * kL0 * (f(d * kL0) - f(kL0)), 1e-12 * kL0) << d;
    EXPECT_NEAR(wendland.y(), 0.0, 1e-15) << d;
    EXPECT_LT(wendland.norm(), bound) << d;
    if (d >= 0.6) EXPECT_LT(wendland.x(), 0.0) << d;  // moved away from the crowding neighbour
    if (d <= 0.01) EXPECT_GT(mps.norm(), 1e4 * wendland.norm()) << d;
  }
}

// A water particle on a flat interface with air above it (the full lattice, its upper half air), moving along it,
// with a surface normal 30 degrees off the interface's (the last pressure gradient in a falling sheet is noise):
// counting only the water in the first moment, as the two systems did before the twentieth session, the truncated
// neighbourhood shifts it up, into the air; counting both phases, as the solver does now, it is not shifted at all
// (solver_liquid_stabilised.cpp, shiftParticles).
TEST(ParticleShifting, AWaterParticleOnAnEvenInterfaceIsNotShiftedIntoTheAirWhateverItsNormal) {
  const auto x = lattice<2>(Shape::Full);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  auto water = [&](std::int32_t j) { return x[j].y() <= 1e-12; };
  const double tilt = 30.0 * M_PI / 180.0;
  const Vec<2> normal(std::sin(tilt), -std::cos(tilt));
  const Vec<2> u(1.0, 0.0);
  const Vec<2> water_only = shiftingDisplacement<2>(0, x, nl, c, 2.0, u, 1e-3, normal, water);
  const Vec<2> both_phases = shiftingDisplacement<2>(0, x, nl, c, 2.0, u, 1e-3, normal, all);
  EXPECT_GT(water_only.y(), 1e-3 * water_only.norm());
  EXPECT_GT(water_only.norm(), 1e-7);
  EXPECT_LT(both_phases.norm(), 1e-15);
}

namespace {

// Water moving at 5 m/s over a floor (stabilised scheme, l0 = 1 cm): the case, and the particle at `at` in it.
struct FastWater {
  CaseConfig config;
  SimulationState<2> state;
  FastWater(double shift_limit, bool wall_stop, double shift_stability = 0.0) {
    const std::string text = R"(
[case]
name = "close_pair"
dimension = 2
[domain]
min = [-0.04, -0.04]
max = [0.24, 0.24]
[numerics]
particle_spacing = 0.01
scheme = "stabilised"
pressure_source = "mixed"
source_relaxation = 0.01
dt_max = 5e-4
shift_limit = )" + std::to_string(shift_limit) + R"(
shift_wall_stop = )" + (wall_stop ? "true" : "false") + R"(
shift_stability = )" + std::to_string(shift_stability) + R"(
[output]
end_time = 1.0
[[region]]
name = "water"
material = "water"
min = [0.0, 0.0]
max = [0.2, 0.1]
velocity = [5.0, 0.0]
[[region]]
name = "box"
material = "wall"
min = [-0.04, -0.04]
max = [0.24, 0.0]
)";
    config = parseCase(text, "close_pair.toml");
    state.particles = buildParticles<2>(config);
  }
  std::size_t at(const Vec<2>& x) const {
    const auto& p = state.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      if ((p.position[i] - x).norm() < 1e-9) return i;
    return p.size();
  }
};

// One particle put 0.5 l0 from its neighbour: a close pair in a fast flow. Returns the step's report and how far that
// particle moved.
std::pair<StepReport, double> stepWithAClosePair(double shift_limit, double shift_stability = 0.0) {
  FastWater water(shift_limit, false, shift_stability);
  auto& p = water.state.particles;
  const std::size_t anchor = water.at(Vec<2>(0.105, 0.045)), moved = water.at(Vec<2>(0.115, 0.045));
  p.position[moved] = p.position[anchor] + Vec<2>(0.005, 0.0);
  const Vec<2> before = p.position[moved];
  MpsSolver<2> solver(water.config, water.state);
  const StepReport report = solver.step(1.0);
  return {report, (p.position[moved] - before).norm()};
}

// The pair at the floor: one particle more put 0.25 l0 above one of the lowest row (no hole left above it: a hole
// reads as a free surface, whose normal takes the vertical shift), whose correction and shift then point at the floor.
// Returns the step's report and that lowest particle's distance from its nearest wall particle.
std::pair<StepReport, double> stepWithAPairAtTheFloor(bool wall_stop) {
  FastWater water(1.0, wall_stop);
  auto& p = water.state.particles;
  const std::size_t lowest = water.at(Vec<2>(0.105, 0.005));
  p.add(p.position[lowest] + Vec<2>(0.0, 0.0025), p.velocity[lowest], ParticleKind::Fluid, Phase::Liquid);
  const std::uint64_t id = p.id[lowest];
  MpsSolver<2> solver(water.config, water.state);
  const StepReport report = solver.step(1.0);
  std::size_t i = 0;
  while (p.id[i] != id) ++i;
  double nearest = 1.0;
  for (std::size_t j = 0; j < p.size(); ++j)
    if (isFixed(p.kind[j])) nearest = std::min(nearest, (p.position[j] - p.position[i]).norm());
  return {report, nearest};
}

}  // namespace

// numerics.shift_limit (a guard): shifts longer than the limit are cut and counted (here 0.29 l0 at most, in a fast
// flow with a close pair: the longest is the water meeting the right wall, the test below); a limit above the longest
// shift cuts nothing, and the trajectory is the unlimited one.
TEST(ParticleShifting, TheShiftLimitCutsTheShiftsAboveItAndCountsThem) {
  const auto [free_report, free_move] = stepWithAClosePair(0.0);
  EXPECT_GT(free_report.largest_shift, 0.2);
  EXPECT_EQ(0u, free_report.shift_cuts);
  const auto [cut_report, cut_move] = stepWithAClosePair(0.2);
  EXPECT_GT(cut_report.shift_cuts, 0u);
  EXPECT_DOUBLE_EQ(free_report.largest_shift, cut_report.largest_shift);  // the shift as computed, before the cut
  const auto [loose_report, loose_move] = stepWithAClosePair(1.0);
  EXPECT_EQ(0u, loose_report.shift_cuts);
  EXPECT_DOUBLE_EQ(free_move, loose_move);
}

// The step names the particle of its largest shift (diagnostics.csv's largest_shift_id and largest_shift_time, for
// --trace): in the fast flow one of its fluid particles, in the step that starts at t = 0 (here the water meeting the
// right wall, 0.29 l0); water starting at rest, by under a thousandth of a spacing (0.00058 l0: its first step).
TEST(ParticleShifting, TheStepNamesTheParticleItShiftedFurthest) {
  for (const double speed : {5.0, 0.0}) {
    FastWater water(0.0, false);
    auto& p = water.state.particles;
    for (auto& u : p.velocity) u.x() = speed;
    std::set<std::int64_t> fluid;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid) fluid.insert(static_cast<std::int64_t>(p.id[i]));
    MpsSolver<2> solver(water.config, water.state);
    const StepReport report = solver.step(1.0);
    if (speed > 0.0) {
      EXPECT_GT(report.largest_shift, 0.2);
      EXPECT_EQ(1u, fluid.count(report.largest_shift_id)) << report.largest_shift_id;
      EXPECT_EQ(0.0, report.largest_shift_time);
    } else {
      EXPECT_LT(report.largest_shift, 1e-3);
    }
  }
}

// numerics.shift_wall_stop (a guard, counted): a close pair above the lowest row shifts the lowest particle towards
// the floor (the correction gives it 3.8 m/s downwards, as at 7 mm: docs/waterfall.md). Without the stop, with shifts
// of at most a spacing (the shipped waterfall_small), it ends inside the floor's first row, 0.27 l0 from a wall
// particle; with it, no nearer than the collision distance (0.5 l0 here; 0.91 l0 measured), and the stop is counted.
TEST(ParticleShifting, TheWallStopKeepsAShiftFromCarryingWaterOntoTheFloor) {
  const auto [free_report, free_nearest] = stepWithAPairAtTheFloor(false);
  const auto [stop_report, stop_nearest] = stepWithAPairAtTheFloor(true);
  std::printf("nearest wall particle after the step: %.3f l0 without the stop, %.3f l0 with it (%zu stops)\n",
              free_nearest / 0.01, stop_nearest / 0.01, stop_report.shift_wall_stops);
  EXPECT_EQ(0u, free_report.shift_wall_stops);
  EXPECT_LT(free_nearest, 0.5 * 0.01);
  EXPECT_GT(stop_report.shift_wall_stops, 0u);
  EXPECT_GE(stop_nearest, 0.5 * 0.01 - 1e-12);
}

// numerics.shift_stability (shift_stability.hpp): in the fast flow with a close pair (the particle 0.5 l0 from its
// neighbour, 5 m/s, dt 0.5 ms: A |u| dt / l0 = 0.75, four times the bound on a full lattice at beta = 1) the bound
// cuts shifts, counts them, and shortens the longest; a beta above every particle's K S cuts nothing and leaves the
// trajectory as without it.
TEST(ParticleShifting, TheStabilityBoundShortensTheShiftsAboveItAndCountsThem) {
  const auto [free_report, free_move] = stepWithAClosePair(0.0);
  EXPECT_EQ(0u, free_report.shift_bounded);
  const auto [bounded_report, bounded_move] = stepWithAClosePair(0.0, 1.0);
  EXPECT_GT(bounded_report.shift_bounded, 0u);
  EXPECT_LT(bounded_report.largest_shift, 0.5 * free_report.largest_shift);
  const auto [loose_report, loose_move] = stepWithAClosePair(0.0, 10.0);
  EXPECT_EQ(0u, loose_report.shift_bounded);
  EXPECT_DOUBLE_EQ(free_move, loose_move);
}
