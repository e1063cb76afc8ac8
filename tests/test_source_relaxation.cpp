// numerics.source_relaxation_basis (pressure_poisson.hpp sourceTermFor): the mixed source's number-density term
// moves a particle by about gamma delta l0 per step, so the velocity it gives is ~ gamma delta L / dt. Relaxed per
// step (Tanaka & Masunaga), a step cut short by the Courant limit kicks the water harder by the same factor; relaxed
// per time (gamma per dt_max), the kick keeps its size. On the one-equation waterfall a 32x shorter step turned the
// pool's slight density error into -3 MPa and 50 m/s (docs/two-phase.md); these tests are that in a tank.
#include <gtest/gtest.h>

#include <algorithm>

#include "mps/pressure_poisson.hpp"
#include "support/run_case.hpp"

using namespace mistfall;

namespace {

TEST(SourceRelaxation, PerTimeScalesGammaWithAStepShorterThanDtMax) {
  NumericsConfig n;
  n.pressure_source = PressureSource::Mixed;
  n.source_relaxation = 0.01;
  n.dt_max = 1e-3;
  EXPECT_DOUBLE_EQ(sourceTermFor(n, 1e-3).relaxation, 0.01);
  EXPECT_DOUBLE_EQ(sourceTermFor(n, 2.5e-4).relaxation, 0.01);  // "step", the default
  n.source_relaxation_per_time = true;
  EXPECT_DOUBLE_EQ(sourceTermFor(n, 1e-3).relaxation, 0.01);  // a full step is unchanged
  EXPECT_DOUBLE_EQ(sourceTermFor(n, 2.5e-4).relaxation, 0.0025);
}

// The largest speed in the water after one step of length dt from the shipped still tank with its water squeezed
// uniformly by 1 % in height (a density error delta ~ 1 % everywhere, as a pool's lattice drifts to).
double speedAfterOneStep(bool per_time, double dt) {
  CaseConfig c = test_support::loadShippedCase("hydrostatic.toml");
  c.numerics.source_relaxation = 0.01;
  c.numerics.source_relaxation_per_time = per_time;
  SimulationState<2> state;
  state.particles = buildParticles<2>(c);
  auto& p = state.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid) p.position[i][1] *= 0.99;
  MpsSolver<2> solver(c, state);
  // From rest the Courant limit allows dt_max; a step towards an output time less than dt_max away is cut to reach
  // it, and one less than 2 dt_max away is halved (solver.cpp), so `until` = dt for a short step, 2 dt for dt_max.
  solver.step(dt < c.numerics.dt_max ? dt : 2.0 * dt);
  EXPECT_DOUBLE_EQ(state.dt, dt);
  double fastest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid) fastest = std::max(fastest, p.velocity[i].norm());
  return fastest;
}

struct Basis {
  const char* name;
  bool per_time;
  double low, high;  // bounds on (speed after a dt_max/32 step) / (speed after a dt_max step)
};

class SourceRelaxationBasis : public ::testing::TestWithParam<Basis> {};

const Basis kBases[] = {
    {"per_step_kicks_32x_harder", false, 16.0, 64.0},
    {"per_time_keeps_the_kick", true, 0.5, 2.0},
};

INSTANTIATE_TEST_SUITE_P(Tank, SourceRelaxationBasis, ::testing::ValuesIn(kBases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_P(SourceRelaxationBasis, ShortStepKicksTheSqueezedWater) {
  const Basis& b = GetParam();
  const double dt_max = 1e-3;  // hydrostatic.toml
  const double full = speedAfterOneStep(b.per_time, dt_max);
  const double short_step = speedAfterOneStep(b.per_time, dt_max / 32.0);
  ASSERT_GT(full, 1e-4);  // the squeeze is felt
  const double ratio = short_step / full;
  EXPECT_GE(ratio, b.low) << "full step " << full << " m/s, short step " << short_step << " m/s";
  EXPECT_LE(ratio, b.high) << "full step " << full << " m/s, short step " << short_step << " m/s";
}

}  // namespace
