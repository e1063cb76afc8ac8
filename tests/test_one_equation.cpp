// Water and air in one pressure equation (numerics.coupling = "one_equation"; docs/two-phase.md): the interparticle
// density of interface_density.hpp against the exact two-layer hydrostatics, and a tank of still water under still
// air that must stay still (its channel under closed air: tests/test_stabilised_air.cpp). The same tank with the
// arithmetic mean of the two densities as the pair's density (the interface taken midway between every pair) lifts
// the air off the water: 0.1 m/s by 0.18 s (docs/two-phase.md).
#include <gtest/gtest.h>

#include <cmath>

#include "case/case_file.hpp"
#include "mps/interface_density.hpp"
#include "support/breathing_bubble.hpp"
#include "support/closed_channel.hpp"
#include "support/run_case.hpp"
#include "support/scratch.hpp"
#include "support/tank_walls.hpp"

using namespace mistfall;

namespace {

constexpr double kWater = 1000.0, kAir = 1.2, kG = 9.81, kL0 = 0.005;

// Hydrostatic pressure of water below y = 0 under air, with p = 0 at y = top (air above the interface).
double twoLayerPressure(double y, double top) {
  return y >= 0.0 ? kAir * kG * (top - y) : kAir * kG * top - kWater * kG * y;
}

struct LatticePair {
  int water_row;  // rows below the interface: 0 is the row whose centre lies l0/2 under it
  int air_row;    // rows above it: 0 is the row l0/2 over it
};

// For every water-air pair of a lattice cut by a straight interface midway between two rows, within the Laplacian
// radius 3.1 l0, the pair density with the interface distances of the rows makes (p_j - p_i)/rho_ij = g . r_ij
// exactly (the arithmetic mean only where the interface lies midway between the two). A horizontal offset changes
// neither side: the distances are interpolated linearly along the segment.
TEST(InterfaceDensity, ExactForEveryLatticePairAcrossAStraightInterface) {
  const LatticePair pairs[] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 2}, {2, 0}, {1, 2}};
  for (const auto& pair : pairs) {
    const double yi = -(pair.water_row + 0.5) * kL0, yj = (pair.air_row + 0.5) * kL0;
    const double phi_i = -yi, phi_j = yj;
    const double rho = pairDensity(kWater, kAir, phi_i, phi_j);
    const double dp = twoLayerPressure(yj, 0.04) - twoLayerPressure(yi, 0.04);
    EXPECT_NEAR(dp / rho, -kG * (yj - yi), 1e-12) << pair.water_row << " " << pair.air_row;
    const double mean = 0.5 * (kWater + kAir);
    if (pair.water_row != pair.air_row) EXPECT_GT(std::abs(dp / mean + kG * (yj - yi)), 1e-3);
  }
  EXPECT_EQ(pairDensity(kWater, kWater, 0.1, 0.7), kWater);
  EXPECT_DOUBLE_EQ(pairDensity(kWater, kAir, 0.3, 0.3), 0.5 * (kWater + kAir));
}

// The interface distances of a lattice cut by a straight interface: (k + 1/2) l0 for the k-th row on either side.
// 0.1 m of air over 6 cm of water, l0 = 5 mm: a lattice cut by a straight interface at y = 0.06.
std::string cutLattice() {
  return "[case]\nname = \"cut\"\ndimension = 2\n[domain]\nmin = [-0.02, -0.02]\nmax = [0.12, 0.12]\n"
         "[numerics]\nparticle_spacing = 0.005\n[output]\nend_time = 0.1\n"
         "[[region]]\nname = \"air\"\nmaterial = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.1]\n"
         "[[region]]\nname = \"water\"\nmaterial = \"water\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.06]\n" +
         test_support::tankWalls(0.1, 0.1, 0.02);
}

TEST(InterfaceDensity, DistancesOfALatticeCutByAStraightInterface) {
  test_support::SolverRun<2> run(cutLattice(), "cut.toml");
  const auto& nl = run.solver->currentNeighbours();
  const auto& p = run.state.particles;
  const auto phi = interfaceDistances<2>(p, nl, 3.1 * kL0, kL0);
  int checked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const double from_interface = std::abs(p.position[i].y() - 0.06);
    if (from_interface > 2.6 * kL0) continue;  // the rows with a particle of the other phase within the radius
    EXPECT_NEAR(phi[i], from_interface, 1e-9) << p.position[i].transpose();
    ++checked;
  }
  EXPECT_EQ(checked, 6 * 20);
}

