// Texture particle motion, eqs. (18)-(19): a 0.075 mm mist droplet released at rest in still air and a 0.075 mm
// micro-bubble in still water reach the terminal velocity that eq. (18) gives at du_p/dt = 0,
//   1/2 A2 d^2 C_D(v) v^2 = |rho_p/rho_f - 1| A3 d^3 g,   C_D = 24/Re (1 + 0.15 Re^0.687),  Re = v d / nu,
// solved here by bisection, independently of the model code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "texture/texture_cloud.hpp"

using namespace mistfall;

namespace {

constexpr double kG = 9.81, kD = 7.5e-5;

// Terminal speed from the force balance of the header (bisection on [0, 10] m/s).
double analyticTerminalSpeed(double rho_p, double rho_f, double nu) {
  const double a2 = std::numbers::pi / 4, a3 = std::numbers::pi / 6;
  auto imbalance = [&](double v) {
    const double re = v * kD / nu;
    const double cd = 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687));
    return 0.5 * rho_f * a2 * kD * kD * cd * v * v - std::abs(rho_p - rho_f) * a3 * kD * kD * kD * kG;
  };
  double lo = 1e-12, hi = 10.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (imbalance(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

UniformFlow stillFluids() {
  FlowSample gas, liquid;
  gas.liquid_fraction = 0.0;
  liquid.liquid_fraction = 1.0;
  return UniformFlow(gas, liquid);
}

// Vertical velocity of one particle of `kind` released at rest after `steps` steps of dt.
double releasedVelocity(TextureKind kind, double dt, int steps) {
  TextureParameters params;
  params.source_diameter = 0.005;
  TextureCloud cloud(params);
  cloud.addParticle(kind, Vec3::Zero(), Vec3::Zero(), kD, 0.0);
  const UniformFlow flow = stillFluids();
  for (int s = 0; s < steps; ++s) cloud.step(flow, s * dt, dt);
  EXPECT_EQ(cloud.size(), 1u);
  EXPECT_NEAR(cloud.velocity[0][0], 0.0, 1e-15);
  return cloud.velocity[0][1];
}

}  // namespace

TEST(TextureMotion, MistReachesTerminalVelocityInStillAir) {
  const double expected = analyticTerminalSpeed(1000.0, 1.2, 1.5e-5);  // about 0.16 m/s downwards
  const double v = releasedVelocity(TextureKind::Mist, 1e-3, 400);     // 0.4 s, over 20 relaxation times
  EXPECT_LT(v, 0.0);
  EXPECT_NEAR(-v, expected, 0.01 * expected) << "analytic " << expected;  // the 1 % asked for
  // The exponential step's fixed point is the terminal velocity itself, so hold it far tighter: a 1 % tolerance
  // would let a drag correction of 0.16 instead of 0.15 Re^0.687 pass (0.7 % here).
  EXPECT_NEAR(-v, expected, 1e-6 * expected);
  // The result does not hinge on the step: a 10x coarser step lands on the same velocity.
  EXPECT_NEAR(releasedVelocity(TextureKind::Mist, 1e-2, 40), v, 1e-3 * expected);
}

TEST(TextureMotion, MicroBubbleReachesTerminalVelocityInStillWater) {
  const double expected = analyticTerminalSpeed(1.2, 1000.0, 1.0e-6);  // about 3 mm/s upwards
  // dt = 1e-3 s is six relaxation times of the bubble (tau ~ 1.6e-4 s): the exponential step stays stable.
  const double v = releasedVelocity(TextureKind::MicroBubble, 1e-3, 20);
  EXPECT_GT(v, 0.0);
  EXPECT_NEAR(v, expected, 0.01 * expected) << "analytic " << expected;
  EXPECT_NEAR(v, expected, 1e-6 * expected);
}

TEST(TextureMotion, ExponentialStepIsExactForStokesDrag) {
  // At Re -> 0 (f = 1) with no forcing, u(t) = u0 e^{-t/tau}; one big step equals many small ones.
  DragParticle p;
  p.diameter = 1e-6;
  p.density_ratio = 800.0;
  p.viscosity = 1.5e-5;
  const double tau = (p.density_ratio + p.added_mass) * p.diameter * p.diameter / (18.0 * p.viscosity);
  const Vec3 u0(1e-9, 0.0, 0.0);  // Re ~ 1e-10: f(Re) = 1 to 1e-8
  const MotionResult one = advanceParticle(p, u0, Vec3::Zero(), Vec3::Zero(), 3 * tau);
  EXPECT_NEAR(one.velocity[0], 1e-9 * std::exp(-3.0), 1e-9 * 1e-7);
  EXPECT_NEAR(one.displacement[0], 1e-9 * tau * (1 - std::exp(-3.0)), 1e-9 * tau * 1e-7);
}

TEST(TextureMotion, AddedMassSetsTheBubblesStartingAcceleration) {
  // Released at rest, before drag acts (h << tau): du_p/dt = (rho_p/rho_f - 1) g / (rho_p/rho_f + C_M), eq. (18).
  // With C_M = 0.5 a micro-bubble in water starts upwards at about 2 g (without added mass it would be 832 g).
  TextureParameters params;
  TextureCloud cloud(params);
  cloud.addParticle(TextureKind::MicroBubble, Vec3::Zero(), Vec3::Zero(), kD, 0.0);
  const UniformFlow flow = stillFluids();
  const double h = 1e-8;  // tau ~ 1.5e-4 s
  cloud.step(flow, 0.0, h);
  const double ratio = 1.2 / 1000.0;
  const double expected = (1.0 - ratio) * kG / (ratio + 0.5);
  EXPECT_NEAR(cloud.velocity[0][1] / h, expected, 1e-3 * expected);
  EXPECT_NEAR(cloud.position[0][1], 0.5 * expected * h * h, 1e-3 * 0.5 * expected * h * h);
}
