// `mistfall render RUN_DIR` end to end on a hand-made run (two frames of a 2D block of water in a walled box, one
// droplet): meshes, scenes, preview images, MP4 and GIF; skipping rendered frames; errors for a missing povray or
// ffmpeg (simulated by a PATH without them) that name the Debian package and write nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "io/vtk_writer.hpp"
#include "render/external_tools.hpp"
#include "render/mesh_files.hpp"
#include "support/cli.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::quoted;
using test_support::runCli;
using test_support::slurp;

namespace {

constexpr double kL0 = 0.01;

// A 2D case: a 10 x 10 block of water (l0 = 1 cm) on a floor, 64 x 48 previews; `output` ends [output].
std::string tinyCase(const std::string& name, const std::string& output, double extrusion_width) {
  return "[case]\nname = \"" + name + R"("
dimension = 2
[domain]
min = [-0.03, -0.03]
max = [0.3, 0.2]
[numerics]
particle_spacing = 0.01
[output]
end_time = 0.02
interval = 0.01
)" + output + R"(
[render]
preview_width = 64
preview_height = 48
frame_rate = 5
extrusion_width = )" + std::to_string(extrusion_width) + R"(
[[region]]
name = "water"
min = [0.0, 0.0]
max = [0.1, 0.1]
[[region]]
name = "floor"
material = "wall"
min = [-0.03, -0.03]
max = [0.3, 0.0]
)";
}

// A run directory: case.toml and two frames of the block (the second moved right by 2 cm) with a droplet above
// it, classified (category array).
fs::path makeRun(const std::string& name) {
  const fs::path dir = test_support::freshDir(name);
  std::ofstream(dir / "case.toml") << tinyCase("tiny_block", "", 0.05);
  fs::create_directories(dir / "frames");
  for (int f = 0; f < 2; ++f) {
    Particles<2> p;
    std::vector<std::uint8_t> category;
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j) {
        p.add(Vec<2>((i + 0.5 + 2 * f) * kL0, (j + 0.5) * kL0), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
        category.push_back(j == 9 ? 2 : 1);
      }
    p.add(Vec<2>(0.05, 0.15), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    category.push_back(3);  // a droplet
    writeVtp<2>(dir / "frames" / ("frame_0000" + std::to_string(f) + ".vtp"), p, 0.01 * f, false, &category);
  }
  return dir;
}

// Sets PATH for the life of the object.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) : old_(std::getenv("PATH")) { ::setenv("PATH", path.c_str(), 1); }
  ~ScopedPath() { ::setenv("PATH", old_.c_str(), 1); }

 private:
  std::string old_;
};

}  // namespace

