// Dam break against Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312-324, Fig. 3:
// surge-front position Z = z/a against T = t sqrt(2 g / a) for a column of width a and height 2a (n^2 = 2).
// 2D simulations are known to lead this experiment (its gate took time to lift; the flow was not exactly 2D).
// The front is the surge's leading edge, spray ahead of it left out (a lone droplet had moved the T = 2.0 point by
// 8 % with the summation order alone). Ours leads by 10-16 % in Z (paper scheme, l0 = 4 mm; 16-20 % at T = 1.2-2.0
// with l0 = 2 mm: docs/validation.md). So we assert
//  - Z within 20 % of the data at each time,
//  - the front speed dZ/dT over the constant-speed regime T >= 1.2 (free of the start-up delay and of the
//    initial acceleration) within 15 % (measured: +6.1 % in 2D),
//  - the front speed below Ritter's dry-bed shallow-water bound 2 sqrt(g h0), i.e. dZ/dT < 2 for h0 = 2a.
// The 3D case is the same column filling the whole depth of a narrow tank (quasi-2D), so it must follow the
// same curve (measured: within 3 % of the 2D run).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/run_case.hpp"

using namespace mistfall;

namespace {
// Martin & Moyce (1952) Fig. 3, n^2 = 2, a = 2.25 in (read off the published figure).
struct Point { double T, Z; };
constexpr Point kMartinMoyce[] = {{0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}, {3.345, 4.134}};

// a: column width (the inner left wall is at x = 0); points: how many data points fit before the far wall.
// `stabilised`: run the case with numerics.scheme = "stabilised" (docs/validation.md) instead of as shipped.
template <int D>
void checkSurgeFront(const char* case_name, double a, std::size_t points, std::size_t fluid_particles,
                     bool stabilised = false, double collision = 0.5) {
  CaseConfig config = test_support::loadShippedCase(case_name);
  if (stabilised) {
    config.numerics.scheme = Scheme::Stabilised;
    config.numerics.pressure_source = PressureSource::Mixed;
    config.numerics.source_relaxation = 0.0;
    config.numerics.collision_distance = collision;
  }
  const double g = 9.81;
  std::vector<double> times;
  for (std::size_t k = 0; k < points; ++k) times.push_back(kMartinMoyce[k].T / std::sqrt(2.0 * g / a));
  std::size_t k = 0;
  std::vector<double> simulated;
  test_support::runThrough<D>(config, times, [&](double t, const SimulationState<D>& s, const MpsSolver<D>&) {
    // The surge's leading edge: the most downstream water particle with at least two others within re = 2.1 l0
    // (spray thrown ahead of the surge does not count: a lone droplet 2.6 l0 ahead moved Z at T = 2.0 from +12 %
    // to +20 % with the summation order of the sums alone).
    const auto& p = s.particles;
    const double l0 = config.numerics.particle_spacing, re = 2.1 * l0;
    std::vector<std::size_t> water;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid) water.push_back(i);
    double front = 0.0;
    for (std::size_t i : water) {
      if (p.position[i][0] + 0.5 * l0 <= front) continue;
      int close = 0;
      for (std::size_t j : water) close += j != i && (p.position[j] - p.position[i]).squaredNorm() < re * re;
      if (close >= 2) front = p.position[i][0] + 0.5 * l0;
    }
    const std::size_t fluid = water.size();
    const double Z = front / a;
    std::printf("%s%dD T = %.3f (t = %.4f s): Z simulated %.3f, Martin & Moyce %.3f (%+.1f%%)\n", stabilised ? "stabilised " : "", D,
                kMartinMoyce[k].T, t, Z, kMartinMoyce[k].Z, 100.0 * (Z - kMartinMoyce[k].Z) / kMartinMoyce[k].Z);
    EXPECT_NEAR(Z, kMartinMoyce[k].Z, 0.20 * kMartinMoyce[k].Z) << "at T = " << kMartinMoyce[k].T;
    EXPECT_EQ(fluid, fluid_particles);
    simulated.push_back(Z);
    ++k;
  });
  ASSERT_EQ(k, points);
  const auto& first = kMartinMoyce[1];
  const auto& last = kMartinMoyce[points - 1];
  const double speed_data = (last.Z - first.Z) / (last.T - first.T);
  const double speed_sim = (simulated.back() - simulated[1]) / (last.T - first.T);
  std::printf("%s%dD front speed dZ/dT: simulated %.3f, Martin & Moyce %.3f (%+.1f%%), Ritter bound 2\n",
              stabilised ? "stabilised " : "", D, speed_sim,
              speed_data, 100.0 * (speed_sim - speed_data) / speed_data);
  EXPECT_NEAR(speed_sim, speed_data, 0.15 * speed_data);
  EXPECT_LT(speed_sim, 2.0);
}
}  // namespace

TEST(PhysicsDamBreak, SurgeFrontFollowsMartinMoyce2D) { checkSurgeFront<2>("dam_break.toml", 0.1, 5, 1250); }

// The 3D tank is 4a long, so the front reaches the far wall near T = 3: compare up to T = 2.547.
TEST(PhysicsDamBreak, SurgeFrontFollowsMartinMoyce3D) { checkSurgeFront<3>("dam_break_3d.toml", 0.06, 4, 2000); }

// The stabilised scheme (pressure repulsion and particle shifting on, docs/validation.md): in 2D with the paper
// scheme's 0.5 l0 collision (48 reversals in 0.4 s; before the shifting it needed 0.8 l0 and thousands a frame):
// +6 to +15 % in Z, +1.7 % in front speed. In 3D the 0.8 l0 collision stays: with 0.5 two particles leave the tank by
// t = 0.14 s.
TEST(PhysicsDamBreak, StabilisedSurgeFrontFollowsMartinMoyce2D) {
  checkSurgeFront<2>("dam_break.toml", 0.1, 5, 1250, true);
}
TEST(PhysicsDamBreak, StabilisedSurgeFrontFollowsMartinMoyce3D) {
  checkSurgeFront<3>("dam_break_3d.toml", 0.06, 4, 2000, true, 0.8);
}
