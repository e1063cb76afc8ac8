// Gas in a closed box (numerics.gas_domain = "closed", docs/waterfall.md): every particle of the gas system carries
// a pressure unknown and gas pressures may fall below the ambient, their level fixed by eq. (17)'s compressibility.
// Still air in a closed box must be hydrostatic (dp/dy = -rho_g g) and stay still; a void in the air must draw the
// gas in by suction (negative pressure, which free-surface gas never has) and close no faster than a free fall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/enclosed_gas.hpp"
#include "mps/solver.hpp"
#include "support/case_text.hpp"
#include "support/run_case.hpp"
#include "support/tank_walls.hpp"

using namespace mistfall;

namespace {

// A closed 2D box 0.1 m x 0.1 m (l0 = 5 mm, walls all round): a 2 cm layer of water under air, optionally with a
// void in the air: a band 1 cm high at y = 0.045-0.055 m left empty.
std::string airBoxCase(const std::string& gas_domain, bool void_band, bool floor_pocket = false) {
  std::string text = R"(
[case]
name = "closed_air"
dimension = 2
[domain]
min = [-0.02, -0.02]
max = [0.12, 0.12]
[numerics]
particle_spacing = 0.005
dt_max = 5e-4
pressure_source = "mixed"
source_relaxation = 0.01
gas_domain = ")" + gas_domain + R"("
[output]
end_time = 1.0
)";
  if (void_band)
    text += "[[region]]\nname = \"low\"\nmaterial = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.045]\n"
            "[[region]]\nname = \"high\"\nmaterial = \"gas\"\nmin = [0.0, 0.055]\nmax = [0.1, 0.1]\n";
  else
    text += "[[region]]\nname = \"air\"\nmaterial = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.1]\n";
  text += "[[region]]\nname = \"water\"\nmaterial = \"water\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.02]\n";
  if (floor_pocket)  // two gas particles in the water's lower left corner, against the floor and the wall
    text += "[[region]]\nname = \"pocket\"\nmaterial = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.005]\n";
  text += test_support::tankWalls(0.1, 0.1, 0.02);
  text += test_support::wallRegion("lid", -0.02, 0.1, 0.12, 0.12);
  return text;
}

struct AirBox : test_support::SolverRun<2> {
  explicit AirBox(const std::string& text) : SolverRun(text, "closed_air.toml") {}
  double maxGasSpeed() const {
    const auto& p = state.particles;
    double v = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(p.kind[i], p.phase[i])) v = std::max(v, p.velocity[i].norm());
    return v;
  }
  double minGasPressure() const {
    const auto& p = state.particles;
    double m = 1e300;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(p.kind[i], p.phase[i])) m = std::min(m, p.pressure[i]);
    return m;
  }
};

}  // namespace

TEST(ClosedGas, CaseFileKeyAndItsLimits) {
  EXPECT_EQ(parseCase(airBoxCase("closed", false), "a.toml").numerics.gas_domain, GasDomain::Closed);
  EXPECT_EQ(parseCase(airBoxCase("open", false), "a.toml").numerics.gas_domain, GasDomain::Open);
  const std::string bad = test_support::errorOf(airBoxCase("sealed", false));
  EXPECT_HAS(bad, "numerics.gas_domain");
  EXPECT_HAS(bad, "\"closed\"");
  std::string incompressible = airBoxCase("closed", false);
  incompressible.replace(incompressible.find("[numerics]"), 10, "[physics.gas]\nsound_speed = \"inf\"\n[numerics]");
  EXPECT_HAS(test_support::errorOf(incompressible), "physics.gas.sound_speed");
}

// Still air in a closed box: the pressure falls with height as rho_g g (the box is 0.1 m high: about 1.2 Pa top to
// bottom) and the air stays still.
TEST(ClosedGas, StillAirIsHydrostatic) {
  AirBox box(airBoxCase("closed", false));
  for (int step = 0; step < 60; ++step) box.solver->step(1.0);
  const auto& p = box.state.particles;
  // Least-squares slope of p against y over the gas.
  double sy = 0, sp = 0, syy = 0, syp = 0, count = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i])) continue;
    const double y = p.position[i][1];
    sy += y, sp += p.pressure[i], syy += y * y, syp += y * p.pressure[i], count += 1;
  }
  const double slope = (count * syp - sy * sp) / (count * syy - sy * sy);
  const double expected = -box.config.physics.gas.density * 9.81;
  EXPECT_NEAR(slope, expected, 0.1 * std::abs(expected)) << "dp/dy of the still air";
  EXPECT_LT(box.maxGasSpeed(), 0.01) << "still air in a closed box";
}

