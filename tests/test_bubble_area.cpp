// Issue 16, item 1: a bubble's area within 1 % of its compressed equilibrium. The coarse bubble tank (l0 = 5 mm, a gas
// disc of radius 2.25 cm, 62 gas particles, its centre 5.75 cm under the surface) on the stabilised scheme, at rest
// under gravity. The bubble's area is measured from its gas's number density at the step's end positions,
//   A = sum_{i in B} l0^2 n0 / n_i,
// and its compressed equilibrium is what eq. (17) gives the gas for the bubble's pressure P_B:
//   A_eq = N l0^2 (1 - (P_B - P_0) / (rho_g c_g^2)),
// P_0 the pressure at which the gas is at its lattice spacing: the first step's P_B, as every case here starts with
// numerics.bubble_initial_pressure = "water" (the default: the bubble takes the water's pressure with its lattice
// spacing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mps/weight.hpp"
#include "support/bubble_void.hpp"
#include "support/coarse_bubble_case.hpp"
#include "support/run_case.hpp"

using namespace mistfall;

namespace {

struct AreaCase {
  const char* name;
  const char* numerics;  // lines added to the coarse case's [numerics]
};

struct AreaRecord {
  double worst = 0.0;      // the largest |A / A_eq - 1| over the run
  double worst_void = 0.0; // the largest |V / A_eq - 1|, V the bubble's void (support/bubble_void.hpp)
  bool open = false;       // the void's cavity ever reached 8 l0 past the gas
  double area_loss = 0.0;  // 1 - A / (N l0^2) at the end
  double pressure = 0.0;   // P_B at the end [Pa]
};

AreaRecord measure(const AreaCase& c, double until) {
  test_support::SolverRun<2> run(test_support::coarseBubbleCase(c.numerics, std::to_string(until)), "bubble_area.toml");
  const auto& p = run.state.particles;
  const double l0 = run.config.numerics.particle_spacing, re = run.solver->constants().re_number_density;
  const double n0 = run.solver->constants().n0;
  const double stiffness = run.config.physics.gas.density * std::pow(run.config.physics.gas.sound_speed, 2);
  AreaRecord out;
  double p0 = 0.0;
  while (run.state.time < until - 1e-12) {
    run.solver->step(until);
    const auto bubbles = run.solver->currentBubbles();
    EXPECT_EQ(1u, bubbles.size()) << c.name << " at t = " << run.state.time;
    if (bubbles.size() != 1) break;
    if (run.state.step == 1) p0 = bubbles[0].mean_pressure;
    double area = 0.0;
    std::size_t count = 0;
    std::vector<char> in_bubble(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!(p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && p.enclosed[i])) continue;
      in_bubble[i] = 1;
      double n = 0.0;
      for (std::size_t j = 0; j < p.size(); ++j)
        if (j != i && isActive(p.kind[j])) n += weight((p.position[j] - p.position[i]).norm(), re);
      area += l0 * l0 * n0 / n;
      ++count;
    }
    const double equilibrium = count * l0 * l0 * (1.0 - (bubbles[0].mean_pressure - p0) / stiffness);
    out.worst = std::max(out.worst, std::abs(area / equilibrium - 1.0));
    const test_support::BubbleVoid space = test_support::bubbleVoid(p, in_bubble, l0);
    out.worst_void = std::max(out.worst_void, std::abs(space.area() / equilibrium - 1.0));
    out.open = out.open || space.open;
    out.area_loss = 1.0 - area / (count * l0 * l0);
    out.pressure = bubbles[0].mean_pressure;
  }
  return out;
}

}  // namespace

// Measured over the first 30 ms (0.03 s; P_B 484-793 Pa against 564 Pa hydrostatic at the centre):
//  * the stiff rows (gas_pressure_memory = true): worst 0.62 %, the area 0.79 % below the lattice's at 30 ms (started
//    at 0 Pa instead, bubble_initial_pressure = "zero", against P_0 = 0, the bubble breathes and reads 2.1 %); its
//    void (support/bubble_void.hpp) departs by at most 0.60 %;
//  * the soft rows (the mixed source without the memory term, which settle at gamma rho_g c^2 delta, gamma = 0.01):
//    the area 25 % below the lattice's at 30 ms, 24.9 % from its stiff equilibrium: the "100x too soft"; its
//    void departs by 17.6 %.
// Past 30 ms the stiff bubble's gas, which follows the water, no longer fills its void: an empty cavity opens over
// it from about 40 ms, and the void is 36 % over its equilibrium at 60 ms and 104 % at 0.1 s while the measure
// A reads 1.2 % and 2.3 % (thirty-eighth session, docs/validation.md).
struct AreaBound {
  AreaCase setup;
  double low, high;            // the bounds on the worst |A / A_eq - 1| over 30 ms
  double void_low, void_high;  // and on the worst |V / A_eq - 1| of its void
};

