// The volumes of the render stage (src/render/density_grid, frame_volumes, vdb_export): the mist grid integrates
// to the volume its representatives stand for (each 250 droplets of 0.075 mm), 2D air spread across the fall
// integrates to its amount, the df3 and VDB files hold the grid, and a cloud of mist drawn by povray makes the
// image brighter where it is than the same scene with render.mist off.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "render/density_grid.hpp"
#include "render/external_tools.hpp"
#include "render/frame_volumes.hpp"
#include "render/materials.hpp"
#include "render/scene_writer.hpp"
#include "render/vdb_export.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;

namespace {

// `n` points uniformly in a ball of radius r around c (seeded).
std::vector<Vec<3>> ball(int n, double r, const Vec<3>& c, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec<3>> p;
  while (static_cast<int>(p.size()) < n) {
    const Vec<3> q(u(rng), u(rng), u(rng));
    if (q.norm() <= 1.0) p.push_back(c + r * q);
  }
  return p;
}

Box bigBox() {
  Box b;
  b.min = {-10, -10, -10}, b.max = {10, 10, 10};
  return b;
}

// Mean grey level of a binary PPM (P6, 255) over the rectangle [x0, x1) x [y0, y1).
double meanGrey(const fs::path& file, int x0, int x1, int y0, int y1) {
  std::ifstream in(file, std::ios::binary);
  auto field = [&in]() {
    std::string token;
    while (in >> token && token[0] == '#') std::getline(in, token);
    return token;
  };
  EXPECT_EQ(field(), "P6");
  const int w = std::stoi(field()), h = std::stoi(field());
  field();
  in.get();
  std::vector<unsigned char> px(static_cast<std::size_t>(3) * w * h);
  in.read(reinterpret_cast<char*>(px.data()), static_cast<std::streamsize>(px.size()));
  double s = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k) s += px[(static_cast<std::size_t>(y) * w + x) * 3 + k] / 255.0;
  return s / (3.0 * (x1 - x0) * (y1 - y0));
}

}  // namespace

TEST(RenderVolume, MistGridIntegratesToTheRepresentedMistVolume) {
  CaseConfig c;
  c.numerics.particle_spacing = 0.01;
  c.render.mist = true;
  c.render.mist_voxel = 0.01;
  c.texture.fine_diameter = 7.5e-5;
  c.texture.representative_ratio = 1.0 / 250;
  FrameScene s;
  s.content.scene_box = bigBox();
  s.mist = ball(2000, 0.1, Vec<3>(0.3, 0.2, 0.0));
  const FrameVolumes v = frameVolumes(s, c);
  const double droplet = M_PI / 6.0 * std::pow(7.5e-5, 3);  // one 0.075 mm droplet
  EXPECT_NEAR(v.mist.integral() / (2000 * 250 * droplet), 1.0, 1e-5);
  EXPECT_DOUBLE_EQ(v.mist_extinction, 3.0 / 7.5e-5);
  EXPECT_TRUE(v.white_water.empty());
  c.render.mist = false;
  EXPECT_TRUE(frameVolumes(s, c).mist.empty());
}

TEST(RenderVolume, AirAcrossTheFallIntegratesToItsAmount) {
  Box b = bigBox();
  b.min = {0.0, 0.0, -0.1}, b.max = {1.0, 0.5, 0.1};
  DensityGrid g = emptyGrid(b, 0.01);
  const std::vector<Vec<2>> air{{0.3, 0.1}, {0.5, 0.2}, {0.505, 0.2}};
  splatAcross(g, air, 2.0);  // 2 per metre across, 0.2 m
  EXPECT_NEAR(g.integral(), 3 * 2.0 * 0.2, 1e-6);
  // Every layer across z holds the same values.
  EXPECT_FLOAT_EQ(g.at(30, 10, 0), g.at(30, 10, g.n[2] - 1));
}

TEST(RenderVolume, Df3AndVdbFilesHoldTheGrid) {
  const fs::path dir = test_support::freshDir("render_volume_files");
  DensityGrid g = emptyGrid(boundsOf(ball(50, 0.05, Vec<3>::Zero()), 0.02, bigBox()), 0.01);
  splat(g, ball(50, 0.05, Vec<3>::Zero()), 1e-6);
  const double scale = writeDf3(dir / "g.df3", g);
  EXPECT_FLOAT_EQ(static_cast<float>(scale), g.maximum());
  std::ifstream in(dir / "g.df3", std::ios::binary);
  unsigned char header[6];
  in.read(reinterpret_cast<char*>(header), 6);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(header[2 * k] * 256 + header[2 * k + 1], g.n[k]);
  EXPECT_EQ(fs::file_size(dir / "g.df3"), 6 + 2 * g.value.size());
  writeVdb(dir / "g.vdb", {{"mist", &g}});
  const DensityGrid back = readVdbGrid(dir / "g.vdb", "mist", g);
  for (std::size_t i = 0; i < g.value.size(); ++i) ASSERT_FLOAT_EQ(back.value[i], g.value[i]) << i;
  EXPECT_THROW(readVdbGrid(dir / "g.vdb", "white_water", g), std::runtime_error);
}

TEST(RenderVolume, MistMakesTheCloudBrighterThanTheSameFrameWithout) {
  ASSERT_TRUE(findOnPath("povray")) << "povray is not installed (scripts/install-deps.sh installs it)";
  const fs::path dir = test_support::freshDir("render_volume_mist");
  ASSERT_TRUE(installMaterials(dir));
  CaseConfig c;
  c.numerics.particle_spacing = 0.01;
  c.render.mist_voxel = 0.01;
  RenderConfig& r = c.render;
  r.camera_location = {0.0, 1.0, 0.6};  // above and in front, looking down at the cloud over the ground
  r.camera_look_at = {0.0, 0.1, 0.0};
  r.camera_angle = 30.0;
  r.light_location = {1.0, 3.0, 2.0};
  FrameScene s;
  s.content.up_axis = 1;
  s.content.scene_box = bigBox();
  s.content.ground = 0.0;
  s.mist = ball(20000, 0.08, Vec<3>(0.0, 0.1, 0.0));  // a cloud of 5e6 droplets, about 1 cm^3 of water
  for (bool mist : {true, false}) {
    c.render.mist = mist;
    const FrameVolumes v = frameVolumes(s, c);
    SceneContent content = s.content;
    if (mist) {
      const double top = writeDf3(dir / "mist.df3", v.mist);
      content.mist_volume = VolumeFile{"mist.df3", v.mist.origin, v.mist.upper(), top * v.mist_extinction};
    }
    writeScene(dir / "scene.pov", r, content, "mist test");
    const std::string image = mist ? "with.ppm" : "without.ppm";
    ASSERT_TRUE(runProcess({"povray", "-D", "+FP", "+WT1", "+Iscene.pov", "+O" + image, "+W64", "+H48", "+Q9"}, dir,
                           dir / "povray.log"))
        << test_support::slurp(dir / "povray.log");
  }
  // The cloud is at the centre of the view (about 12 pixels across); a corner is the ground far from it.
  const double with = meanGrey(dir / "with.ppm", 28, 36, 20, 28);
  const double without = meanGrey(dir / "without.ppm", 28, 36, 20, 28);
  EXPECT_GT(with, without + 0.1) << "with mist " << with << ", without " << without;
  EXPECT_NEAR(meanGrey(dir / "with.ppm", 0, 6, 0, 6), meanGrey(dir / "without.ppm", 0, 6, 0, 6), 0.02);
}
