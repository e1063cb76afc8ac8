// A position-only displacement stopped at the walls (mps/wall_stop.hpp, numerics.shift_wall_stop), and a bubble's gas
// stopped at a floor as it follows the water (mps/bubble_gas_motion.hpp, numerics.bubble_gas_wall_stop).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mps/bubble_gas_motion.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/wall_stop.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01, kStop = 0.8 * kL0;

// The distance from `at` to the nearest wall particle.
double nearestWallTo(const std::vector<Vec<2>>& position, const std::vector<ParticleKind>& kind, const Vec<2>& at) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < position.size(); ++j)
    if (kind[j] == ParticleKind::Wall) nearest = std::min(nearest, (position[j] - at).norm());
  return nearest;
}

// A floor of wall particles at y = 0 (x = -4..4 l0), a water particle a spacing above it at x = 0 (index 0), and a
// second water particle at (0, 0.5 l0) when `water_below` (between it and the floor).
struct Floor {
  std::vector<Vec<2>> position;
  std::vector<ParticleKind> kind;
  NeighbourList nl;
  explicit Floor(bool water_below = false) {
    position.push_back(Vec<2>(0.0, kL0)), kind.push_back(ParticleKind::Fluid);
    if (water_below) position.push_back(Vec<2>(0.0, 0.5 * kL0)), kind.push_back(ParticleKind::Fluid);
    for (int k = -4; k <= 4; ++k) position.push_back(Vec<2>(k * kL0, 0.0)), kind.push_back(ParticleKind::Wall);
    NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
    search.build(position, kind, nl);
  }
  auto fixed() const {
    return [this](std::int32_t j) { return kind[j] == ParticleKind::Wall; };
  }
  double nearestWall(const Vec<2>& at) const { return nearestWallTo(position, kind, at); }
};

struct Case {
  const char* what;
  Vec<2> displacement;  // in l0
  bool stopped;
  Vec<2> kept;  // in l0
};

}  // namespace

