// Source shedding and shrinking, eq. (20) as volume bookkeeping (texture/source_shedding.hpp): at every step the
// volume shed by representatives plus the volume the sources still hold (plus what spent or surfaced sources
// took with them) equals the sources' initial volume; a source disappears when spent; a bubble source
// disappears when it reaches the water surface; a droplet born inside the water's footprint on the grid is kept
// for the birth grace unless it has reached the air, after which entering the water absorbs it at once.
#include <gtest/gtest.h>

#include <cmath>

#include "texture/texture_cloud.hpp"

using namespace mistfall;

namespace {

// Water below y = 0, air above, both still.
class PoolFlow final : public FlowField {
 public:
  FlowSample sample(bool, const Vec3& x, double) const override {
    FlowSample s;
    s.liquid_fraction = x[1] < 0.0 ? 1.0 : 0.0;
    return s;
  }
};

double heldVolume(const TextureCloud& c) {
  double v = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (isSource(c.kind[i])) v += c.sourceVolume(i);
  return v;
}

TextureParameters params() {
  TextureParameters p;
  p.source_diameter = 0.005;
  return p;
}

}  // namespace

TEST(TextureShedding, VolumeIsConservedAndSpentSourceDisappears) {
  TextureCloud cloud(params());
  const PoolFlow flow;
  cloud.addSource(TextureKind::Droplet, Vec3(0.0, 10.0, 0.0), Vec3::Zero(), 0.0);  // high in the air
  const double v0 = sphereVolume(0.005);
  const double dt = 1e-3;
  double previous_diameter = 0.005;
  for (int s = 0; s < 600; ++s) {
    cloud.step(flow, s * dt, dt);
    const TextureTally& t = cloud.tally();
    EXPECT_NEAR(t.shed_volume + heldVolume(cloud) + t.residual_volume, v0, 1e-12 * v0) << "step " << s;
    if (cloud.size() && cloud.kind[0] == TextureKind::Droplet) {
      EXPECT_LE(cloud.diameter[0], previous_diameter);  // shrinks as it sheds
      EXPECT_NEAR(sphereVolume(cloud.diameter[0]), cloud.sourceVolume(0), 1e-12 * v0);
      previous_diameter = cloud.diameter[0];
    }
  }
  // Lifetime 0.5 s: all 500 representatives shed, each of 250 real 0.075 mm droplets; the source is gone.
  const auto counts = cloud.counts();
  EXPECT_EQ(counts[static_cast<int>(TextureKind::Droplet)], 0);
  EXPECT_EQ(counts[static_cast<int>(TextureKind::Mist)], 500);
  EXPECT_EQ(cloud.tally().spent, 1);
  EXPECT_NEAR(cloud.tally().shed_volume, 500 * 250 * sphereVolume(7.5e-5), 1e-12 * v0);
  EXPECT_NEAR(cloud.tally().residual_volume, v0 - cloud.tally().shed_volume, 1e-12 * v0);
}

TEST(TextureShedding, SourceRunsOutOfVolumeBeforeItsCount) {
  TextureParameters p = params();
  p.shedding.representatives_per_source = 100000;  // more than the volume allows
  p.shedding.source_lifetime = 0.1;
  TextureCloud cloud(p);
  const PoolFlow flow;
  cloud.addSource(TextureKind::Droplet, Vec3(0.0, 10.0, 0.0), Vec3::Zero(), 0.0);
  const double v0 = sphereVolume(0.005);
  const auto expected = static_cast<std::int64_t>(std::floor(v0 / representativeVolume(p.shedding)));
  for (int s = 0; s < 200; ++s) cloud.step(flow, s * 1e-3, 1e-3);
  EXPECT_EQ(cloud.counts()[static_cast<int>(TextureKind::Mist)], expected);
  EXPECT_EQ(cloud.tally().spent, 1);
  EXPECT_LT(cloud.tally().residual_volume, representativeVolume(p.shedding));
  EXPECT_NEAR(cloud.tally().shed_volume + cloud.tally().residual_volume, v0, 1e-12 * v0);
}

TEST(TextureShedding, BubbleSourceDisappearsAtTheWaterSurface) {
  TextureCloud cloud(params());
  const PoolFlow flow;
  cloud.addSource(TextureKind::Bubble, Vec3(0.0, -0.002, 0.0), Vec3::Zero(), 0.0);
  const double v0 = sphereVolume(0.005);
  int surfaced_at = -1;
  for (int s = 0; s < 200 && surfaced_at < 0; ++s) {
    cloud.step(flow, s * 1e-3, 1e-3);
    if (cloud.counts()[static_cast<int>(TextureKind::Bubble)] == 0) surfaced_at = s;
  }
  ASSERT_GE(surfaced_at, 0) << "the bubble never reached the surface";
  // The source, and any micro-bubble it shed in the step it crossed the surface, count as surfaced.
  EXPECT_GE(cloud.tally().surfaced, 1);
  EXPECT_EQ(cloud.tally().spent, 0);
  EXPECT_GT(cloud.tally().residual_volume, 0.5 * v0);  // it had shed only a little
  EXPECT_NEAR(cloud.tally().shed_volume + cloud.tally().residual_volume, v0, 1e-12 * v0);
  // Its micro-bubbles are all still under water (they surface later, slower).
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ(cloud.kind[i], TextureKind::MicroBubble);
    EXPECT_LT(cloud.position[i][1], 0.0);
  }
}

TEST(TextureShedding, DropletBornInTheWaterFootprintIsKeptForTheBirthGrace) {
  TextureParameters p = params();
  p.shedding.representatives_per_source = 1;  // keep the cloud to the sources
  p.shedding.source_lifetime = 100.0;
  TextureCloud cloud(p);
  const PoolFlow flow;
  const std::uint64_t sinking = cloud.addSource(TextureKind::Droplet, Vec3(0.0, -0.01, 0.0), Vec3::Zero(), 0.0);
  const std::uint64_t leaping = cloud.addSource(TextureKind::Droplet, Vec3(0.1, -0.001, 0.0), Vec3(0, 1.5, 0), 0.0);
  auto alive = [&](std::uint64_t id) {
    for (auto i : cloud.id)
      if (i == id) return true;
    return false;
  };
  const double dt = 1e-3;
  int step = 0;
  for (; step < 19; ++step) cloud.step(flow, step * dt, dt);
  EXPECT_TRUE(alive(sinking));  // still within the 0.02 s grace
  EXPECT_TRUE(alive(leaping));
  cloud.step(flow, step * dt, dt), ++step;
  cloud.step(flow, step * dt, dt), ++step;
  EXPECT_FALSE(alive(sinking));  // absorbed at age 0.02 s
  EXPECT_EQ(cloud.tally().absorbed, 1);
  // The leaping droplet reached the air (armed); it falls back and is absorbed the step it re-enters the water.
  int reentered = -1;
  for (; step < 1000 && alive(leaping); ++step) {
    const double y = cloud.position[0][1];
    if (y < 0.0 && reentered < 0) reentered = step;
    cloud.step(flow, step * dt, dt);
  }
  ASSERT_GE(reentered, 0);
  EXPECT_FALSE(alive(leaping));
  EXPECT_EQ(step, reentered + 1);
  EXPECT_EQ(cloud.tally().absorbed, 2);
}
