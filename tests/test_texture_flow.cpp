// GridFlow (texture/flow_field.hpp): the flow a texture particle sees, sampled from two frames' grids. A field
// linear in x, y and t is reproduced exactly (bilinear in space, linear in time); nodes the phase does not cover
// do not pull the mean towards their written 0; the liquid fraction comes from the coverages; outside the grid
// the sample says so; in 2D the coordinate across the fall is ignored.
#include <gtest/gtest.h>

#include "texture/flow_field.hpp"

using namespace mistfall;

namespace {

// 5 x 4 nodes of spacing 0.1 from (1, 2); gas velocity (a + x + 2y, 3 - y, 0) at time t = `time` (a = 10 t),
// gas k = 0.01 (1 + x), gas everywhere except node column i = 4 (liquid there, gas velocity written as 0).
std::shared_ptr<const ImageData> grid(double time) {
  auto g = std::make_shared<ImageData>();
  g->origin = {1.0, 2.0, 0.0};
  g->spacing = {0.1, 0.1, 1.0};
  g->dims = {5, 4, 1};
  g->time = time;
  const std::size_t n = g->nodeCount();
  std::vector<double> gu(3 * n, 0.0), lu(3 * n, 0.0), gk(n, 0.0), lk(n, 0.0), gc(n, 0.0), lc(n, 0.0);
  for (std::size_t node = 0; node < n; ++node) {
    const int i = static_cast<int>(node % 5), j = static_cast<int>(node / 5);
    const double x = 1.0 + 0.1 * i, y = 2.0 + 0.1 * j;
    if (i == 4) {
      lc[node] = 2.0;
      lk[node] = 5.0;
      continue;
    }
    gc[node] = 1.0;
    gu[3 * node] = 10.0 * time + x + 2.0 * y;
    gu[3 * node + 1] = 3.0 - y;
    gk[node] = 0.01 * (1.0 + x);
  }
  g->arrays = {{"gas_velocity", 3, gu}, {"liquid_velocity", 3, lu}, {"gas_sps_k", 1, gk},
               {"liquid_sps_k", 1, lk}, {"gas_coverage", 1, gc},    {"liquid_coverage", 1, lc}};
  return g;
}

}  // namespace

TEST(TextureFlow, LinearFieldIsExactInSpaceAndTime) {
  const GridFlow flow(grid(0.0), grid(0.1), 2);
  const Vec3 x(1.137, 2.251, 0.7);  // inside the gas-only columns; z is ignored in 2D
  const FlowSample s = flow.sample(false, x, 0.04);
  ASSERT_TRUE(s.inside);
  EXPECT_NEAR(s.mean_velocity[0], 0.4 + 1.137 + 2 * 2.251, 1e-12);
  EXPECT_NEAR(s.mean_velocity[1], 3.0 - 2.251, 1e-12);
  EXPECT_EQ(s.mean_velocity[2], 0.0);
  EXPECT_NEAR(s.k, 0.01 * 2.137, 1e-12);
  EXPECT_EQ(s.liquid_fraction, 0.0);
}

TEST(TextureFlow, UncoveredNodesDoNotDragTheMeanAndSetTheLiquidFraction) {
  const GridFlow flow(grid(0.0), grid(0.0), 2);
  // Between column 3 (gas) and column 4 (liquid, gas velocity written as 0): the gas mean is column 3's.
  const Vec3 x(1.375, 2.1, 0.0);
  const FlowSample gas = flow.sample(false, x, 0.0);
  EXPECT_NEAR(gas.mean_velocity[0], 1.3 + 2 * 2.1, 1e-12);
  // Coverages: gas 1 x (1 - 0.75), liquid 2 x 0.75 -> liquid fraction 1.5 / 1.75.
  EXPECT_NEAR(gas.liquid_fraction, 1.5 / 1.75, 1e-12);
  const FlowSample liquid = flow.sample(true, x, 0.0);
  EXPECT_NEAR(liquid.liquid_fraction, 1.5 / 1.75, 1e-12);
  EXPECT_NEAR(liquid.k, 5.0, 1e-12);
}

