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

// A move longer than one spacing reads the walls along its path (slideAlongWallsOnPath, WallCells): a floor of three
// wall rows at y = 0, -1, -2 l0 (x = -20..20 l0), the particle at (0, 3.6 l0).
namespace {

struct ThickFloor {
  std::vector<Vec<2>> position{Vec<2>(0.0, 3.6 * kL0)};
  std::vector<ParticleKind> kind{ParticleKind::Fluid};
  ThickFloor() {
    for (int row = 0; row < 3; ++row)
      for (int k = -20; k <= 20; ++k) position.push_back(Vec<2>(k * kL0, -row * kL0)), kind.push_back(ParticleKind::Wall);
  }
  WallCells<2> cells() const {
    return WallCells<2>(position, [this](std::int32_t j) { return kind[j] == ParticleKind::Wall; }, kRe);
  }
};

struct PathCase {
  const char* what;
  Vec<2> displacement;  // in l0
  bool slid;
  double lowest;        // the end's height above the floor's top row at least, in l0
};

}  // namespace

TEST(WallSlip, ALongMoveSlidesAlongTheWallsOfItsWholePath) {
  const ThickFloor floor;
  const WallCells<2> walls = floor.cells();
  const PathCase cases[] = {
      // the traced re-spacing of the 5 mm waterfall: 10.8 l0 from 3.6 l0 above the floor, which is beyond re of the start
      {"the traced jump into the floor stops above it", {7.9, -7.3}, true, 1.0},
      {"straight down 6 l0: stops above the floor", {0.0, -6.0}, true, 1.0},
      {"along the floor 8 l0: kept", {8.0, 0.0}, false, 3.6},
      {"up and away 5 l0: kept", {1.0, 5.0}, false, 3.6},
      {"one spacing down: left to the slide at its start", {0.0, -1.0}, false, 2.6},
  };
  Vec<2> diverged(0.0, -1e7 * kL0);  // beyond max_pieces: left as it is, not walked
  EXPECT_FALSE(slideAlongWallsOnPath<2>(floor.position[0], walls, kL0, diverged));
  EXPECT_EQ(Vec<2>(0.0, -1e7 * kL0), diverged);
  for (const PathCase& c : cases) {
    SCOPED_TRACE(c.what);
    const Vec<2> before = c.displacement * kL0;
    Vec<2> d = before;
    EXPECT_EQ(c.slid, slideAlongWallsOnPath<2>(floor.position[0], walls, kL0, d));
    EXPECT_GE(floor.position[0].y() + d.y(), c.lowest * kL0 - 1e-12);
    if (!c.slid) EXPECT_EQ(before, d);  // to the bit
    // Only the part into the walls is taken off: the part along the floor is kept, but for the lattice's tilt of the
    // walls' first moment off the floor's normal between its particles.
    EXPECT_NEAR(before.x(), d.x(), 0.1 * kL0);
  }
}

// The binned walls give the first moment of the neighbour list's walls (the slide at the start reads those), and none
// away from every wall.
TEST(WallSlip, BinnedWallsGiveTheListsFirstMoment) {
  const ThickFloor floor;
  const WallCells<2> walls = floor.cells();
  for (double height : {0.5, 1.0, 1.7, 2.05}) {
    std::vector<Vec<2>> position = floor.position;
    position[0] = Vec<2>(0.3 * kL0, height * kL0);
    NeighbourList nl;
    NeighbourSearch<2> search(Vec<2>(-0.3, -0.1), Vec<2>(0.3, 0.1), kRe);
    search.build(position, floor.kind, nl);
    const Vec<2> listed = neighbourhoodFirstMoment<2>(0, position, nl, kRe,
                                                      [&](std::int32_t j) { return floor.kind[j] == ParticleKind::Wall; });
    const Vec<2> binned = walls.firstMoment(position[0]);
    EXPECT_GT(listed.norm(), 0.0);
    EXPECT_NEAR(0.0, (binned - listed).norm(), 1e-9 * listed.norm());
  }
  EXPECT_EQ(Vec<2>::Zero(), walls.firstMoment(Vec<2>(0.0, 2.2 * kL0)));
  EXPECT_EQ(Vec<2>::Zero(), walls.firstMoment(Vec<2>(5.0, 5.0)));
}
