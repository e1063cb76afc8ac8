// Free-surface detection (numerics.surface_threshold and surface_neighbour_fraction): a clump of a splash has a
// high number density but few neighbours; with the neighbour-count test it is a free surface (p = 0) instead of a
// pressure island that throws its neighbours apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/number_density.hpp"
#include "mps/solver.hpp"
#include "support/tank_walls.hpp"

using namespace mistfall;

namespace {

// Six water particles (a 3 x 2 block at l0 = 1 cm) in free fall, no walls.
std::string clumpCase(double fraction, double asymmetry = 0.0) {
  return R"(
[case]
name = "clump"
dimension = 2
[domain]
min = [-0.5, -0.5]
max = [0.5, 0.5]
[numerics]
particle_spacing = 0.01
dt_max = 1e-4
surface_neighbour_fraction = )" + std::to_string(fraction) + R"(
surface_asymmetry = )" + std::to_string(asymmetry) + R"(
[output]
end_time = 1.0
[[region]]
name = "drop"
material = "water"
min = [0.0, 0.0]
max = [0.03, 0.02]
)";
}

// Squeezes four particles into a square of side 0.55 l0 (closer than a lattice, beyond the collision distance
// 0.5 l0): each has two neighbours at 0.55 l0 and one at 0.78 l0, n >= 2 (2.1/0.55 - 1) + (2.1/0.78 - 1) = 7.3,
// above beta n0 = 6.3, but 4-5 neighbours where a full lattice has 12. The other two sit 1.45 l0 to the side
// (n about 4: free surface, p = 0), so the clump's pressure is determined.
double maxPressureAfterOneStep(double fraction, std::size_t* neighbour_surfaces = nullptr, double asymmetry = 0.0) {
  const CaseConfig c = parseCase(clumpCase(fraction, asymmetry), "clump.toml");
  SimulationState<2> s;
  s.particles = buildParticles<2>(c);
  EXPECT_EQ(6u, s.particles.size());
  const double side = 0.0055;
  for (std::size_t i = 0; i < 6; ++i)
    s.particles.position[i] = Vec<2>(i < 4 ? (i / 2) * side : side + 0.0145, (i % 2) * side);
  MpsSolver<2> solver(c, s);
  const StepReport report = solver.step(1.0);
  if (neighbour_surfaces) *neighbour_surfaces = report.neighbour_surfaces;
  double p_max = 0.0;
  for (double p : s.particles.pressure) p_max = std::max(p_max, p);
  return p_max;
}

}  // namespace

TEST(SurfaceDetection, NeighbourCountMatchesTheLattice) {
  // A full 2D lattice: 12 neighbours within 2.1 l0 for an interior particle.
  Particles<2> p;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) p.add(Vec<2>(0.01 * i, 0.01 * j), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 0.021);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  const std::size_t centre = 4 * 9 + 4;
  auto all = [](std::int32_t) { return true; };
  EXPECT_EQ(12, neighbourCountAt<2>(centre, p.position, nl, 0.021, all));
  EXPECT_EQ(0, neighbourCountAt<2>(centre, p.position, nl, 0.021, [](std::int32_t) { return false; }));
  EXPECT_EQ(5, neighbourCountAt<2>(0, p.position, nl, 0.021, all));  // a corner: (1,0),(2,0),(0,1),(1,1),(0,2)
}

TEST(SurfaceDetection, SplashClumpIsAFreeSurfaceWithTheNeighbourTest) {
  EXPECT_GT(maxPressureAfterOneStep(0.0), 100.0);  // number density alone: a pressure island
  // With the neighbour count (4-5 of 12): free surface, p = 0, at every fraction from 0.5 (6 needed) up.
  // The clump's four particles are dense enough for an unknown: the test, not the number density, sets them free.
  // So it is with the asymmetry test alone (surface_asymmetry = 0.15): each sees its neighbours on one side.
  const std::pair<double, double> tests[] = {{0.5, 0.0}, {0.7, 0.0}, {0.85, 0.0}, {0.0, 0.15}};
  for (const auto& [fraction, asymmetry] : tests) {
    std::size_t counted = 0;
    EXPECT_EQ(0.0, maxPressureAfterOneStep(fraction, &counted, asymmetry)) << fraction << ", " << asymmetry;
    EXPECT_EQ(4u, counted) << fraction << ", " << asymmetry;
  }
}