TEST(TextureFlow, EmptySpaceOfAWaterOnlyRunCountsAsAir) {
  // No gas at all: full liquid coverage 2 on the right half, a thin 0.2 on the left half.
  auto g = std::make_shared<ImageData>(*grid(0.0));
  for (auto& a : g->arrays) std::fill(a.values.begin(), a.values.end(), 0.0);
  auto& liquid = g->arrays[5].values;
  for (std::size_t node = 0; node < g->nodeCount(); ++node) liquid[node] = node % 5 >= 2 ? 2.0 : 0.2;
  const GridFlow flow(g, g, 2);
  EXPECT_NEAR(flow.sample(true, Vec3(1.35, 2.1, 0.0), 0.0).liquid_fraction, 1.0, 1e-12);
  EXPECT_NEAR(flow.sample(false, Vec3(1.05, 2.1, 0.0), 0.0).liquid_fraction, 0.1, 1e-12);
}

TEST(TextureFlow, OutsideTheGridIsReported) {
  const GridFlow flow(grid(0.0), grid(0.1), 2);
  EXPECT_FALSE(flow.sample(false, Vec3(0.99, 2.1, 0.0), 0.0).inside);
  EXPECT_FALSE(flow.sample(false, Vec3(1.2, 2.31, 0.0), 0.0).inside);
  EXPECT_TRUE(flow.sample(false, Vec3(1.4, 2.3, 0.0), 0.0).inside);  // the far corner node itself
}

TEST(TextureFlow, TrilinearIn3D) {
  // 3 x 4 x 5 nodes; liquid everywhere with velocity (x + 2y - z, 4z, 1) and k = 1 + x y z (trilinear, so the
  // interpolation is exact).
  auto g = std::make_shared<ImageData>();
  g->origin = {-0.2, 0.1, 0.3};
  g->spacing = {0.1, 0.05, 0.2};
  g->dims = {3, 4, 5};
  const std::size_t n = g->nodeCount();
  std::vector<double> u(3 * n), k(n), c(n, 1.0), zero3(3 * n, 0.0), zero(n, 0.0);
  for (std::size_t node = 0; node < n; ++node) {
    const double x = -0.2 + 0.1 * (node % 3), y = 0.1 + 0.05 * (node / 3 % 4), z = 0.3 + 0.2 * (node / 12);
    u[3 * node] = x + 2 * y - z;
    u[3 * node + 1] = 4 * z;
    u[3 * node + 2] = 1.0;
    k[node] = 1.0 + x * y * z;
  }
  g->arrays = {{"gas_velocity", 3, zero3}, {"liquid_velocity", 3, u}, {"gas_sps_k", 1, zero},
               {"liquid_sps_k", 1, k},     {"gas_coverage", 1, zero},  {"liquid_coverage", 1, c}};
  const GridFlow flow(g, g, 3);
  const Vec3 x(-0.13, 0.21, 0.77);
  const FlowSample s = flow.sample(true, x, 0.0);
  ASSERT_TRUE(s.inside);
  EXPECT_NEAR(s.mean_velocity[0], -0.13 + 0.42 - 0.77, 1e-12);
  EXPECT_NEAR(s.mean_velocity[1], 4 * 0.77, 1e-12);
  EXPECT_NEAR(s.mean_velocity[2], 1.0, 1e-12);
  EXPECT_NEAR(s.k, 1.0 - 0.13 * 0.21 * 0.77, 1e-12);
  EXPECT_EQ(s.liquid_fraction, 1.0);
  EXPECT_FALSE(flow.sample(true, Vec3(-0.13, 0.21, 1.2), 0.0).inside);
}

TEST(TextureFlow, MissingArrayIsAnError) {
  auto bad = std::make_shared<ImageData>(*grid(0.0));
  bad->arrays.pop_back();
  EXPECT_THROW(GridFlow(grid(0.0), bad, 2), std::runtime_error);
}
