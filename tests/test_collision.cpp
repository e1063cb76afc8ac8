// The collision model (mps/collision.hpp) and its wall limit (numerics.collision_wall_limit).
#include <gtest/gtest.h>

#include <vector>

#include "mps/collision.hpp"
#include "mps/neighbour_search.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01, kDt = 5e-4;
constexpr double kWater = 1000.0 * kL0 * kL0, kAir = 1.2 * kL0 * kL0;  // masses of a 2D particle

// A wall column at x = 0 (wall particles at y = -3..3 l0, index 1...) and a fluid particle (index 0) at `at` (in l0),
// with velocity `u`; optionally a water particle (the last index) at `water_at` with `water_u`.
struct Scene {
  std::vector<Vec<2>> position, velocity;
  std::vector<ParticleKind> kind;
  std::vector<double> mass;
  NeighbourList nl;
  Scene(Vec<2> at, Vec<2> u, double m) {
    add(at * kL0, u, ParticleKind::Fluid, m);
    for (int k = -3; k <= 3; ++k) add(Vec<2>(0.0, k * kL0), Vec<2>::Zero(), ParticleKind::Wall, kWater);
  }
  void addWater(Vec<2> at, Vec<2> u) { add(at * kL0, u, ParticleKind::Fluid, kWater); }
  CollisionCount collide(bool wall_limit) {
    NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
    search.build(position, kind, nl);
    return resolveCollisions<2>(position, velocity, kind, mass, nl, CollisionModel{0.8 * kL0, 0.2, wall_limit}, kDt);
  }
  // The fastest approach of particle 0 to a wall particle within the collision distance (0 when none approaches).
  double wallApproach() const {
    double fastest = 0.0;
    for (std::size_t j = 0; j < position.size(); ++j) {
      const Vec<2> r = position[j] - position[0];
      if (kind[j] == ParticleKind::Wall && r.norm() < 0.8 * kL0)
        fastest = std::max(fastest, velocity[0].dot(r.normalized()));
    }
    return fastest;
  }

 private:
  void add(Vec<2> x, Vec<2> u, ParticleKind k, double m) {
    position.push_back(x), velocity.push_back(u), kind.push_back(k), mass.push_back(m);
  }
};

// The traced loss of waterfall_small (docs/waterfall.md): air 0.6 l0 left of the wall, leaving it at 0.85 m/s, and a
// water particle 0.7 l0 further left approaching it at 1.66 m/s.
Scene squeezedAir() {
  Scene s(Vec<2>(-0.6, 0.0), Vec<2>(-0.85, 0.0), kAir);
  s.addWater(Vec<2>(-1.3, 0.0), Vec<2>(1.66, 0.0));
  return s;
}

}  // namespace

// Jacobi-style, the pair with the wall is judged on the old velocity, which leaves it: the water's reversal alone sends
// the air into the wall at (1 + e) * 2.51 m/s - 0.85 m/s = 2.16 m/s (the flaw the limit removes).
TEST(Collision, WithoutTheWallLimitAirBetweenWaterAndAWallIsSentIntoTheWall) {
  Scene s = squeezedAir();
  const CollisionCount count = s.collide(false);
  EXPECT_EQ(2u, count.reversals);  // the pair's two sides: (air, water) and (water, air)
  EXPECT_EQ(0u, count.wall_limits);
  EXPECT_NEAR(-0.85 + 1.2 * 2.51 * kWater / (kWater + kAir), s.velocity[0].x(), 1e-12);
  EXPECT_GT(s.wallApproach(), 2.0);
}

TEST(Collision, TheWallLimitKeepsTheWatersReversalFromDrivingAirIntoTheWall) {
  Scene s = squeezedAir();
  const Vec<2> start = s.position[0];
  const CollisionCount count = s.collide(true);
  EXPECT_EQ(2u, count.reversals);
  EXPECT_EQ(1u, count.wall_limits);
  EXPECT_LE(s.wallApproach(), 1e-12);  // no approach to a wall particle within the distance
  EXPECT_NEAR(0.0, s.velocity[0].x(), 1e-12);  // stopped against the wall it faces head-on
  EXPECT_NEAR(0.0, s.velocity[0].y(), 1e-12);
  EXPECT_NEAR(start.x(), s.position[0].x(), 1e-15 + kDt * 0.85);  // moved with the whole change, no further
  // The water, 1.3 l0 from the wall, is outside every wall pair: the pass leaves it as it was (air barely pushes it).
  EXPECT_NEAR(1.66, s.velocity.back().x(), 1.66 * 2.0 * kAir / kWater);
}