namespace {

// The water's kinetic energy per unit mass and depth, sum |u|^2 / 2 over the fluid particles [m^2/s^2 per particle
// mass]: its largest value over 0.1-1 s in a tank 20 x 15 cm (l0 = 1 cm, the stabilised liquid with the waterfalls'
// numerics) whose corner particle is kicked at (-0.15, -0.23) m/s into the corner at t = 0 (the speed at which a
// pool particle of waterfall_small went into the pool's corner, docs/waterfall.md), and that kick's energy.
struct KickedTank {
  double largest = 0.0, kick = 0.0;  // kinetic energies
  std::size_t neighbour_surfaces = 0;  // particle-solves made free surface by the neighbour test over the 1 s
};
KickedTank kickedTank(double fraction, double asymmetry) {
  const std::string text = R"(
[case]
name = "kicked_tank"
dimension = 2
[domain]
min = [-0.04, -0.04]
max = [0.24, 0.24]
[numerics]
particle_spacing = 0.01
dt_max = 5e-4
scheme = "stabilised"
collision_distance = 0.8
shift_limit = 1.0
pressure_source = "mixed"
source_relaxation = 0.01
source_relaxation_basis = "time"
surface_neighbour_fraction = )" + std::to_string(fraction) + R"(
surface_asymmetry = )" + std::to_string(asymmetry) + R"(
[output]
end_time = 1.0
[[region]]
name = "water"
material = "water"
min = [0.01, 0.0]
max = [0.2, 0.15]
[[region]]
name = "water_left"
material = "water"
min = [0.0, 0.01]
max = [0.01, 0.15]
[[region]]
name = "kick"
material = "water"
min = [0.0, 0.0]
max = [0.01, 0.01]
velocity = [-0.15, -0.23]
)" + test_support::tankWalls(0.2, 0.2, 0.04);
  const CaseConfig c = parseCase(text, "kicked_tank.toml");
  SimulationState<2> s;
  s.particles = buildParticles<2>(c);
  auto energy = [&] {
    double e = 0.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (s.particles.kind[i] == ParticleKind::Fluid) e += 0.5 * s.particles.velocity[i].squaredNorm();
    return e;
  };
  KickedTank r;
  r.kick = energy();
  MpsSolver<2> solver(c, s);
  while (s.time < 1.0 - 1e-12) {
    r.neighbour_surfaces += solver.step(1.0).neighbour_surfaces;
    if (s.time >= 0.1) r.largest = std::max(r.largest, energy());
  }
  return r;
}

}  // namespace

// A disturbance in still water must die away: once the kick's energy has spread into waves (0.1 s), the water's
// kinetic energy stays below what the kick put in (the potential energy of the still tank is the least, and the
// scheme adds no energy). Without the neighbour test, and with it at 0.7 or 0.8 (9 or 10 of 12 neighbours needed),
// the largest kinetic energy over 0.1-1 s is 0.41 of the kick's, the same to the bit. At 0.85 (11 of 12: an interior
// particle one of whose neighbours at 2 l0 drifts past re = 2.1 l0 becomes free surface, p = 0, among water at
// 1.4 kPa) it reaches 71 times the kick's. The waterfalls keep 0.85: on waterfall_small 0.7 moved the brink and the
// sheet away from their references (docs/waterfall.md, twenty-eighth session).
// At 0.7 the test makes no particle of the sloshing tank free surface (diagnostics.csv's neighbour_surfaces), nor
// does the asymmetry test at 0.15 of n0 (one missing neighbour at 2 l0 moves the sum by 0.008 n0).
TEST(SurfaceDetection, AKickedTankCalmsDownWithoutTheNeighbourCountAtElevenTwelfths) {
  const std::pair<double, double> tests[] = {{0.0, 0.0}, {0.7, 0.0}, {0.0, 0.15}};  // {fraction, asymmetry}
  for (const auto& [fraction, asymmetry] : tests) {
    SCOPED_TRACE(std::to_string(fraction) + ", asymmetry " + std::to_string(asymmetry));
    const KickedTank r = kickedTank(fraction, asymmetry);
    EXPECT_LT(r.largest, r.kick);
    EXPECT_EQ(0u, r.neighbour_surfaces);  // (at 0.85: 1,761 particle-solves in the 1 s)
  }
}
