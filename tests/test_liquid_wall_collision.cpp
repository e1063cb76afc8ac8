// numerics.liquid_collision_after_correction: the collision model once more after the liquid correction, for water
// approaching a wall or dummy particle (solver_collisions.cpp, collideCorrectedLiquid). The mirrored walls of the
// stabilised scheme hold each particle's own pressure, so nothing in the pressure pushes a particle back out of a
// corner, and the correction can leave it moving in (the 5 mm waterfall lost a particle so, docs/waterfall.md).
// Here: still water in a 10 x 10 cm tank, its bottom-left particle moved `inset` of the way from its lattice place
// (0.5 l0 from both faces) towards the corner of the faces, within the collision distance of the corner's wall
// particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "support/run_case.hpp"

using namespace mistfall;

namespace {

struct CornerRun {
  double closest = 1e9;  // the corner particle's least distance from either face over the run [l0]
  double final = 0.0;     // its distance at the end [l0]
  double pressure = 0.0;  // its pressure at the end [Pa]
  std::size_t reversals = 0;  // the key's reversals (diagnostics.csv's liquid_wall_collisions)
  std::size_t escaped = 0;
};

CornerRun runCorner(bool key, double inset, double end, bool thin_liquid = false) {
  const double l0 = 0.01;
  CaseConfig c = test_support::stillTankCase(l0, 0.1, 0.1);
  c.numerics.collision_distance = 0.8;
  c.numerics.liquid_collision_after_correction = key;
  c.numerics.thin_rows_hold_liquid = thin_liquid;
  SimulationState<2> state;
  state.particles = buildParticles<2>(c);
  auto& p = state.particles;
  std::size_t corner = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid && (p.position[i] - Vec<2>(0.5 * l0, 0.5 * l0)).norm() < 1e-9) corner = i;
  CornerRun run;
  if (corner == p.size()) {
    ADD_FAILURE() << "no fluid particle at the tank's corner place";
    return run;
  }
  const auto id = p.id[corner];
  p.position[corner] *= 1.0 - inset;
  MpsSolver<2> solver(c, state);
  while (state.time < end - 1e-12) {
    run.reversals += solver.step(end).liquid_wall_collisions;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] == id) {
        run.final = std::min(p.position[i][0], p.position[i][1]) / l0;
        run.pressure = p.pressure[i];
        run.closest = std::min(run.closest, run.final);
      }
  }
  run.escaped = p.count(ParticleKind::Escaped);
  return run;
}

}  // namespace

// Measured over 1 s (l0 = 1 cm, collision at 0.8 l0), the particle's least distance from a face and where it ends:
//   inset          0.2            0.4            0.6             0.8
//   without key    0.40 -> 0.47   0.25 -> 0.47   -1.11 -> -1.08  -1.10 -> -1.07  (into the wall, and it stays there)
//   with the key   0.40 -> 0.47   0.27 -> 0.42    0.06 -> 0.42    0.05 -> 0.32   (back towards its place, 0.5)
// Asserted with the key: never past a face, back to at least a quarter spacing from both at the end, nothing lost, the
// reversals counted.
TEST(LiquidWallCollision, CornerParticleIsNotSwallowedByTheWalls) {
  for (double inset : {0.6, 0.8}) {
    const CornerRun run = runCorner(true, inset, 1.0);
    std::printf("inset %.1f: the corner particle's least distance from a face %.3f l0, at the end %.3f l0; %zu "
                "reversals\n", inset, run.closest, run.final, run.reversals);
    EXPECT_GT(run.closest, 0.0) << "inset " << inset;
    EXPECT_GT(run.final, 0.25) << "inset " << inset;
    EXPECT_EQ(run.escaped, 0u) << "inset " << inset;
    EXPECT_GT(run.reversals, 0u) << "inset " << inset;  // the guard fired, and was counted
  }
}

// numerics.thin_row_pressure = "liquid" without the guard. The corner particle's liquid support falls below
// liquid_support_fraction as it nears the corner, so its row is made free surface; with the free surface's value
// (half a spacing of the last gradient: about 40 Pa here, 0.1 m under the surface) the water around pushes it into
// the walls. Holding its liquid neighbours' pressure continued hydrostatically (solver_liquid_stabilised.cpp), it
// stays out with no reversal. Measured over 1 s:
//   inset                       0.2            0.4            0.6             0.8
//   "surface" (the default)     0.40 -> 0.47   0.25 -> 0.47   -1.11 -> -1.08  -1.10 -> -1.07
//   "liquid"                    0.40 -> 0.47   0.29 -> 0.40    0.20 -> 0.44    0.10 -> 0.35
TEST(LiquidWallCollision, ThinRowHoldingTheLiquidsPressureKeepsACornerParticleOutWithoutTheGuard) {
  const double hydrostatic = 1000.0 * 9.81 * 0.1;  // at the tank's bottom, 0.1 m of water
  struct Row {
    bool thin_liquid;
    double inset;
  };
  for (const Row& row : {Row{false, 0.6}, Row{true, 0.6}, Row{true, 0.8}}) {
    const CornerRun run = runCorner(false, row.inset, 1.0, row.thin_liquid);
    std::printf("thin_row_pressure %s, inset %.1f: least distance %.3f l0, at the end %.3f l0, pressure %.0f Pa\n",
                row.thin_liquid ? "liquid" : "surface", row.inset, run.closest, run.final, run.pressure);
    EXPECT_EQ(run.reversals, 0u);
    EXPECT_EQ(run.escaped, 0u);
    if (!row.thin_liquid) {  // the mechanism the key mends: the particle goes into the walls
      EXPECT_LT(run.closest, 0.0) << "inset " << row.inset;
      continue;
    }
    EXPECT_GT(run.closest, 0.05) << "inset " << row.inset;
    EXPECT_GT(run.final, 0.25) << "inset " << row.inset;
    EXPECT_NEAR(run.pressure, hydrostatic, 0.1 * hydrostatic) << "inset " << row.inset;
  }
}
