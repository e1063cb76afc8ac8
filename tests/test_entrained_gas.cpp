// Buoyant rise of entrained gas below a bubble's resolution (mps/entrained_gas_rise.hpp): single gas particles
// enclosed in still water climb by exchange with the liquid above at numerics.entrained_gas_rise_speed on average,
// reach the surface and join the air; each phase keeps its particle count; with the speed 0 they stay where the
// water carries them. The exchange draw is uniform.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/bubble_gas_motion.hpp"
#include "mps/enclosed_gas.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/entrained_gas_rise.hpp"
#include "mps/solver.hpp"
#include "support/run_case.hpp"
#include "support/pocket_tank.hpp"
#include "support/tank_case.hpp"
#include "support/scratch.hpp"

using namespace mistfall;

namespace {

using test_support::kPockets;
constexpr double kStartHeight = 0.5 * (test_support::kPocketLowRow + test_support::kPocketHighRow);

std::string entrainedCase(double rise_speed) {
  return test_support::pocketTankCase("entrained_gas",
                                      "entrained_gas_rise_speed = " + std::to_string(rise_speed) + "\n");
}

struct EntrainedRun : test_support::SolverRun<2> {
  explicit EntrainedRun(double rise_speed) : SolverRun(entrainedCase(rise_speed), "entrained.toml") {}
  std::size_t count(Phase phase) const {
    const auto& p = state.particles;
    std::size_t c = 0;
    for (std::size_t i = 0; i < p.size(); ++i) c += p.kind[i] == ParticleKind::Fluid && p.phase[i] == phase;
    return c;
  }
  // Mean height of the gas below y = 0.05 m (the entrained pockets; the air starts at 0.06 m).
  std::pair<double, std::size_t> submergedGas() const {
    const auto& p = state.particles;
    double sum = 0.0;
    std::size_t c = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(p.kind[i], p.phase[i]) && p.position[i][1] < 0.05) sum += p.position[i][1], ++c;
    return {c ? sum / c : 0.0, c};
  }
  double gasHeightSum() const {
    const auto& p = state.particles;
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(p.kind[i], p.phase[i])) sum += p.position[i][1];
    return sum;
  }
  std::size_t swaps = 0, steps = 0;
  void runTo(double t) {
    while (state.time < t - 1e-12) swaps += solver->step(t).entrained_gas_swaps, ++steps;
  }
};

}  // namespace

TEST(EntrainedGas, RisesAtTheSetSpeedAndKeepsEachPhasesCount) {
  const double speed = 0.15, t = 0.1, l0 = 0.005;
  EntrainedRun run(speed);
  const std::size_t gas0 = run.count(Phase::Gas), liquid0 = run.count(Phase::Liquid);
  auto [height0, pockets] = run.submergedGas();
  ASSERT_EQ(pockets, static_cast<std::size_t>(kPockets));
  ASSERT_NEAR(height0, kStartHeight, 1e-12);
  const double sum0 = run.gasHeightSum();
  run.runTo(t);
  // Swaps drawn with probability U dt / l0 per step and pocket (dt = dt_max here): about 30 in all, binomial.
  const double expected_swaps = kPockets * static_cast<double>(run.steps) * speed * 5e-4 / l0;
  EXPECT_NEAR(static_cast<double>(run.swaps), expected_swaps, 3.0 * std::sqrt(expected_swaps));
  // The gas climbs the water by about l0 a swap: the mean rise speed of a pocket is U (the 240 particles of still
  // air above add a little noise to the sum of heights).
  const double climb = (run.gasHeightSum() - sum0) / kPockets;
  EXPECT_NEAR(climb / static_cast<double>(run.swaps) * kPockets, l0, 0.25 * l0) << "climb per swap";
  EXPECT_NEAR(climb / t, speed, 0.4 * speed) << "mean rise speed";
  std::printf("entrained gas: %zu swaps (expected %.1f), climb %.4f m per pocket, rise speed %.3f m/s\n", run.swaps, expected_swaps, climb, climb / t);
  EXPECT_EQ(run.count(Phase::Gas), gas0);
  EXPECT_EQ(run.count(Phase::Liquid), liquid0);
}

TEST(EntrainedGas, ReachesTheSurfaceAndJoinsTheAir) {
  EntrainedRun run(0.25);
  run.runTo(0.3);  // 7.5 cm of climb at 0.25 m/s for a way up of at most 4.75 cm
  auto [height, submerged] = run.submergedGas();
  EXPECT_EQ(submerged, 0u) << "entrained gas left in the water, mean height " << height;
  const auto& p = run.state.particles;
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_FALSE(p.enclosed[i]) << "particle " << i << " still enclosed";
}

TEST(EntrainedGas, WithoutARiseSpeedItStaysWithTheWater) {
  EntrainedRun run(0.0);
  run.runTo(0.1);
  auto [height, submerged] = run.submergedGas();
  EXPECT_EQ(submerged, static_cast<std::size_t>(kPockets));
  EXPECT_NEAR(height, kStartHeight, 0.005);
}

TEST(EntrainedGas, DrawIsUniform) {
  // Mean and the fraction below 0.1 of 100000 draws over steps and indices.
  double sum = 0.0;
  int below = 0;
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const double u = entrainedGasDraw(k / 100, static_cast<std::size_t>(k % 100));
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    below += u < 0.1;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);
  EXPECT_NEAR(static_cast<double>(below) / n, 0.1, 0.003);
}

