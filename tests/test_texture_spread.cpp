// Turbulent spread of a texture cloud in a uniform k field with U = 0 and no gravity, eqs. (23)-(24)
// (texture/turbulent_fluctuation.hpp), against the variance the model predicts, sigma_u^2 = 2k/3:
//  * redrawn (the paper): u_f is a fresh sigma_u xi each step, held over the step, and the particle relaxes to it
//    with a = e^{-dt/tau}, b = tau (1 - a). Released at rest at the origin, after N steps each coordinate is
//    X_N = sigma_u sum_m c_m xi_m with c_m = dt - b a^{N-1-m}, so Var X = sigma_u^2 sum_{j<N} (dt - b a^j)^2
//    (-> sigma_u^2 dt t for t >> tau: the spread depends on dt);
//  * langevin: for a tracer the fluid velocity held over a step is a stationary AR(1) sequence with correlation
//    rho = e^{-dt/T_L}: Var X = sigma_u^2 dt^2 [N + 2 sum_{l=1}^{N-1} (N - l) rho^l]
//    (-> 2 sigma_u^2 T_L t for t >> T_L, whatever dt).
// 20000 particles from a fixed seed: the sample variance, pooled over the three axes, has a relative standard
// error of 0.6 %; the tolerance is 3 %.
#include <gtest/gtest.h>

#include <cmath>

#include "texture/texture_cloud.hpp"

using namespace mistfall;

namespace {

constexpr double kK = 1.5e-4;  // sigma_u = 0.01 m/s
constexpr int kParticles = 20000;

// Pooled per-axis variance of the positions of a cloud of `kind` released at the origin after `steps` of dt.
double cloudVariance(TextureKind kind, FluctuationParameters fluct, double dt, int steps) {
  TextureParameters p;
  p.gravity = Vec3::Zero();
  p.fluctuation = fluct;
  p.seed = 20261123;
  TextureCloud cloud(p);
  for (int i = 0; i < kParticles; ++i) cloud.addParticle(kind, Vec3::Zero(), Vec3::Zero(), 7.5e-5, 0.0);
  FlowSample gas, liquid;
  gas.k = liquid.k = kK;
  liquid.liquid_fraction = 1.0;
  const UniformFlow flow(gas, liquid);
  for (int s = 0; s < steps; ++s) cloud.step(flow, s * dt, dt);
  double sum = 0.0;
  for (const auto& x : cloud.position) sum += x.squaredNorm();
  return sum / (3.0 * cloud.size());
}

FluctuationParameters langevin(double t_l) {
  FluctuationParameters f;
  f.model = FluctuationModel::Langevin;
  f.ds = t_l * f.ce * std::sqrt(kK) / f.time_scale_constant;  // gives T_L = t_l at k = kK
  return f;
}

}  // namespace

TEST(TextureSpread, RedrawnFluctuationMatchesTheDiscreteModel) {
  const double dt = 1e-3;
  const int steps = 200;
  const double sigma2 = 2.0 * kK / 3.0;
  // A mist droplet in air; its relaxation time at the typical slip sqrt(3) sigma_u (Re ~ 0.09).
  DragParticle mist;
  mist.diameter = 7.5e-5;
  mist.density_ratio = 1000.0 / 1.2;
  mist.viscosity = 1.5e-5;
  const double tau = relaxationTime(mist, std::sqrt(3.0 * sigma2));
  const double a = std::exp(-dt / tau), b = tau * (1.0 - a);
  double predicted = 0.0;
  for (int j = 0; j < steps; ++j) predicted += std::pow(dt - b * std::pow(a, j), 2);
  predicted *= sigma2;
  const double measured = cloudVariance(TextureKind::Mist, FluctuationParameters{}, dt, steps);
  EXPECT_NEAR(measured, predicted, 0.03 * predicted) << "tracer limit sigma^2 dt t = " << sigma2 * dt * steps * dt;
  // Inertia matters here (tau = 17 ms against t = 0.2 s): the tracer value is 15 % higher and must be excluded.
  EXPECT_LT(measured, 0.93 * sigma2 * dt * dt * steps);
}

TEST(TextureSpread, RedrawnSpreadGrowsWithTheTimeStep) {
  const double t = 0.2;
  const double fine = cloudVariance(TextureKind::MicroBubble, FluctuationParameters{}, 1e-3, 200);
  const double coarse = cloudVariance(TextureKind::MicroBubble, FluctuationParameters{}, 4e-3, 50);
  const double sigma2 = 2.0 * kK / 3.0;
  // Micro-bubbles are near-tracers (tau = 0.16 ms): Var = sigma_u^2 dt t.
  EXPECT_NEAR(fine, sigma2 * 1e-3 * t, 0.03 * sigma2 * 1e-3 * t);
  EXPECT_NEAR(coarse / fine, 4.0, 0.2);
}

TEST(TextureSpread, LangevinMatchesTheOrnsteinUhlenbeckModelAtAnyStep) {
  const double t_l = 0.01, t = 0.3, sigma2 = 2.0 * kK / 3.0;
  for (double dt : {1e-3, 4e-3}) {
    const int steps = static_cast<int>(std::lround(t / dt));
    const double rho = std::exp(-dt / t_l);
    double sum = steps;
    for (int l = 1; l < steps; ++l) sum += 2.0 * (steps - l) * std::pow(rho, l);
    const double predicted = sigma2 * dt * dt * sum;
    const double measured = cloudVariance(TextureKind::MicroBubble, langevin(t_l), dt, steps);
    EXPECT_NEAR(measured, predicted, 0.03 * predicted) << "dt = " << dt;
    // ... and the continuous-time law 2 sigma^2 T_L [t - T_L (1 - e^{-t/T_L})] within the discretisation error.
    const double continuous = 2.0 * sigma2 * t_l * (t - t_l * (1.0 - std::exp(-t / t_l)));
    EXPECT_NEAR(measured, continuous, 0.05 * continuous) << "dt = " << dt;
  }
}
