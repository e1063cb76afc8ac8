// numerics.gas_pressure_memory on which rows (pressure_poisson.hpp, docs/case-file.md): `true` puts eq. (17)'s
// memory term on every compressible gas row, "bubbles" on the bubbles' merged rows only. The coarse bubble tank with
// its air in a closed box (no gas free surface, so the boxed air's rows are compressible rows that settle at
// rho_g c^2 delta with the memory term and at gamma times that without): over the first 5 ms, with "bubbles" the
// boxed air's pressure is the one without the memory term and the bubble's the one with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/coarse_bubble_case.hpp"
#include "support/run_case.hpp"

using namespace mistfall;

namespace {

struct Pressures {
  double open_air = 0.0;  // the mean |p| of the open gas over the steps [Pa]
  double bubble = 0.0;    // the bubble's mean pressure at the end [Pa]
};

Pressures runFor5ms(const std::string& memory) {
  const std::string extra = "gas_domain = \"closed\"\n" + (memory.empty() ? "" : "gas_pressure_memory = " + memory + "\n");
  test_support::SolverRun<2> run(test_support::coarseBubbleCase(extra, "0.005"), "memory.toml");
  const auto& p = run.state.particles;
  Pressures out;
  int steps = 0;
  while (run.state.time < 0.005 - 1e-12) {
    run.solver->step(0.005);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && !p.enclosed[i])
        sum += std::abs(p.pressure[i]), ++count;
    out.open_air += sum / static_cast<double>(count);
    ++steps;
  }
  out.open_air /= steps;
  const auto bubbles = run.solver->currentBubbles();
  EXPECT_EQ(1u, bubbles.size()) << memory;
  if (!bubbles.empty()) out.bubble = bubbles[0].mean_pressure;
  return out;
}

TEST(GasPressureMemory, BubblesOnlyKeepsTheBoxedAirSoftAndTheBubbleStiff) {
  const Pressures none = runFor5ms(""), all = runFor5ms("true"), bubbles = runFor5ms("\"bubbles\"");
  // The memory term stiffens the boxed air (its pressure departs further from 0: measured 318 against 138 Pa) and
  // the bubble, which starts at 0 Pa, reaches and passes its hydrostatic pressure (564 Pa at its centre) within the
  // 5 ms (807 Pa) where the soft rows need their 25 ms (250 Pa).
  EXPECT_GT(all.open_air, 2.0 * none.open_air) << all.open_air << " against " << none.open_air;
  EXPECT_GT(all.bubble, 2.0 * none.bubble) << all.bubble << " against " << none.bubble;
  // "bubbles": the air as without the term (132 Pa), the bubble as with it (807 Pa).
  EXPECT_NEAR(bubbles.open_air, none.open_air, 0.1 * none.open_air);
  EXPECT_NEAR(bubbles.bubble, all.bubble, 0.01 * all.bubble);
}

}  // namespace