// Gas that has just joined the water (was open, is enclosed now) takes its liquid neighbours' velocity: a gas
// particle at 10 m/s inside a 7 x 7 patch of water moving at (1, 0) m/s leaves with (1, 0); a lone gas particle far
// from the water, also flagged, keeps its own; a liquid particle is untouched.
TEST(EntrainedGas, GasJoiningTheWaterTakesItsVelocity) {
  const double l0 = 0.01, re = 2.1 * l0;
  Particles<2> p;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const bool centre = i == 3 && j == 3;
      p.add(Vec<2>(i * l0, j * l0), centre ? Vec<2>(0.0, 10.0) : Vec<2>(1.0, 0.0), ParticleKind::Fluid,
            centre ? Phase::Gas : Phase::Liquid);
    }
  p.add(Vec<2>(0.5, 0.5), Vec<2>(0.0, -3.0), ParticleKind::Fluid, Phase::Gas);
  const std::size_t centre = 3 * 7 + 3, lone = p.size() - 1;
  NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.7, 0.7), re);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  std::vector<char> joined(p.size(), 0);
  joined[centre] = joined[lone] = 1;
  adoptLiquidVelocity<2>(p, nl, joined, re);
  EXPECT_NEAR(p.velocity[centre][0], 1.0, 1e-12);
  EXPECT_NEAR(p.velocity[centre][1], 0.0, 1e-12);
  EXPECT_EQ(p.velocity[lone], Vec<2>(0.0, -3.0));
  EXPECT_EQ(p.velocity[0], Vec<2>(1.0, 0.0));
}

// The mass the collision model gives gas that moves with the water (solver_collisions.cpp). numerics.
// entrained_gas_inertia: gas below a bubble's resolution moves as liquid in the liquid system; traced on the 5 mm
// waterfall (docs/waterfall.md, fifty-first session) a soft bubble squeezed to 1.7 n0 fell below the resolution with a
// water particle 0.5 l0 from its gas and closing on it at 4.4 m/s; with the gas's inertia the collision left the
// water's approach whole, the liquid correction stopped it with 133 kPa and threw the water out at 20 m/s.
// numerics.bubble_gas_inertia: a resolved bubble's gas follows the water's velocity extended into the bubble
// (bubble_gas_motion.hpp); traced at 5 mm (fifty-second session) a water particle closed from 0.83 to 0.27 l0 on such
// gas over 12 steps, every step inside the collision distance, and was thrown up at 12 m/s. Here: the pocket tank's
// first pocket (one gas particle, enclosed) or the top gas particle of tank_case.hpp's bubble, after a first step (in
// which the pocket joined the water and took its velocity), the water above it then moved to 0.5 l0 over it and sent
// down at 1 m/s more than the gas, no restitution. The collision stage shares the approach by mass: with the water's
// inertia the water gives up half of it (+0.5 m/s), with the gas's none (the gas takes it all).
TEST(EntrainedGas, WaterClosingOnGasThatMovesWithItSharesTheApproachByTheInertiaTheKeyGives) {
  struct Row {
    const char* gas;      // "pocket": below a bubble's resolution; "bubble": a resolved bubble's
    const char* key;      // the key that sets the gas's inertia, and its value
    const char* inertia;
    double water_change;  // the water's vertical velocity change in the collision stage [m/s]
  };
  const Row rows[] = {{"pocket", "entrained_gas_inertia", "liquid", 0.5},
                      {"pocket", "entrained_gas_inertia", "gas", 0.0},
                      {"bubble", "bubble_gas_inertia", "liquid", 0.5},
                      {"bubble", "bubble_gas_inertia", "gas", 0.0}};
  for (const Row& row : rows) {
    const std::string name = std::string(row.gas) + "_" + row.inertia;
    SCOPED_TRACE(name);
    const std::string numerics = std::string("collision_distance = 0.8\ncollision_restitution = 0.0\n") + row.key +
                                 " = \"" + row.inertia + "\"\n";
    const bool pocket = std::string(row.gas) == "pocket";
    test_support::SolverRun<2> run(pocket ? test_support::pocketTankCase("gas_inertia", numerics)
                                          : test_support::tankCase("gas_inertia", true, true, "", numerics),
                                   "gas_inertia.toml");
    auto& p = run.state.particles;
    auto at = [&](Vec<2> where) {
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.kind[i] == ParticleKind::Fluid && (p.position[i] - where).norm() < 1e-9) return i;
      return p.size();
    };
    const Vec<2> gas_at = pocket ? Vec<2>(0.0175, 0.0125) : Vec<2>(0.0475, 0.0375);  // the bubble's top row
    std::size_t gas = at(gas_at), water = at(gas_at + Vec<2>(0.0, 0.005));
    ASSERT_LT(gas, p.size());
    ASSERT_LT(water, p.size());
    ASSERT_EQ(p.phase[gas], Phase::Gas);
    ASSERT_EQ(p.phase[water], Phase::Liquid);
    const auto gas_id = p.id[gas], water_id = p.id[water];  // the steps sort the particles by place
    run.solver->step(1.0);
    auto byId = [&](std::uint64_t id) {
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.id[i] == id) return i;
      return p.size();
    };
    gas = byId(gas_id), water = byId(water_id);
    ASSERT_EQ(run.solver->lastReport().entrained_gas == 0, !pocket) << "the bubble is resolved, the pockets not";
    p.position[water] = p.position[gas] + Vec<2>(0.0, 0.0025);
    p.velocity[water] = p.velocity[gas] + Vec<2>(0.0, -1.0);
    const auto path = test_support::freshDir("gas_inertia_" + name) / "trace.csv";
    run.solver->traceParticle(water_id, 0.0, path.string());
    run.solver->step(1.0);
    // column 12: uy
    const double predicted = test_support::traceValue(path, "predict", "self", 12);
    const double collided = test_support::traceValue(path, "collision", "self", 12);
    ASSERT_TRUE(std::isfinite(predicted) && std::isfinite(collided)) << "no rows for the water in " << path;
    EXPECT_NEAR(collided - predicted, row.water_change, 0.01);
  }
}
