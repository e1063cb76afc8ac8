// numerics.bubble_cavity = "joined" (experimental; src/mps/bubble_cavity.hpp, docs/validation.md "A bubble's void"):
// the empty cavity a stiff bubble's gas leaves in the water is part of the bubble. The coarse bubble tank (l0 = 5 mm,
// 62 gas particles, the stiff rows of test_bubble_area.cpp) at dt_max = 2.5e-4 s over 0.1 s, its void V (the gas's
// cells plus the cavity joined to them, support/bubble_void.hpp) against eq. (17)'s equilibrium A_eq for its P_B.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/bubble_void.hpp"
#include "support/case_text.hpp"
#include "support/coarse_bubble_case.hpp"
#include "support/run_case.hpp"

using namespace mistfall;

namespace {

struct VoidRecord {
  double worst = 0.0;     // the largest |V / A_eq - 1| over the run
  double rise = 0.0;      // the gas's centroid's rise [m]
  bool one_bubble = true; // one bubble at every step
};

VoidRecord runCoarseBubble(const std::string& extra, double until) {
  const std::string keys = "scheme = \"stabilised\"\ncollision_distance = 0.8\ngas_pressure_memory = true\n" + extra;
  std::string text = test_support::coarseBubbleCase(keys, std::to_string(until));
  text.replace(text.find("dt_max = 5e-4"), 13, "dt_max = 2.5e-4");
  test_support::SolverRun<2> run(text, "bubble_cavity.toml");
  const auto& p = run.state.particles;
  const double l0 = run.config.numerics.particle_spacing;
  const double stiffness = run.config.physics.gas.density * std::pow(run.config.physics.gas.sound_speed, 2);
  VoidRecord out;
  double p0 = 0.0, start = 0.0;
  while (run.state.time < until - 1e-12) {
    run.solver->step(until);
    const auto bubbles = run.solver->currentBubbles();
    if (bubbles.size() != 1) {
      out.one_bubble = false;
      break;
    }
    std::vector<char> in_bubble(p.size(), 0);
    double count = 0.0, height = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && p.enclosed[i])
        in_bubble[i] = 1, count += 1.0, height += p.position[i][1];
    if (run.state.step == 1) p0 = bubbles[0].mean_pressure, start = height / count;
    const double equilibrium = count * l0 * l0 * (1.0 - (bubbles[0].mean_pressure - p0) / stiffness);
    out.worst = std::max(out.worst, std::abs(test_support::bubbleVoid(p, in_bubble, l0).area() / equilibrium - 1.0));
    out.rise = height / count - start;
  }
  return out;
}

}  // namespace

// Measured (thirty-eighth session): with the key the void stays within 3.0 % of its equilibrium over the 0.1 s and
// the gas's centroid rises 2.5 cm; without it an empty cavity opens over the gas (the void 76 % over its equilibrium
// at worst) and the gas rises 1.1 cm, to sink back after (over 0.05-0.15 s: -0.003 m/s, docs/validation.md).
TEST(BubbleCavity, AJoinedCavityKeepsTheStiffBubblesVoidAndLetsItRise) {
  const VoidRecord joined = runCoarseBubble("bubble_cavity = \"joined\"\n", 0.1);
  ASSERT_TRUE(joined.one_bubble);
  EXPECT_LT(joined.worst, 0.04);
  EXPECT_GT(joined.rise, 0.02);
  const VoidRecord plain = runCoarseBubble("", 0.1);
  ASSERT_TRUE(plain.one_bubble);
  EXPECT_GT(plain.worst, 0.5);
  EXPECT_LT(plain.rise, 0.015);
}

TEST(BubbleCavity, CaseKeyDefaultsAndErrors) {
  using test_support::errorOf;
  using test_support::Parts;
  EXPECT_FALSE(parseCase(Parts{}.text(), "t.toml").numerics.bubble_cavity_joined);
  Parts joined;
  joined.numerics += "bubble_cavity = \"joined\"\n";
  EXPECT_TRUE(parseCase(joined.text(), "t.toml").numerics.bubble_cavity_joined);
  Parts bad;
  bad.numerics += "bubble_cavity = \"open\"\n";
  EXPECT_NE(errorOf(bad.text()).find("numerics.bubble_cavity = \"open\""), std::string::npos);
  Parts three = joined;
  three.header = "name = \"t\"\ndimension = 3\n";
  three.domain = "min = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n";
  three.regions = "[[region]]\nname = \"w\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.5, 0.5, 0.5]\n";
  EXPECT_NE(errorOf(three.text()).find("is built for 2D cases"), std::string::npos);
  Parts one = joined;
  one.numerics += "scheme = \"stabilised\"\npressure_source = \"mixed\"\ncoupling = \"one_equation\"\n";
  EXPECT_NE(errorOf(one.text()).find("needs numerics.coupling = \"two_systems\""), std::string::npos);
}