TEST(WallStop, ADisplacementKeepsWhatDoesNotApproachAWallWithinTheCollisionDistance) {
  const Case cases[] = {
      {"down, to 0.5 l0 from the floor: its approach is taken off", {0.0, -0.5}, true, {0.0, 0.0}},
      {"down, to 0.9 l0: outside the collision distance, kept", {0.0, -0.1}, false, {0.0, -0.1}},
      {"along the floor: kept", {0.5, 0.0}, false, {0.5, 0.0}},
      {"up: kept", {0.0, 0.5}, false, {0.0, 0.5}},
      {"slanting down to 0.64 l0: the part along the floor is kept", {0.4, -0.5}, true, {0.4, 0.0}},
      {"a shift of a spacing onto the floor (the 7 mm loss)", {0.0, -0.91}, true, {0.0, 0.0}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const Floor floor;
    Vec<2> d = c.displacement * kL0;
    EXPECT_EQ(c.stopped, stopDisplacementAtWalls<2>(0, floor.position, floor.nl, kStop, floor.fixed(), d));
    EXPECT_NEAR(c.kept.x() * kL0, d.x(), 1e-15);
    EXPECT_NEAR(c.kept.y() * kL0, d.y(), 1e-15);
    // Displaced by what is kept, the particle is no nearer a wall than the collision distance.
    EXPECT_GE(floor.nearestWall(floor.position[0] + d), kStop - 1e-15);
  }
}

// Only the particles the caller names stop a displacement: with the walls alone, water in the way does not (the
// re-spacing between fluid particles is the stage's purpose; stopping it against the water as well lost 15 and 2
// particles on waterfall_small in the twenty-fifth session, before the stabilised scheme; since the forty-ninth
// numerics.respacing_stop names the water, or every fluid particle, too: below).
TEST(WallStop, WaterInTheWayDoesNotStopADisplacement) {
  const Floor floor(/*water_below=*/true);
  Vec<2> d(0.0, -0.15 * kL0);  // towards the water 0.5 l0 below, to 0.85 l0 above the floor
  EXPECT_FALSE(stopDisplacementAtWalls<2>(0, floor.position, floor.nl, kStop, floor.fixed(), d));
  EXPECT_DOUBLE_EQ(-0.15 * kL0, d.y());
  Vec<2> onto(0.0, -0.3 * kL0);  // to 0.7 l0 above the floor: the floor stops it, not the water
  EXPECT_TRUE(stopDisplacementAtWalls<2>(0, floor.position, floor.nl, kStop, floor.fixed(), onto));
  EXPECT_NEAR(0.0, onto.y(), 1e-15);
}

// numerics.respacing_stop = "water": a bubble's gas re-spaced towards the water around the bubble, the water named as
// the walls (solver_gas.cpp); "fluid" names the bubble's own gas as well. A bubble of the nine lattice points within 1.5 l0 of the origin (gas) in water on the lattice
// to 5 l0; the moving particle is the gas at the bubble's right edge, (1, 0) l0.
TEST(WallStop, ABubblesGasReSpacedOntoTheWaterAroundItStopsAtTheCollisionDistance) {
  std::vector<Vec<2>> position{Vec<2>(kL0, 0.0)};
  std::vector<ParticleKind> kind{ParticleKind::Fluid};
  std::vector<Phase> phase{Phase::Gas};
  for (int a = -5; a <= 5; ++a)
    for (int b = -5; b <= 5; ++b) {
      if ((a == 1 && b == 0) || a * a + b * b > 25) continue;
      position.push_back(Vec<2>(a * kL0, b * kL0)), kind.push_back(ParticleKind::Fluid);
      phase.push_back(a * a + b * b <= 2 ? Phase::Gas : Phase::Liquid);
    }
  NeighbourList nl;
  NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
  search.build(position, kind, nl);
  auto water = [&](std::int32_t j) { return kind[j] == ParticleKind::Fluid && phase[j] == Phase::Liquid; };
  auto nearestWater = [&](const Vec<2>& at) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < position.size(); ++j)
      if (water(static_cast<std::int32_t>(j))) nearest = std::min(nearest, (position[j] - at).norm());
    return nearest;
  };
  const Case cases[] = {
      {"the traced re-spacing, 1.4 l0 onto the water particle at (2, -1): taken off whole", {1.0, -1.0}, true,
       {0.0, 0.0}},
      {"to 0.5 l0 from the water at (2, 0): its approach is taken off", {0.5, 0.0}, true, {0.0, 0.0}},
      {"to 0.85 l0 from it: outside the collision distance, kept", {0.15, 0.0}, false, {0.15, 0.0}},
      {"along the interface: kept", {0.0, 0.3}, false, {0.0, 0.3}},
      {"back into the bubble, onto its own gas: kept (the gas is not the water)", {-0.9, 0.0}, false, {-0.9, 0.0}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    Vec<2> d = c.displacement * kL0;
    EXPECT_EQ(c.stopped, stopDisplacementAtWalls<2>(0, position, nl, kStop, water, d));
    EXPECT_NEAR(c.kept.x() * kL0, d.x(), 1e-15);
    EXPECT_NEAR(c.kept.y() * kL0, d.y(), 1e-15);
    EXPECT_GE(nearestWater(position[0] + d), kStop - 1e-15);
  }
  // With every fluid particle named ("fluid"), the move onto its own gas at (0, 0) is stopped too.
  auto fluid = [&](std::int32_t j) { return kind[j] == ParticleKind::Fluid; };
  Vec<2> onto_gas(-0.9 * kL0, 0.0);
  EXPECT_TRUE(stopDisplacementAtWalls<2>(0, position, nl, kStop, fluid, onto_gas));
  EXPECT_NEAR(0.0, onto_gas.norm(), 1e-15);
}