// One water particle of the interface's row moved down by 0.2 l0: the air particle above it stays 0.5 l0 from the
// interface (the other particles have not moved). The fitted line moves by a fraction of that; the distance to the
// nearest water particle would read 0.7 l0, the feedback that grew a separation (docs/two-phase.md).
TEST(InterfaceDensity, OneParticleMovedHardlyMovesTheInterface) {
  test_support::SolverRun<2> run(cutLattice(), "cut.toml");
  auto& p = run.state.particles;
  auto at = [&](double x, double y) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && (p.position[i] - Vec<2>(x, y)).norm() < 1e-6) return i;
    ADD_FAILURE() << "no particle at " << x << ", " << y;
    return std::size_t{0};
  };
  const std::size_t water = at(0.0475, 0.0575), air = at(0.0475, 0.0625);
  p.position[water].y() -= 0.2 * kL0;
  const auto phi = interfaceDistances<2>(p, run.solver->currentNeighbours(), 3.1 * kL0, kL0);
  EXPECT_NEAR(phi[air], 0.5 * kL0, 0.05 * kL0);
  EXPECT_GT(phi[water], 0.6 * kL0);  // the moved particle itself is deeper
}

// 6 cm of water under 4 cm of air open at the top, l0 = 5 mm (cases/two_layer_tank.toml): at rest to 1 s (both
// phases below 1 mm/s at every 0.1 s; nothing lost) with the two-layer hydrostatic pressure in the water. Measured:
// 1e-4 m/s to 10 s. The arithmetic mean as the pair density fails by 0.1 s (0.1 m/s by 0.18 s); the distance to
// the nearest particle of the other phase as phi fails from 0.6 s (a separation at the walls, 9e-3 m/s at 0.6 s).
TEST(OneEquation, StillWaterUnderStillAirStaysAtRest) {
  const CaseConfig config = test_support::loadShippedCase("two_layer_tank.toml");
  std::vector<double> times;
  for (int k = 1; k <= 10; ++k) times.push_back(0.1 * k);
  test_support::runThrough<2>(config, times, [&](double t, const SimulationState<2>& s, const MpsSolver<2>& solver) {
    const auto [water, air] = solver.maxPhaseSpeeds();
    EXPECT_LT(water, 1e-3) << "t = " << t;
    EXPECT_LT(air, 1e-3) << "t = " << t;
    EXPECT_EQ(s.particles.count(ParticleKind::Escaped), 0u);
    if (t < 0.99) return;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      if (s.particles.kind[i] != ParticleKind::Fluid || s.particles.phase[i] != Phase::Liquid) continue;
      const double depth = 0.06 - s.particles.position[i].y();
      EXPECT_NEAR(s.particles.pressure[i], kWater * kG * depth + kAir * kG * 0.04, 0.02 * kWater * kG * depth)
          << s.particles.position[i].transpose();
    }
  });
}


