// Dam break against Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312-324, Fig. 3:
// surge-front position Z = z/a against T = t sqrt(2 g / a) for a column of width a and height 2a (n^2 = 2).
// 2D simulations are known to lead this experiment (its gate took time to lift; the flow was not exactly 2D):
// ours leads by 10-16 % in Z; l0 = 4 mm and 2 mm agree within 2 %. So we assert
//  - Z within 20 % of the data at each time,
//  - the front speed dZ/dT over the constant-speed regime T >= 1.2 (points 2-5: free of the start-up delay and
//    of the initial acceleration) within 15 % (measured: +5.8 %),
//  - the front speed below Ritter's dry-bed shallow-water bound 2 sqrt(g h0), i.e. dZ/dT < 2 for h0 = 2a.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/run_case.hpp"

using namespace mistfall;

namespace {
// Martin & Moyce (1952) Fig. 3, n^2 = 2, a = 2.25 in (read off the published figure).
struct Point { double T, Z; };
constexpr Point kMartinMoyce[] = {{0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}, {3.345, 4.134}};
}  // namespace

TEST(PhysicsDamBreak, SurgeFrontFollowsMartinMoyce) {
  const CaseConfig config = test_support::loadShippedCase("dam_break.toml");
  const double a = 0.1;  // column width in cases/dam_break.toml; the inner left wall is at x = 0
  const double g = 9.81;
  std::vector<double> times;
  for (const auto& p : kMartinMoyce) times.push_back(p.T / std::sqrt(2.0 * g / a));
  std::size_t k = 0;
  std::vector<double> simulated;
  test_support::runThrough<2>(config, times, [&](double t, const SimulationState<2>& s, const MpsSolver<2>&) {
    double front = 0.0;
    std::size_t fluid = 0;
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (s.particles.kind[i] == ParticleKind::Fluid) {
        front = std::max(front, s.particles.position[i][0] + 0.5 * config.numerics.particle_spacing);
        ++fluid;
      }
    const double Z = front / a;
    std::printf("T = %.3f (t = %.4f s): Z simulated %.3f, Martin & Moyce %.3f (%+.1f%%)\n", kMartinMoyce[k].T, t, Z,
                kMartinMoyce[k].Z, 100.0 * (Z - kMartinMoyce[k].Z) / kMartinMoyce[k].Z);
    EXPECT_NEAR(Z, kMartinMoyce[k].Z, 0.20 * kMartinMoyce[k].Z) << "at T = " << kMartinMoyce[k].T;
    simulated.push_back(Z);
    EXPECT_EQ(fluid, 1250u);
    ++k;
  });
  ASSERT_EQ(k, std::size(kMartinMoyce));
  const auto& first = kMartinMoyce[1];
  const auto& last = kMartinMoyce[std::size(kMartinMoyce) - 1];
  const double speed_data = (last.Z - first.Z) / (last.T - first.T);
  const double speed_sim = (simulated.back() - simulated[1]) / (last.T - first.T);
  std::printf("front speed dZ/dT: simulated %.3f, Martin & Moyce %.3f (%+.1f%%), Ritter bound 2\n", speed_sim,
              speed_data, 100.0 * (speed_sim - speed_data) / speed_data);
  EXPECT_NEAR(speed_sim, speed_data, 0.15 * speed_data);
  EXPECT_LT(speed_sim, 2.0);
}