TEST(RenderCommand, PreviewWritesMeshesScenesImagesAndAnimation) {
  ASSERT_TRUE(findOnPath("povray") && findOnPath("ffmpeg")) << "scripts/install-deps.sh installs povray and ffmpeg";
  const fs::path run = makeRun("render_command");
  const auto r = runCli("render " + quoted(run) + " --preview --jobs 2 --export --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path out = run / "render";
  for (const char* f : {"materials.inc", "natural.inc", "lab.inc", "export/water_00000.ply", "export/water_00001.ply",
                        "preview/frame_00000.png", "preview/frame_00001.png", "preview/tiny_block.mp4",
                        "preview/tiny_block.gif", "timings.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // The intermediates are gone once the images are done.
  for (const char* f : {"scene_00000.pov", "mesh_00000.inc", "scene_00001.pov", "preview/tmp_frame_00000.png"})
    EXPECT_FALSE(fs::exists(out / f)) << f;
  const TriangleMesh mesh = readPly(out / "export/water_00000.ply");
  EXPECT_EQ(openEdgeCount(mesh), 0u);
  // The section of 100 particles of 1 cm^2 extruded across 5 cm; the droplet is a sphere, not part of the mesh.
  EXPECT_NEAR(enclosedVolume(mesh) / (100 * kL0 * kL0 * 0.05), 1.0, 0.05);

  // Again: both frames are skipped, the animation is rebuilt; an edited materials.inc is kept.
  std::ofstream(out / "materials.inc", std::ios::app) << "// edited\n";
  const auto again = runCli("render " + quoted(run) + " --preview --plain-progress");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("2 of 2 frames already rendered"), std::string::npos) << again.err;
  EXPECT_NE(slurp(out / "materials.inc").find("// edited"), std::string::npos);

  // Rendered anew with --keep-intermediates: the scene, the mesh include stay.
  fs::remove_all(out / "preview");
  const auto kept = runCli("render " + quoted(run) + " --preview --keep-intermediates --plain-progress");
  ASSERT_EQ(kept.code, 0) << kept.err;
  EXPECT_TRUE(fs::exists(out / "mesh_00001.inc"));
  const std::string scene = slurp(out / "scene_00001.pov");
  EXPECT_NE(scene.find("#include \"mesh_00001.inc\""), std::string::npos);
  EXPECT_NE(scene.find("// droplets: 1"), std::string::npos);
  EXPECT_NE(scene.find("#declare Wall_Count = 1;"), std::string::npos);  // the floor
}

TEST(RenderCommand, FrameIntervalPicksTheFramesNearestToItsMultiples) {
  ASSERT_TRUE(findOnPath("povray") && findOnPath("ffmpeg")) << "scripts/install-deps.sh installs povray and ffmpeg";
  const fs::path run = makeRun("render_interval");  // frames 0 and 1, 0.01 s apart
  std::string text = slurp(run / "case.toml");
  text.replace(text.find("[render]\n"), 9, "[render]\nframe_interval = 0.02\n");
  std::ofstream(run / "case.toml") << text;
  const auto r = runCli("render " + quoted(run) + " --preview --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(run / "render/preview/frame_00000.png"));
  EXPECT_FALSE(fs::exists(run / "render/preview/frame_00001.png"));
  EXPECT_FALSE(fs::exists(run / "render/export"));
}

TEST(RenderCommand, MissingPovrayOrFfmpegNamesThePackageAndWritesNothing) {
  const fs::path run = makeRun("render_missing_tools");
  const fs::path bin = test_support::freshDir("render_missing_tools_bin");
  {
    ScopedPath path(bin.string());  // neither tool
    const auto r = runCli("render " + quoted(run));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("install the Debian package 'povray'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("install the Debian package 'ffmpeg'"), std::string::npos) << r.err;
  }
  const auto povray = findOnPath("povray");
  ASSERT_TRUE(povray);
  fs::create_symlink(*povray, bin / "povray");
  {
    ScopedPath path(bin.string());  // povray only
    const auto r = runCli("render " + quoted(run));
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.err.find("'povray'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ffmpeg is not installed"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(run / "render"));
}

TEST(RenderCommand, BadRunDirectoryIsBadInput) {
  const auto r = runCli("render " + quoted(test_support::scratchRoot() / "no_such_run"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST(RenderCommand, RunDoesSimulateTextureAndRenderInOneCommand) {
  ASSERT_TRUE(findOnPath("povray") && findOnPath("ffmpeg")) << "scripts/install-deps.sh installs povray and ffmpeg";
  const fs::path dir = test_support::freshDir("render_run");
  std::ofstream(dir / "case.toml") << tinyCase("tiny_run", "field_spacing = 0.02", 0.03);
  const fs::path run = dir / "run";
  const auto r = runCli("run " + quoted(dir / "case.toml") + " --out " + quoted(run) +
                        " --preview --threads 1 --jobs 2 --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"frames/frame_00002.vtp", "texture/texture_00002.bin", "render/preview/frame_00000.png",
                        "render/preview/frame_00002.png", "render/preview/tiny_run.mp4", "render/preview/tiny_run.gif"})
    EXPECT_TRUE(fs::exists(run / f)) << f;
}