// numerics.gap_water_floor (gap_water_floor.hpp): the same channel's water leaves its brink (x = 0.40 m) and falls
// through the air into the pit. Nothing pushes a falling sheet sideways but the air's pressure, tens of pascals, so
// it keeps the brink's horizontal speed. Over 0.2-0.3 s the water 1-6 cm below the brink moves out at 0.77 m/s (the
// water over the bed's last 2 cm at 0.64 m/s) and lies 5 cm out from the bed's face (x = 0.451 m). Without the floor
// it turned down the bed's face, held there by the tension of the water at the edge (on waterfall_small: -0.4 to
// -1.3 kPa against the air's -0.14 kPa): -0.045 m/s at x = 0.413 m.
TEST(OneEquation, WaterOverABrinkSpringsClearOfItsFaceWithTheGapFloor) {
  std::string text = test_support::closedChannelCase("one_equation");
  text.replace(text.find("gas_domain = \"closed\""), std::string("gas_domain = \"closed\"").size(),
               "gas_domain = \"closed\"\ngap_water_floor = true");
  const CaseConfig config = parseCase(text, "closed_channel.toml");
  ASSERT_TRUE(config.numerics.gap_water_floor);
  std::vector<double> times;
  for (int k = 0; k <= 10; ++k) times.push_back(0.2 + 0.01 * k);
  double falling_u = 0.0, falling_x = 0.0, brink_u = 0.0;
  int falling = 0, brink = 0;
  std::int64_t floors = 0;
  test_support::runThrough<2>(config, times, [&](double, const SimulationState<2>& s, const MpsSolver<2>& solver) {
    const auto& p = s.particles;
    floors += static_cast<std::int64_t>(solver.lastReport().gap_water_floors);
    EXPECT_EQ(0u, p.count(ParticleKind::Escaped));
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Liquid) continue;
      const Vec<2>& x = p.position[i];
      if (x[0] > 0.40 && x[1] < -0.01 && x[1] > -0.06) falling_u += p.velocity[i][0], falling_x += x[0], ++falling;
      if (x[0] > 0.38 && x[0] < 0.40 && x[1] > 0.0) brink_u += p.velocity[i][0], ++brink;
    }
  });
  ASSERT_GT(falling, 50);
  ASSERT_GT(brink, 50);
  falling_u /= falling, falling_x /= falling, brink_u /= brink;
  EXPECT_GT(falling_u, 0.8 * brink_u) << "falling " << falling_u << " m/s, brink " << brink_u << " m/s";
  EXPECT_GT(falling_x, 0.42);
  EXPECT_GT(floors, 0);  // the floor acts, and is counted
}

TEST(OneEquation, GapFloorIsTheOneEquations) {
  try {
    std::string text = test_support::slurp(std::string(MISTFALL_SOURCE_DIR) + "/cases/waterfall_small.toml");
    text.replace(text.find("[numerics]\n"), std::string("[numerics]\n").size(), "[numerics]\ngap_water_floor = true\n");
    parseCase(text, "waterfall_small.toml");
    FAIL() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("gap_water_floor"), std::string::npos) << e.what();
  }
}

TEST(OneEquation, NeedsTheStabilisedScheme) {
  try {
    std::string text = test_support::slurp(std::string(MISTFALL_SOURCE_DIR) + "/cases/two_layer_tank.toml");
    text.erase(text.find("scheme = \"stabilised\"\n"), std::string("scheme = \"stabilised\"\n").size());
    parseCase(text, "two_layer_tank.toml");
    FAIL() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.scheme = \"stabilised\""), std::string::npos) << e.what();
  }
}

}  // namespace