// A 1 cm void across the box: in a closed box the gas around it is at suction (negative gauge pressure; free-surface
// gas never is), the void closes, and no gas moves faster than a free fall across the void, sqrt(2 g h).
TEST(ClosedGas, VoidDrawsTheGasInGently) {
  AirBox closed(airBoxCase("closed", true));
  AirBox open(airBoxCase("open", true));
  closed.solver->step(1.0);
  EXPECT_LT(closed.minGasPressure(), 0.0) << "suction at the void";
  EXPECT_GE(open.minGasPressure(), 0.0);
  double closed_speed = closed.maxGasSpeed(), open_speed = open.maxGasSpeed();
  for (int step = 1; step < 100; ++step) {
    closed.solver->step(1.0);
    open.solver->step(1.0);
    closed_speed = std::max(closed_speed, closed.maxGasSpeed());
    open_speed = std::max(open_speed, open.maxGasSpeed());
  }
  std::printf("void closing: max gas speed closed %.4f m/s, open %.4f m/s\n", closed_speed, open_speed);
  EXPECT_LT(closed_speed, std::sqrt(2.0 * 9.81 * 0.01));
  // The void has closed: no gas particle inside the box is short of neighbours any more.
  const auto& p = closed.state.particles;
  const auto& nl = closed.solver->currentNeighbours();
  const double re = closed.solver->constants().re_number_density;
  std::size_t short_of_neighbours = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i])) continue;
    int count = 0;
    for (auto s = nl.begin(i); s < nl.end(i); ++s)
      count += (p.position[nl.indices[s]] - p.position[i]).norm() < re;
    short_of_neighbours += count < 9;  // 12 in a full lattice at re = 2.1 l0
  }
  EXPECT_EQ(short_of_neighbours, 0u);
}

// A pocket of gas in the water against the floor and the side wall: in an open gas domain it borders walls, so it
// is not enclosed (it would be open air inside the pool); in a closed one it is entrained gas. The air above, which
// touches the water, the walls and the lid, is open in both, even when the size limit exceeds it (the largest
// region is never a pocket).
TEST(ClosedGas, SmallPocketAgainstAWallIsEntrainedOnlyInAClosedDomain) {
  for (const std::size_t limit : {std::size_t{0}, std::size_t{6}, std::size_t{1000000}}) {
    const bool closed = limit > 0;
    AirBox box(airBoxCase(closed ? "closed" : "open", false, true));
    const auto& p = box.state.particles;
    const auto& nl = box.solver->currentNeighbours();
    GasRegions regions;
    findGasRegions<2>(p, nl, box.solver->constants().re_number_density, 0.005, regions, {nullptr, limit});
    std::size_t pocket = 0, air = 0, pocket_enclosed = 0, air_enclosed = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!isGas(p.kind[i], p.phase[i])) continue;
      const bool in_pocket = p.position[i][1] < 0.02;
      (in_pocket ? pocket : air) += 1;
      (in_pocket ? pocket_enclosed : air_enclosed) += regions.enclosed_particle[i];
    }
    ASSERT_EQ(pocket, 2u);
    EXPECT_EQ(pocket_enclosed, closed ? 2u : 0u) << "limit " << limit;
    EXPECT_EQ(air_enclosed, 0u) << "limit " << limit;
    EXPECT_GT(air, 100u);
  }
}

namespace {

// The air box's case text with one more [numerics] key.
std::string airBoxWith(const std::string& key, double value) {
  std::string t = airBoxCase("closed", false);
  t.replace(t.find("gas_domain"), 10, key + " = " + std::to_string(value) + "\ngas_domain");
  return t;
}

// Gives the gas particle nearest (0.05, 0.06), in the middle of the box, the velocity (speed, 0); returns it.
std::size_t shootGas(Particles<2>& p, double speed) {
  std::size_t shot = p.size();
  double best = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i])) continue;
    const double d = (p.position[i] - Vec<2>(0.05, 0.06)).norm();
    if (d < best) best = d, shot = i;
  }
  p.velocity[shot] = Vec<2>(speed, 0.0);
  return shot;
}

}  // namespace

