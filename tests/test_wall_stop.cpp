// A position-only displacement stopped at the walls (mps/wall_stop.hpp, numerics.shift_wall_stop).
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/wall_stop.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01, kStop = 0.8 * kL0;

// A floor of wall particles at y = 0 (x = -4..4 l0), a water particle a spacing above it at x = 0 (index 0), and a
// second water particle at (0, 0.5 l0) when `water_below` (between it and the floor).
struct Floor {
  std::vector<Vec<2>> position;
  std::vector<ParticleKind> kind;
  NeighborList nl;
  explicit Floor(bool water_below = false) {
    position.push_back(Vec<2>(0.0, kL0)), kind.push_back(ParticleKind::Fluid);
    if (water_below) position.push_back(Vec<2>(0.0, 0.5 * kL0)), kind.push_back(ParticleKind::Fluid);
    for (int k = -4; k <= 4; ++k) position.push_back(Vec<2>(k * kL0, 0.0)), kind.push_back(ParticleKind::Wall);
    NeighborSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
    search.build(position, kind, nl);
  }
  auto fixed() const {
    return [this](std::int32_t j) { return kind[j] == ParticleKind::Wall; };
  }
  double nearestWall(const Vec<2>& at) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < position.size(); ++j)
      if (kind[j] == ParticleKind::Wall) nearest = std::min(nearest, (position[j] - at).norm());
    return nearest;
  }
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

// Only fixed particles stop a displacement: the re-spacing between fluid particles is the stage's purpose (stopping
// it against the water as well lost 15 and 2 particles on waterfall_small).
TEST(WallStop, WaterInTheWayDoesNotStopADisplacement) {
  const Floor floor(/*water_below=*/true);
  Vec<2> d(0.0, -0.15 * kL0);  // towards the water 0.5 l0 below, to 0.85 l0 above the floor
  EXPECT_FALSE(stopDisplacementAtWalls<2>(0, floor.position, floor.nl, kStop, floor.fixed(), d));
  EXPECT_DOUBLE_EQ(-0.15 * kL0, d.y());
  Vec<2> onto(0.0, -0.3 * kL0);  // to 0.7 l0 above the floor: the floor stops it, not the water
  EXPECT_TRUE(stopDisplacementAtWalls<2>(0, floor.position, floor.nl, kStop, floor.fixed(), onto));
  EXPECT_NEAR(0.0, onto.y(), 1e-15);
}
