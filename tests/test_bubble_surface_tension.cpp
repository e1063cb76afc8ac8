// numerics.bubble_surface_tension = "jump" (solver_liquid.cpp, applyLaplaceJump): a bubble at rest in weightless water
// holds the Young-Laplace pressure P_B - p_l = sigma / R (2D), p_l = 0 at the water's free surface. A lattice disc of
// gas of radius R = 9 l0 (the coarse bubble tank at l0 = 2.5 mm: the disc 5.75 cm under the surface of water 0.2 m
// wide, air above), no gravity, compressible gas (c = 340 m/s; its compression at sigma / R is 2e-4, negligible);
// without the jump the bubble holds no pressure. Each run 0.1 s.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/coarse_bubble_case.hpp"
#include "support/run_case.hpp"

using namespace mistfall;

namespace {

// The coarse bubble tank (support/coarse_bubble_case.hpp) at 2.5 mm, without gravity.
std::string weightlessBubble(const std::string& jump, double sigma) {
  return test_support::coarseBubbleCase("bubble_surface_tension = \"" + jump + "\"\n[physics]\ngravity = [0.0, 0.0]\n"
                                        "surface_tension = " + std::to_string(sigma) + "\n",
                                        "1.0", "0.0025");
}

// 200 steps of dt_max = 5e-4 s: P_B rises from 0 without overshoot (the mixed source damps the breathing) and is
// within 1 % of its plateau by 0.08 s.
constexpr int kSteps = 200;

// The bubble's pressure after `steps` steps from rest [Pa], and the unfitted interface particles over them.
struct LaplaceRecord {
  double pressure = 0.0;
  std::size_t unfitted = 0;
  double largest_water_speed = 0.0;  // [m/s], at the end
};

LaplaceRecord bubblePressure(const std::string& jump, double sigma, int steps) {
  test_support::SolverRun<2> run(weightlessBubble(jump, sigma), "laplace_bubble.toml");
  LaplaceRecord out;
  for (int k = 0; k < steps; ++k) out.unfitted += run.solver->step(1.0).curvature_unfitted;
  const auto& p = run.state.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Liquid)
      out.largest_water_speed = std::max(out.largest_water_speed, p.velocity[i].norm());
  const auto bubbles = run.solver->currentBubbles();
  EXPECT_EQ(1u, bubbles.size());
  if (!bubbles.empty()) out.pressure = bubbles[0].mean_pressure;
  return out;
}

}  // namespace

TEST(BubbleSurfaceTension, WeightlessBubbleHoldsTheLaplacePressure) {
  const double radius = 0.0225;
  for (const double sigma : {0.0728, 0.5}) {
    const auto r = bubblePressure("jump", sigma, kSteps);
    EXPECT_EQ(0u, r.unfitted);
    // measured: 1.056 and 1.004 (the curvature fit reads this disc's kappa R as 0.962 at its start)
      EXPECT_NEAR(1.0, r.pressure / (sigma / radius), 0.08) << "sigma = " << sigma << ": P_B = " << r.pressure;
    // the spurious currents the staircase's curvature noise drives: capillary number mu U / sigma (measured 3.9e-5
    // and 1.2e-5; the bubble without the jump leaves the water at 7e-5 m/s)
    EXPECT_LT(1e-3 * r.largest_water_speed / sigma, 1e-4) << "sigma = " << sigma;
    }
}

TEST(BubbleSurfaceTension, WithoutTheJumpTheBubbleHoldsNoPressure) {
  const double sigma = 0.5, radius = 0.0225;
  const auto r = bubblePressure("none", sigma, kSteps);
  EXPECT_LT(std::abs(r.pressure), 0.05 * sigma / radius) << "P_B = " << r.pressure;
}