namespace {

// The breathing bubble of tests/test_bubble_breathing.cpp (a = 2 cm of air in a ring of water to b = 8 cm, no gravity,
// the water started with u = -U0 a / r, U0 = 0.05 m/s, l0 = 2.5 mm, dt = 1e-4 s) on the one equation: the 2D
// Rayleigh-Plesset oscillator, omega^2 = 2 K / (rho_l a^2 ln(b/a)) with K = rho_g c^2 (period 8.88 ms, pressure
// amplitude 2 K U0 / (a omega) = 981 Pa). The two-system coupling follows the first compression but not the
// expansion (its gas only follows the water); here the air has its own pressure and momentum and breathes out too.
// The implicit compressibility damps each period by (1 + (omega dt)^2)^(-N/2) = 0.80 for N = 89 steps a period.
// Measured: peaks 913, -800, 730, -641 Pa, zero crossings every 4.48-4.51 ms (period 8.97 ms, +1.0 %).
constexpr double kBreathingK = test_support::kBreathingGasDensity * test_support::kBreathingSoundSpeed *
                                test_support::kBreathingSoundSpeed;
constexpr double kA = test_support::kBreathingRadius, kB = test_support::kBreathingRing;
constexpr double kU0 = test_support::kBreathingWallSpeed, kBreathingDt = 1e-4;

TEST(OneEquation, BubbleBreathesInAndOutAtTheTwoDimensionalRayleighPlessetFrequency) {
  test_support::SolverRun<2> run(
      test_support::breathingBubbleCase(0.0025, kBreathingDt,
                                        "scheme = \"stabilised\"\ncoupling = \"one_equation\"\ncollision_distance = 0.8\n"
                                        "pressure_source = \"mixed\"\nsource_relaxation = 0.0\n"),
      "breathing_bubble.toml");
  test_support::startBreathing(run.state.particles);
  // The bubble's mean pressure: its zero crossings and the extreme between two of them.
  std::vector<double> zeros, extremes;
  double last = 0.0, last_time = 0.0, extreme = 0.0;
  const double until = 0.028;  // three periods
  while (run.state.time < until - 1e-12) {
    run.solver->step(until);
    std::size_t count = 0;
    const double P = test_support::bubbleMeanPressure(*run.solver, &count), t = run.state.time;
    ASSERT_GT(count, 150u) << "the bubble broke up at " << run.state.time << " s";
    if (std::abs(P) > std::abs(extreme)) extreme = P;
    if (last != 0.0 && (last > 0.0) != (P > 0.0)) {
      zeros.push_back(last_time + (t - last_time) * last / (last - P));
      extremes.push_back(extreme);
      extreme = 0.0;
    }
    last = P, last_time = t;
  }
  const double omega = std::sqrt(2.0 * kBreathingK / (1000.0 * kA * kA * std::log(kB / kA)));
  const double amplitude = 2.0 * kBreathingK * kU0 / (kA * omega);
  const double damping = std::pow(1.0 + omega * omega * kBreathingDt * kBreathingDt, -0.5 * (2.0 * M_PI / omega) / kBreathingDt);
  ASSERT_GE(zeros.size(), 6u);
  const double period = (zeros[5] - zeros[0]) / 2.5;
  std::printf("period %.3f ms (analytic %.3f); peaks %.0f %.0f %.0f %.0f Pa (analytic %.0f, damped by %.2f a period)\n",
              1e3 * period, 2e3 * M_PI / omega, extremes[0], extremes[1], extremes[2], extremes[3], amplitude, damping);
  EXPECT_NEAR(period, 2.0 * M_PI / omega, 0.03 * 2.0 * M_PI / omega);
  EXPECT_NEAR(zeros[0], M_PI / omega, 0.03 * M_PI / omega);       // the first compression ends on time
  EXPECT_NEAR(extremes[0], amplitude, 0.10 * amplitude);         // and peaks at the analytic pressure
  EXPECT_LT(extremes[1], -0.7 * amplitude);                      // the bubble expands: suction, not coasting water
  EXPECT_NEAR(extremes[2] / extremes[0], damping, 0.05);         // one period later, as the implicit damping says
  EXPECT_NEAR(extremes[3] / extremes[1], damping, 0.05);
}

}  // namespace

// [[inflow]] pressure (inflow_pressure.hpp) on the one equation: the closed channel above, 0-0.1 s, while the sealed
// box's level rises by 5 kPa. With the water's source ("solved") the buffer's rows read the gap its upstream layer
// opens behind it (the next layer is made when a whole l0 fits) and the wall it leaves as expansion, and with no free
// surface in the closed box they hold tension: down to -7 to -32 kPa while the water beside the gate (x < 0.10 m)
// holds 0 to +7 kPa. With "harmonic" rows (no source) the buffer's lowest pressure stays within 35 Pa of that water's
// lowest: its hydrostatic height, less than rho g l0.
TEST(OneEquation, HarmonicInflowBufferHoldsTheWatersPressureNotTension) {
  for (const bool harmonic : {false, true}) {
    std::string text = test_support::closedChannelCase("one_equation");
    if (harmonic) text.replace(text.find("discharge = 0.016"), 17, "discharge = 0.016\npressure = \"harmonic\"");
    const CaseConfig config = parseCase(text, "closed_channel.toml");
    double lowest_below = 0.0;  // the buffer's lowest pressure less the lowest of the water beside the gate
    const std::vector<double> times{0.002, 0.006, 0.01, 0.02, 0.04, 0.06, 0.08, 0.1};
    test_support::runThrough<2>(config, times, [&](double, const SimulationState<2>& s, const MpsSolver<2>&) {
      const auto& p = s.particles;
      double buffer = 1e300, water = 1e300;
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.kind[i] == ParticleKind::Inflow) buffer = std::min(buffer, p.pressure[i]);
        if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Liquid && p.position[i][0] < 0.10 &&
            p.position[i][1] > 0.0)
          water = std::min(water, p.pressure[i]);
      }
      lowest_below = std::min(lowest_below, buffer - water);
    });
    if (harmonic)
      EXPECT_GT(lowest_below, -1000.0 * 9.81 * 0.01) << "harmonic";
    else
      EXPECT_LT(lowest_below, -3000.0) << "solved: the tension this key removes";
  }
}