// Where the pass changes a velocity without creating an approach to a wall, the limit changes nothing.
TEST(Collision, TheWallLimitLeavesEveryOtherReversalAsItWas) {
  struct Case {
    const char* what;
    Vec<2> at, u;  // in l0, m/s
    bool water;
  };
  const Case cases[] = {
      {"water hitting the wall head-on: reversed with e", {-0.6, 0.0}, {1.0, 0.0}, false},
      {"water hitting the wall slanting: reversed with e", {-0.6, 0.3}, {1.0, -0.5}, false},
      {"water moving along the wall: nothing to reverse", {-0.6, 0.5}, {0.0, 1.0}, false},
      {"two water particles away from the wall", {-3.0, 0.0}, {1.0, 0.0}, true},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    Scene with(c.at, c.u, kWater), without(c.at, c.u, kWater);
    if (c.water) with.addWater(c.at + Vec<2>(0.6, 0.0), Vec<2>::Zero()), without.addWater(c.at + Vec<2>(0.6, 0.0), Vec<2>::Zero());
    const CollisionCount a = with.collide(true), b = without.collide(false);
    EXPECT_EQ(b.reversals, a.reversals);
    EXPECT_EQ(0u, a.wall_limits);
    for (std::size_t i = 0; i < with.position.size(); ++i) {
      EXPECT_EQ(without.velocity[i], with.velocity[i]);
      EXPECT_EQ(without.position[i], with.position[i]);
    }
  }
}

// numerics.collision_passes: an air particle (i) between water approaching it from the left at 2 m/s and air at rest
// 0.6 l0 to its right (the traced loss of waterfall_small in its twenty-ninth session, docs/waterfall.md). One Jacobi
// pass reverses i off the water, straight at the air on its right, which that pass did not see approaching (2.4
// m/s, e = 0.2); the second reverses that approach (and sends i back towards the water at 1.04 m/s); the passes
// settle with the three moving together at the water's speed, no pair approaching, in nine passes that reverse
// two pairs each and a tenth that reverses none.
TEST(Collision, FurtherPassesReverseTheApproachesTheFirstMade) {
  for (int passes : {1, 2, 10}) {
    SCOPED_TRACE(passes);
    Scene s(Vec<2>(5.0, 0.0), Vec<2>::Zero(), kAir);  // i: index 0, far from the wall column at x = 0
    s.addWater(Vec<2>(4.3, 0.0), Vec<2>(2.0, 0.0));    // the water approaching i
    const std::size_t water = s.position.size() - 1;
    s.addWater(Vec<2>(5.6, 0.0), Vec<2>::Zero());      // the air on i's right (its mass set below)
    const std::size_t air = s.position.size() - 1;
    s.mass[air] = kAir;
    NeighbourSearch<2> search(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), 2.1 * kL0);
    search.build(s.position, s.kind, s.nl);
    const CollisionCount count =
        resolveCollisionPasses<2>(passes, s.position, s.velocity, s.kind, s.mass, s.nl,
                                  CollisionModel{0.8 * kL0, 0.2, false}, kDt, [](std::int64_t, std::int32_t) {
                                    return true;
                                  });
    auto approach = [&](std::size_t j) {  // i's approach to j (> 0: closing) while within the distance
      const Vec<2> r = s.position[j] - s.position[0];
      return r.norm() < 0.8 * kL0 ? (s.velocity[0] - s.velocity[j]).dot(r.normalized()) : 0.0;
    };
    if (passes == 1) EXPECT_GT(approach(air), 2.0);
    if (passes == 2) EXPECT_LT(approach(air), 0.0);
    if (passes == 10) {
      EXPECT_LT(approach(air), 1e-3);
      EXPECT_LT(approach(water), 1e-3);
      EXPECT_EQ(18u, count.reversals);
    }
  }
}