namespace {

// Water over a floor: two wall rows at y = 0 and -l0 (x = -6..6 l0), water on the lattice above them up to y = 5 l0,
// all moving down at 1 m/s, but for a bubble's gas (enclosed, at rest) in the three lattice points of the first row
// above the floor at x = -l0, 0, l0. The water's velocity extended into the bubble carries the gas towards the floor.
struct BubbleOnAFloor {
  Particles<2> p;
  CouplingRoles roles;
  NeighbourList nl;
  std::vector<std::size_t> gas;
  BubbleOnAFloor() {
    for (int iy = -1; iy <= 5; ++iy)
      for (int ix = -6; ix <= 6; ++ix) {
        const Vec<2> x(ix * kL0, iy * kL0);
        if (iy <= 0) {
          p.add(x, Vec<2>::Zero(), ParticleKind::Wall, Phase::Liquid);
        } else if (iy == 1 && std::abs(ix) <= 1) {
          gas.push_back(p.size());
          p.add(x, Vec<2>::Zero(), ParticleKind::Fluid, Phase::Gas);
        } else {
          p.add(x, Vec<2>(0.0, -1.0), ParticleKind::Fluid, Phase::Liquid);
        }
      }
    const std::size_t n = p.size();
    roles.open_gas.assign(n, 0);
    roles.gas_side_wall.assign(n, 0);
    roles.in_liquid_system.assign(n, 1);
    roles.enclosed_gas.assign(n, 0);
    for (auto i : gas) roles.enclosed_gas[i] = 1;
    roles.enclosed_count = roles.gas_count = gas.size();
    NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
    search.build(p.position, p.kind, nl);
  }
  double nearestWall(std::size_t i) const { return nearestWallTo(p.position, p.kind, p.position[i]); }
};

}  // namespace

// numerics.bubble_gas_wall_stop (a guard, counted): the bubble's gas has no pressure force of its own, so without the
// key the water's velocity extended into it carries it into the floor's collision distance (traced on the 5 mm
// waterfall: to 0.25 l0 from the first wall row); with it, the gas stops at the distance, its velocity matches its
// move, and it keeps its motion along the floor.
TEST(WallStop, ABubblesGasFollowingTheWaterStopsAtTheFloor) {
  constexpr double kDt = 5e-3;  // the extension gives the gas 0.54-0.59 m/s downwards (measured): 0.27-0.30 l0 a step
  const BubbleOnAFloor at_start;
  BubbleOnAFloor free_gas, stopped_gas;
  EXPECT_EQ(0u, extendVelocityIntoBubbles<2>(free_gas.p, free_gas.nl, free_gas.roles, 2.1 * kL0, kDt));
  const std::size_t stops = extendVelocityIntoBubbles<2>(stopped_gas.p, stopped_gas.nl, stopped_gas.roles,
                                                         2.1 * kL0, kDt, nullptr, nullptr, kStop);
  for (std::size_t k = 0; k < free_gas.gas.size(); ++k) {
    SCOPED_TRACE(k);
    const std::size_t i = free_gas.gas[k];
    // Without the stop the gas moves down by more than the 0.2 l0 that the collision distance leaves it.
    EXPECT_LT(free_gas.p.position[i].y() - at_start.p.position[i].y(), -0.2 * kL0);
    EXPECT_LT(free_gas.nearestWall(i), kStop - 0.01 * kL0);
    // With it, it is no nearer a wall particle than the distance, and its velocity carries its move.
    EXPECT_GE(stopped_gas.nearestWall(i), kStop - 1e-12);
    const Vec<2> move = stopped_gas.p.position[i] - at_start.p.position[i];
    EXPECT_NEAR(move.x(), kDt * stopped_gas.p.velocity[i].x(), 1e-15);
    EXPECT_NEAR(move.y(), kDt * stopped_gas.p.velocity[i].y(), 1e-15);
    // The part of the move along the floor is the free gas's.
    EXPECT_NEAR(free_gas.p.position[i].x(), stopped_gas.p.position[i].x(), 1e-3 * kL0);
  }
  EXPECT_EQ(free_gas.gas.size(), stops);
}
