// A generated scene parses and renders: povray draws a tiny image (64 x 48, PPM) of a block of water in front of
// the background, and the water's pixels differ from the background's. Needs povray (scripts/install-deps.sh).
// Also the scene text, and what a frame puts in its scene (walls cut away on the line of sight, droplets).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>

#include "case/case_file.hpp"
#include "render/external_tools.hpp"
#include "render/frame_scene.hpp"
#include "render/materials.hpp"
#include "render/mesh_files.hpp"
#include "render/scene_writer.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<std::array<double, 3>> rgb;  // in [0, 1], row by row from the top
  const std::array<double, 3>& at(int x, int y) const { return rgb[static_cast<std::size_t>(y) * width + x]; }
};

Image readPpm(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  int maxval = 0;
  Image im;
  // Header fields separated by white space, with '#' comment lines (POV-Ray names itself in one).
  auto field = [&in]() {
    std::string token;
    while (in >> token && token[0] == '#') std::getline(in, token);
    return token;
  };
  magic = field();
  im.width = std::stoi(field());
  im.height = std::stoi(field());
  maxval = std::stoi(field());
  in.get();
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(maxval, 255);
  for (int i = 0; i < im.width * im.height; ++i) {
    std::array<double, 3> c;
    for (double& v : c) v = static_cast<unsigned char>(in.get()) / 255.0;
    im.rgb.push_back(c);
  }
  EXPECT_TRUE(in.good()) << file;
  return im;
}

// Mean colour over a pixel rectangle [x0, x1) x [y0, y1).
std::array<double, 3> mean(const Image& im, int x0, int x1, int y0, int y1) {
  std::array<double, 3> m{0, 0, 0};
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k) m[k] += im.at(x, y)[k] / ((x1 - x0) * (y1 - y0));
  return m;
}

}  // namespace

TEST(RenderScene, TinyRenderShowsTheWaterAgainstTheBackground) {
  ASSERT_TRUE(findOnPath("povray")) << "povray is not installed (scripts/install-deps.sh installs it)";
  const fs::path dir = test_support::freshDir("render_scene");
  // A 0.2 x 0.2 x 0.2 m block of water (l0 = 2 cm) around the origin, y up, seen from +z.
  std::vector<Vec<3>> centres;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) centres.emplace_back(-0.09 + 0.02 * i, -0.09 + 0.02 * j, -0.09 + 0.02 * k);
  writePovMesh(dir / "mesh.inc", liquidSurface(centres, {0.02}), "Water_Surface");
  ASSERT_TRUE(installMaterials(dir));
  RenderConfig r;
  r.style = RenderStyle::Lab;  // a uniform background
  r.camera_location = {0.0, 0.15, 1.2};
  r.camera_look_at = {0.0, 0.0, 0.0};
  r.camera_angle = 30.0;
  r.light_location = {-1.0, 2.0, 2.0};
  SceneContent content;
  content.up_axis = 1;
  content.mesh_include = "mesh.inc";
  content.ground = -2.0;  // far below: the image's top corners are background
  writeScene(dir / "scene.pov", r, content, "test block");
  ASSERT_TRUE(runProcess({"povray", "-D", "+FP", "+WT1", "+Iscene.pov", "+Oimage.ppm", "+W64", "+H48", "+Q8"}, dir,
                         dir / "povray.log"))
      << test_support::slurp(dir / "povray.log");
  const Image im = readPpm(dir / "image.ppm");
  ASSERT_EQ(im.width, 64);
  ASSERT_EQ(im.height, 48);
  // The block spans about 2 * atan(0.1 / 1.1) / 30 deg = 35 % of the width around the centre.
  const auto water = mean(im, 28, 36, 20, 28);
  const auto background = mean(im, 0, 6, 0, 6);
  double difference = 0.0;
  for (int k = 0; k < 3; ++k) difference += std::abs(water[k] - background[k]);
  EXPECT_GT(difference, 0.3) << "water " << water[0] << ' ' << water[1] << ' ' << water[2] << ", background "
                             << background[0] << ' ' << background[1] << ' ' << background[2];
  // The background is uniform: its corners agree with each other.
  const auto other = mean(im, 58, 64, 0, 6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(other[k], background[k], 0.02);
}

