// The gas system's re-spacing of a bubble's gas slid along the walls (mps/wall_slip.hpp, numerics.respacing_walls =
// "slip"): the no-penetration condition of a solid wall on a position-only displacement.
#include <gtest/gtest.h>

#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/wall_slip.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01, kRe = 2.1 * kL0;

// A floor of wall particles at y = 0 (x = -6..6 l0), water beside it at y = 2 l0 (x = -2, 2 l0), and the moving
// particle (index 0) at (0, height l0).
struct Floor {
  std::vector<Vec<2>> position;
  std::vector<ParticleKind> kind;
  NeighbourList nl;
  explicit Floor(double height) {
    position.push_back(Vec<2>(0.0, height * kL0)), kind.push_back(ParticleKind::Fluid);
    for (int k : {-2, 2}) position.push_back(Vec<2>(k * kL0, 2.0 * kL0)), kind.push_back(ParticleKind::Fluid);
    for (int k = -6; k <= 6; ++k) position.push_back(Vec<2>(k * kL0, 0.0)), kind.push_back(ParticleKind::Wall);
    NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), kRe);
    search.build(position, kind, nl);
  }
  auto fixed() const {
    return [this](std::int32_t j) { return kind[j] == ParticleKind::Wall; };
  }
};

struct Case {
  const char* what;
  double height;         // of the particle above the floor's wall row, in l0
  Vec<2> displacement;   // in l0
  bool slid;
  Vec<2> kept;           // in l0
};

}  // namespace

TEST(WallSlip, ARespacingKeepsItsPartAlongTheFloorAndLosesItsPartIntoIt) {
  const Case cases[] = {
      {"straight down: all of it is into the floor", 1.0, {0.0, -0.5}, true, {0.0, 0.0}},
      {"slanting down: the part along the floor is kept", 1.0, {0.4, -0.5}, true, {0.4, 0.0}},
      {"the traced jump, 1.9 l0 along and into the floor: it slides", 0.85, {1.8, -0.6}, true, {1.8, 0.0}},
      {"a small step down far from the collision distance: slid all the same", 2.0, {0.0, -0.01}, true, {0.0, 0.0}},
      {"along the floor: kept", 1.0, {0.5, 0.0}, false, {0.5, 0.0}},
      {"up, away from the floor: kept", 1.0, {0.3, 0.5}, false, {0.3, 0.5}},
      {"no wall within re: kept", 2.2, {0.0, -0.5}, false, {0.0, -0.5}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const Floor floor(c.height);
    Vec<2> d = c.displacement * kL0;
    EXPECT_EQ(c.slid, slideDisplacementAlongWalls<2>(0, floor.position, floor.nl, kRe, floor.fixed(), d));
    EXPECT_NEAR(c.kept.x() * kL0, d.x(), 1e-15);
    EXPECT_NEAR(c.kept.y() * kL0, d.y(), 1e-15);
    // Near the floor, the slid particle is no nearer it than it was.
    if (c.height < 2.1) EXPECT_GE(floor.position[0].y() + d.y(), floor.position[0].y() - 1e-15);
  }
}

// In a corner (a floor at y = 0 and a wall at x = 0, the particle at (l0, l0)) the normal is the mean of the two:
// a move straight into the corner is taken off whole, a move along either wall keeps its part away from the other.
TEST(WallSlip, InACornerAMoveIntoTheCornerIsTakenOff) {
  std::vector<Vec<2>> position{Vec<2>(kL0, kL0)};
  std::vector<ParticleKind> kind{ParticleKind::Fluid};
  for (int k = 0; k <= 6; ++k) {
    position.push_back(Vec<2>(k * kL0, 0.0)), kind.push_back(ParticleKind::Wall);
    if (k > 0) position.push_back(Vec<2>(0.0, k * kL0)), kind.push_back(ParticleKind::Wall);
  }
  NeighbourList nl;
  NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), kRe);
  search.build(position, kind, nl);
  auto fixed = [&](std::int32_t j) { return kind[j] == ParticleKind::Wall; };
  Vec<2> into(-0.3 * kL0, -0.3 * kL0);
  EXPECT_TRUE(slideDisplacementAlongWalls<2>(0, position, nl, kRe, fixed, into));
  EXPECT_NEAR(0.0, into.norm(), 1e-15);
  Vec<2> out(0.3 * kL0, 0.2 * kL0);
  EXPECT_FALSE(slideDisplacementAlongWalls<2>(0, position, nl, kRe, fixed, out));
}
