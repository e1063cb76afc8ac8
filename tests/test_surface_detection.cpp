// Free-surface detection (numerics.surface_threshold and surface_neighbour_fraction): a clump of a splash has a
// high number density but few neighbours; with the neighbour-count test it is a free surface (p = 0) instead of a
// pressure island that throws its neighbours apart.
#include <gtest/gtest.h>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/number_density.hpp"
#include "mps/solver.hpp"

using namespace mistfall;

namespace {

// Six water particles (a 3 x 2 block at l0 = 1 cm) in free fall, no walls.
std::string clumpCase(double fraction) {
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
double maxPressureAfterOneStep(double fraction) {
  const CaseConfig c = parseCase(clumpCase(fraction), "clump.toml");
  SimulationState<2> s;
  s.particles = buildParticles<2>(c);
  EXPECT_EQ(6u, s.particles.size());
  const double side = 0.0055;
  for (std::size_t i = 0; i < 6; ++i)
    s.particles.position[i] = Vec<2>(i < 4 ? (i / 2) * side : side + 0.0145, (i % 2) * side);
  MpsSolver<2> solver(c, s);
  solver.step(1.0);
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
  NeighborSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 0.021);
  NeighborList nl;
  search.build(p.position, p.kind, nl);
  const std::size_t centre = 4 * 9 + 4;
  auto all = [](std::int32_t) { return true; };
  EXPECT_EQ(12, neighbourCountAt<2>(centre, p.position, nl, 0.021, all));
  EXPECT_EQ(0, neighbourCountAt<2>(centre, p.position, nl, 0.021, [](std::int32_t) { return false; }));
  EXPECT_EQ(5, neighbourCountAt<2>(0, p.position, nl, 0.021, all));  // a corner: (1,0),(2,0),(0,1),(1,1),(0,2)
}

TEST(SurfaceDetection, SplashClumpIsAFreeSurfaceWithTheNeighbourTest) {
  EXPECT_GT(maxPressureAfterOneStep(0.0), 100.0);  // number density alone: a pressure island
  EXPECT_EQ(0.0, maxPressureAfterOneStep(0.85));   // with the neighbour count: free surface, p = 0
}