TEST(RenderScene, SceneHasCameraLightMaterialsAndOnlyNonEmptyGroups) {
  RenderConfig r;
  r.camera_location = {1, 2, 3};
  SceneContent c;
  c.up_axis = 2;
  c.droplets = {Vec<3>(0.1, 0.2, 0.3)};
  c.droplet_radius = 0.005;
  const std::string text = sceneText(r, c, "t");
  EXPECT_NE(text.find("#include \"materials.inc\""), std::string::npos);
  EXPECT_NE(text.find("#declare Up = <0, 0, 1>;"), std::string::npos);
  EXPECT_NE(text.find("sky Up"), std::string::npos);
  EXPECT_NE(text.find("#include \"natural.inc\""), std::string::npos);  // the default style
  EXPECT_NE(text.find("right -x"), std::string::npos);
  EXPECT_NE(text.find("material { M_Droplet }"), std::string::npos);
  EXPECT_EQ(text.find("M_Bubble"), std::string::npos);
  EXPECT_EQ(text.find("Water("), std::string::npos);
  EXPECT_EQ(text.find("Mist()"), std::string::npos);
  EXPECT_NE(defaultMaterials().find("ior 1.33"), std::string::npos);
  r.style = RenderStyle::Lab;
  c.mesh_include = "mesh.inc";
  c.mist_volume = VolumeFile{"mist_00001.df3", Vec<3>::Zero(), Vec<3>::Ones(), 40.0};
  const std::string lab = sceneText(r, c, "t");
  EXPECT_NE(lab.find("#include \"lab.inc\""), std::string::npos);
  EXPECT_NE(lab.find("Water(false)"), std::string::npos);
  EXPECT_NE(lab.find("#declare Mist_File = \"mist_00001.df3\";"), std::string::npos);
  EXPECT_NE(lab.find("#declare Mist_Extinction = 40;"), std::string::npos);
  EXPECT_NE(lab.find("Mist()"), std::string::npos);
}

TEST(RenderScene, WallsOnTheLineOfSightAreCutAwayAndDropletsLeaveTheMesh) {
  // 3D tank: floor, back wall (y max) and front wall (y min); the default camera looks from -y.
  const CaseConfig c = parseCase(R"([case]
name = "tank"
dimension = 3
[domain]
min = [-0.1, -0.1, -0.1]
max = [1.1, 1.1, 1.1]
[numerics]
particle_spacing = 0.1
[output]
end_time = 1.0
[[region]]
name = "water"
min = [0.0, 0.0, 0.0]
max = [0.5, 0.5, 0.5]
[[region]]
name = "floor"
material = "wall"
min = [-0.1, -0.1, -0.1]
max = [1.1, 1.1, 0.0]
[[region]]
name = "back"
material = "wall"
min = [-0.1, 1.0, 0.0]
max = [1.1, 1.1, 1.0]
[[region]]
name = "front"
material = "wall"
min = [-0.1, -0.1, 0.0]
max = [1.1, 0.0, 1.0]
)",
                                 "tank.toml");
  Particles<3> p;
  p.add(Vec<3>(0.05, 0.05, 0.05), Vec<3>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  p.add(Vec<3>(0.5, 0.5, 0.9), Vec<3>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  p.add(Vec<3>(0.0, 0.0, -0.05), Vec<3>::Zero(), ParticleKind::Wall, Phase::Liquid);
  const FrameScene s = frameScene<3>(p, {1, 3, 0}, c, nullptr);
  ASSERT_EQ(s.content.walls.size(), 2u);  // floor and back
  EXPECT_DOUBLE_EQ(s.content.walls[1].min[1], 1.0);
  EXPECT_EQ(s.content.up_axis, 2);
  ASSERT_EQ(s.liquid.size(), 1u);  // the droplet (category 3) and the wall particle are not meshed
  ASSERT_EQ(s.content.droplets.size(), 1u);
  EXPECT_DOUBLE_EQ(s.content.droplets[0].z(), 0.9);
}

// cases/waterfall_small.toml's vents: the cavity's, cut through the visible back wall, is drawn as that wall; the
// roof's, cut through the hidden lid, is not.
TEST(RenderScene, AVentIsDrawnAsTheWallItWasCutFromUnlessThatWallIsHidden) {
  const CaseConfig c = loadCaseFile(std::string(MISTFALL_SOURCE_DIR) + "/cases/waterfall_small.toml");
  ASSERT_EQ(c.vents.size(), 2u);
  Particles<2> p;
  p.add(Vec<2>(0.5, 0.05), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  const FrameScene s = frameScene<2>(p, {1}, c, nullptr);
  const auto& names = s.content.wall_names;
  EXPECT_NE(std::find(names.begin(), names.end(), "cavity"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "roof"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "back_upper"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "lid"), names.end());
}