class BubbleArea : public ::testing::TestWithParam<AreaBound> {};

TEST_P(BubbleArea, TheBubblesAreaAgainstItsCompressedEquilibrium) {
  const AreaBound& c = GetParam();
  const AreaRecord r = measure(c.setup, 0.03);
  EXPECT_GE(r.worst, c.low) << c.setup.name << ": area loss " << r.area_loss << ", P_B " << r.pressure << " Pa";
  EXPECT_LT(r.worst, c.high) << c.setup.name << ": area loss " << r.area_loss << ", P_B " << r.pressure << " Pa";
  EXPECT_GE(r.worst_void, c.void_low) << c.setup.name;
  EXPECT_LT(r.worst_void, c.void_high) << c.setup.name;
  EXPECT_FALSE(r.open) << c.setup.name << ": the void opened to the space around the bubble";
}

INSTANTIATE_TEST_SUITE_P(
    Rows, BubbleArea,
    ::testing::Values(
        AreaBound{{"stiff", "scheme = \"stabilised\"\ncollision_distance = 0.8\ngas_pressure_memory = true\n"},
                  0.0, 0.01, 0.0, 0.01},
        AreaBound{{"soft", "scheme = \"stabilised\"\ncollision_distance = 0.8\n"}, 0.15, 0.40, 0.12, 0.30}),
    [](const ::testing::TestParamInfo<AreaBound>& info) { return std::string(info.param.setup.name); });

// The void helper on a hand-made lattice (l0 = 5 mm, the geometry of ctest tools.bubble_void): a gas disc in water
// reads N l0^2 exactly; with a cavity of 12 lattice sites emptied over it the void grows by 12 l0^2 less the band its
// water rim covers (samples within 0.75 l0 of a rim particle, 0.17 l0 deep on average along 10 spacings: 10.39 l0^2
// measured), and a hole of 4 sites a column of water away is not part of it.
TEST(BubbleVoid, ReadsTheGasCellsAndAnEmptyCavityJoinedToThem) {
  const double l0 = 0.005;
  auto inDisc = [](double x, double y) { return std::hypot(x - 0.1025, y - 0.0775) < 0.0225; };
  auto inCavity = [](double x, double y) { return x > 0.09 && x < 0.11 && y > 0.1 && y < 0.115; };
  auto inHole = [](double x, double y) { return x > 0.13 && x < 0.14 && y > 0.07 && y < 0.08; };
  auto lattice = [&](bool emptied, std::vector<char>& in_bubble) {
    Particles<2> p;
    in_bubble.clear();
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 30; ++j) {
        const double x = (i + 0.5) * l0, y = (j + 0.5) * l0;
        if (emptied && (inCavity(x, y) || inHole(x, y))) continue;
        p.add(Vec<2>(x, y), Vec<2>::Zero(), ParticleKind::Fluid, inDisc(x, y) ? Phase::Gas : Phase::Liquid);
        in_bubble.push_back(inDisc(x, y));
      }
    return p;
  };
  std::vector<char> in_bubble;
  const Particles<2> whole = lattice(false, in_bubble);
  const double n = static_cast<double>(std::count(in_bubble.begin(), in_bubble.end(), 1));
  const test_support::BubbleVoid disc = test_support::bubbleVoid(whole, in_bubble, l0);
  EXPECT_NEAR(n * l0 * l0, disc.cells, 1e-12);
  EXPECT_EQ(0.0, disc.cavity);
  const Particles<2> emptied = lattice(true, in_bubble);
  const test_support::BubbleVoid opened = test_support::bubbleVoid(emptied, in_bubble, l0);
  EXPECT_NEAR(12.0 - 0.17 * 10.0, (opened.area() - disc.area()) / (l0 * l0), 0.3);
  EXPECT_GT(opened.cavity, 0.0);
  EXPECT_FALSE(opened.open);
}