// numerics.gas_correction_limit caps the move a gas particle's pressure correction makes in one step at limit l0:
// one gas particle shot at 20 m/s through still air raises a pressure outlier that, unlimited, kicks its
// neighbours by more than that; limited, no gas velocity changes by more than limit l0 / dt (besides g dt).
TEST(ClosedGas, CorrectionLimitCapsTheKickOfAPressureOutlierAtASpeedThatDoesNotGrowAsTheStepShrinks) {
  auto withLimit = [](double limit) { return airBoxWith("gas_correction_limit", limit); };
  EXPECT_HAS(test_support::errorOf(withLimit(1.5)), "numerics.gas_correction_limit");
  const double limit = 0.02, l0 = 0.005, dt_max = 5e-4;
  const double cap = limit * l0 / dt_max;  // 0.2 m/s
  // One gas particle shot at 20 and at 80 m/s: the Courant step is 4 times shorter for the second. The capped
  // kick of its neighbours stays at limit l0 / dt_max in both (a cap of limit l0 / dt would be 20 and 80 m/s).
  for (double shot_speed : {20.0, 80.0}) {
    double largest_kick[2] = {0.0, 0.0};
    std::size_t capped = 0;
    double dt = 0.0;
    for (int limited = 0; limited < 2; ++limited) {
      AirBox box(withLimit(limited ? limit : 0.0));
      auto& p = box.state.particles;
      const std::uint64_t shot = p.id[shootGas(p, shot_speed)];
      std::vector<Vec<2>> before(p.next_id, Vec<2>::Zero());  // by particle id: a step may reorder the arrays
      for (std::size_t i = 0; i < p.size(); ++i) before[p.id[i]] = p.velocity[i];
      const auto& report = box.solver->step(1.0);
      dt = report.dt;
      if (limited) {
        capped = report.gas_corrections_capped;
        EXPECT_EQ(report.gas_correction_cuts, capped) << "every cut is the correction limit's";
        EXPECT_EQ(report.gas_speed_cuts, 0u);
      }
      const Vec<2> gravity_change(0.0, -9.81 * dt);
      for (std::size_t i = 0; i < p.size(); ++i)
        if (isGas(p.kind[i], p.phase[i]) && p.id[i] != shot)
          largest_kick[limited] =
              std::max(largest_kick[limited], (p.velocity[i] - before[p.id[i]] - gravity_change).norm());
    }
    EXPECT_NEAR(dt, 0.2 * l0 / shot_speed, 1e-12) << "the Courant step of the shot particle";
    // (the air's viscosity adds about 1e-4 m/s to the capped kick)
    EXPECT_LE(largest_kick[1], cap + 2e-3) << "shot at " << shot_speed << " m/s";
    EXPECT_GT(largest_kick[0], 5.0 * cap) << "the unlimited kick must exceed the cap";
    EXPECT_GT(capped, 0u) << "the step reports the capped corrections";
    std::printf("shot at %.0f m/s (dt %.2e s): kick of the gas around it unlimited %.3f m/s, limited %.3f m/s "
                "(cap %.3f m/s, %zu capped)\n",
                shot_speed, dt, largest_kick[0], largest_kick[1], cap, capped);
  }
}

// numerics.dispersed_gas_fraction is a fraction: outside [0, 1] the case is refused and the message names the key.
TEST(ClosedGas, DispersedGasFractionOutsideItsRangeIsRefused) {
  const std::string error = test_support::errorOf(airBoxWith("dispersed_gas_fraction", 1.5));
  EXPECT_HAS(error, "numerics.dispersed_gas_fraction");
  EXPECT_HAS(error, "1.5");
}

// numerics.gas_speed_limit: a gas particle shot at 20 m/s through still closed air leaves its first step at the
// limit (unlimited it keeps most of its speed), so the next Courant step is C l0 / limit again.
TEST(ClosedGas, SpeedLimitHoldsAShotGasParticleAndTheTimeStep) {
  auto withLimit = [](double limit) { return airBoxWith("gas_speed_limit", limit); };
  EXPECT_HAS(test_support::errorOf(withLimit(2000.0)), "numerics.gas_speed_limit");
  const double limit = 5.0, l0 = 0.005;
  double fastest[2] = {0.0, 0.0}, second_dt[2] = {0.0, 0.0};
  for (int limited = 0; limited < 2; ++limited) {
    AirBox box(withLimit(limited ? limit : 0.0));
    auto& p = box.state.particles;
    shootGas(p, 20.0);
    const auto& report = box.solver->step(1.0);
    EXPECT_NEAR(report.dt, 0.2 * l0 / 20.0, 1e-12);
    if (limited) {
      EXPECT_GE(report.gas_corrections_capped, 1u);
      EXPECT_EQ(report.gas_speed_cuts, report.gas_corrections_capped) << "every cut is the speed limit's";
      EXPECT_EQ(report.gas_correction_cuts, 0u);
    }
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(p.kind[i], p.phase[i])) fastest[limited] = std::max(fastest[limited], p.velocity[i].norm());
    second_dt[limited] = box.solver->step(1.0).dt;
  }
  EXPECT_GT(fastest[0], 10.0) << "unlimited, the shot particle keeps most of its speed";
  EXPECT_LE(fastest[1], limit * (1.0 + 1e-12));
  EXPECT_NEAR(second_dt[1], 0.2 * l0 / limit, 1e-3 * second_dt[1]);
  std::printf("gas shot at 20 m/s, after one step: unlimited %.2f m/s, limited %.2f m/s; next dt %.2e / %.2e s\n",
              fastest[0], fastest[1], second_dt[0], second_dt[1]);
}
