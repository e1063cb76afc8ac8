// Same seed, same cloud, any thread count: the texture's random numbers are counter-based streams of
// (seed, particle id, step) (texture/counter_rng.hpp), so a cloud with shedding sources, in both fluctuation
// models, comes out bit-identical on 1 and 2 OpenMP threads, and different for another seed.
#include <gtest/gtest.h>

#include <omp.h>

#include "texture/texture_cloud.hpp"

using namespace mistfall;

namespace {

TextureCloud runCloud(int threads, FluctuationModel model, std::uint64_t seed) {
  omp_set_num_threads(threads);
  TextureParameters p;
  p.seed = seed;
  p.source_diameter = 0.005;
  p.shedding.source_lifetime = 0.05;
  p.fluctuation.model = model;
  p.fluctuation.ds = 0.005;
  TextureCloud cloud(p);
  FlowSample gas, liquid;
  gas.k = 2e-3;
  gas.mean_velocity = Vec3(0.3, -0.1, 0.0);
  liquid.k = 1e-3;
  liquid.liquid_fraction = 1.0;
  const UniformFlow flow(gas, liquid);
  for (int s = 0; s < 4; ++s) {
    cloud.addSource(TextureKind::Droplet, Vec3(0.01 * s, 0.0, 0.0), Vec3(0.5, 0.0, 0.0), 0.0);
    cloud.addSource(TextureKind::Bubble, Vec3(0.01 * s, -0.1, 0.0), Vec3::Zero(), 0.0);
  }
  for (int s = 0; s < 60; ++s) cloud.step(flow, s * 1e-3, 1e-3);
  omp_set_num_threads(1);
  return cloud;
}

}  // namespace

TEST(TextureThreads, SameSeedSameCloudOnOneAndTwoThreads) {
  for (auto model : {FluctuationModel::Redrawn, FluctuationModel::Langevin}) {
    const TextureCloud one = runCloud(1, model, 7), two = runCloud(2, model, 7);
    ASSERT_EQ(one.size(), two.size());
    ASSERT_GT(one.size(), 1000u);  // the sources shed
    for (std::size_t i = 0; i < one.size(); ++i) {
      ASSERT_EQ(one.id[i], two.id[i]);
      ASSERT_EQ(one.kind[i], two.kind[i]);
      for (int a = 0; a < 3; ++a) {
        ASSERT_EQ(one.position[i][a], two.position[i][a]) << "particle " << i;
        ASSERT_EQ(one.velocity[i][a], two.velocity[i][a]) << "particle " << i;
      }
      ASSERT_EQ(one.diameter[i], two.diameter[i]);
    }
    const TextureCloud other = runCloud(2, model, 8);
    ASSERT_EQ(other.size(), one.size());
    EXPECT_NE(other.position[0][0], one.position[0][0]);
  }
}
