// `mistfall texture RUN_DIR` end to end on a hand-made classified run (three frames with a `category` array and
// flow grids: still water below y = 0.5, a light breeze above): sources spawn once per newly isolated particle
// (tracked by proximity), the per-frame files and texture.csv are written and agree, the result does not depend
// on the thread count, and bad input (no category, no flow fields, an existing texture folder) is refused
// with a clear message before anything is written.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/grid_fields.hpp"
#include "io/pvd_collection.hpp"
#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"
#include "support/cli.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::quoted;
using test_support::runCli;

namespace {

struct Point {
  double x, y, u, v;
  std::uint8_t phase, category;
};

void writeFrame(const fs::path& file, const std::vector<Point>& pts, double time, bool with_category) {
  std::vector<double> xyz, vel, zeros(pts.size(), 0.0);
  std::vector<std::uint8_t> phase, kind(pts.size(), 0), category;
  for (const Point& p : pts) {
    xyz.insert(xyz.end(), {p.x, p.y, 0.0});
    vel.insert(vel.end(), {p.u, p.v, 0.0});
    phase.push_back(p.phase);
    category.push_back(p.category);
  }
  std::vector<VtpArray> arrays = {{"phase", 1, phase},         {"kind", 1, kind},
                                  {"enclosed", 1, kind},       {"velocity", 3, vel},
                                  {"pressure", 1, zeros},      {"number_density", 1, zeros}};
  if (with_category) arrays.push_back({"category", 1, category});
  writePointsVtp(file, xyz, arrays, time, false, "pressure");
}

void writeFields(const fs::path& file, double time) {
  ImageData g;
  g.spacing = {0.1, 0.1, 1.0};
  g.dims = {11, 11, 1};
  g.time = time;
  const std::size_t n = g.nodeCount();
  GridArray gas_u{"gas_velocity", 3, std::vector<double>(3 * n, 0.0)};
  GridArray liquid_u{"liquid_velocity", 3, std::vector<double>(3 * n, 0.0)};
  GridArray gas_k{"gas_sps_k", 1, std::vector<double>(n, 1e-3)};
  GridArray liquid_k{"liquid_sps_k", 1, std::vector<double>(n, 1e-4)};
  GridArray gas_c{"gas_coverage", 1, std::vector<double>(n)}, liquid_c{"liquid_coverage", 1, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const bool air = (i / 11) * 0.1 > 0.5;
    gas_c.values[i] = air ? 1.0 : 0.0;
    liquid_c.values[i] = air ? 0.0 : 1.0;
    gas_u.values[3 * i] = 0.1;
  }
  g.arrays = {gas_u, liquid_u, gas_k, liquid_k, gas_c, liquid_c};
  writeVti(file, g);
}

// A classified 2D run: frame 0 a droplet and a bubble; frame 1 both moved on (same particles) and a new droplet;
// frame 2 the first droplet again, the bubble rejoined the water, a new bubble.
fs::path makeRun(const std::string& name, bool with_category = true, bool with_fields = true,
                 const std::string& texture_extra = "") {
  const fs::path run = test_support::freshDir(name);
  fs::create_directories(run / "frames");
  fs::create_directories(run / "fields");
  std::ofstream(run / "case.toml") << "[case]\nname = \"t\"\ndimension = 2\n[domain]\nmin = [0.0, 0.0]\n"
                                      "max = [1.0, 1.0]\n[numerics]\nparticle_spacing = 0.02\n[output]\n"
                                      "end_time = 0.1\ninterval = 0.05\nfield_spacing = 0.1\n[[region]]\nname = \"w\"\n"
                                      "min = [0.0, 0.0]\nmax = [1.0, 0.5]\n[texture]\nsource_lifetime = 0.05\n"
                                      "representatives_per_source = 20\nwidth = 0.2\nseed = 5\n"
                                   << texture_extra;
  const std::vector<std::vector<Point>> frames = {
      {{0.3, 0.8, 0.5, 0.0, 0, 3}, {0.6, 0.2, 0.0, 0.2, 1, 6}, {0.1, 0.1, 0.0, 0.0, 0, 1}},
      {{0.325, 0.8, 0.5, 0.0, 0, 3}, {0.6, 0.21, 0.0, 0.2, 1, 6}, {0.1, 0.1, 0.0, 0.0, 0, 1}, {0.8, 0.9, 0, 0, 0, 3}},
      {{0.35, 0.8, 0.5, 0.0, 0, 3}, {0.6, 0.22, 0.0, 0.2, 1, 4}, {0.1, 0.1, 0.0, 0.0, 0, 1}, {0.4, 0.3, 0, 0, 1, 6}},
  };
  PvdCollection pvd(run / "frames.pvd");
  for (int f = 0; f < 3; ++f) {
    const std::string number = "0000" + std::to_string(f);
    writeFrame(run / ("frames/frame_" + number + ".vtp"), frames[f], 0.05 * f, with_category);
    if (with_fields) writeFields(run / ("fields/fields_" + number + ".vti"), 0.05 * f);
    pvd.add(0.05 * f, "frames/frame_" + number + ".vtp");
  }
  pvd.write();
  return run;
}

std::vector<std::vector<std::string>> csvRows(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(test_support::csvFields(line));
  return rows;
}

}  // namespace

TEST(TextureCommand, SpawnsOncePerIsolatedParticleAndWritesEveryFrame) {
  const fs::path run = makeRun("texture_cli");
  const auto r = runCli("texture " + quoted(run) + " --threads 1 --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = csvRows(run / "texture/texture.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0][5], "spawned_droplets");
  // Frame 0: 1 droplet + 1 bubble. Frame 1: the moved droplet and bubble are matched, one new droplet.
  // Frame 2: one new bubble.
  const std::string spawned[3][2] = {{"1", "1"}, {"2", "1"}, {"2", "2"}};
  for (int f = 0; f < 3; ++f) {
    EXPECT_EQ(rows[f + 1][5], spawned[f][0]) << "frame " << f;
    EXPECT_EQ(rows[f + 1][6], spawned[f][1]) << "frame " << f;
    const TextureSnapshot s = readTextureBinary(run / ("texture/texture_0000" + std::to_string(f) + ".bin"));
    EXPECT_NEAR(s.time, 0.05 * f, 1e-12);
    std::array<std::int64_t, kTextureKinds> counts{};
    for (auto k : s.kind) ++counts[static_cast<int>(k)];
    for (int k = 0; k < kTextureKinds; ++k) EXPECT_EQ(std::to_string(counts[k]), rows[f + 1][1 + k]) << f;
    for (std::size_t i = 0; i < s.kind.size(); ++i)
      if (isSource(s.kind[i])) EXPECT_LE(std::abs(s.position[i][2]), 0.1);  // width 0.2 across the fall
    EXPECT_TRUE(fs::exists(run / ("texture/texture_0000" + std::to_string(f) + ".vtp")));
  }
  // The first droplet was spent after 0.05 s, with its 20 representatives shed.
  EXPECT_GE(std::stoi(rows[3][7]), 1);
  EXPECT_GT(std::stoi(rows[3][2]), 0);  // mist
  EXPECT_GT(std::stoi(rows[3][4]), 0);  // micro-bubbles
  PvdCollection pvd(run / "texture/texture.pvd");
  pvd.load();
  EXPECT_EQ(pvd.entries().size(), 3u);
}

// texture.file_interval and texture.vtp: the files of the frames nearest the multiples of 0.1 s only (frames 0 and
// 2 of 0, 0.05, 0.1 s), no ParaView copies, the same cloud in them as with every file, and texture.csv whole.
TEST(TextureCommand, FileIntervalAndVtpKeysWriteFewerFiles) {
  const fs::path all = makeRun("texture_cli_all"), few = makeRun("texture_cli_few", true, true,
                                                                 "file_interval = 0.1\nvtp = false\n");
  ASSERT_EQ(runCli("texture " + quoted(all) + " --threads 1").code, 0);
  const auto r = runCli("texture " + quoted(few) + " --threads 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(few / "texture/texture_00000.bin"));
  EXPECT_FALSE(fs::exists(few / "texture/texture_00001.bin"));
  EXPECT_TRUE(fs::exists(few / "texture/texture_00002.bin"));
  for (int f = 0; f < 3; ++f) EXPECT_FALSE(fs::exists(few / ("texture/texture_0000" + std::to_string(f) + ".vtp")));
  EXPECT_TRUE(test_support::slurp(all / "texture/texture_00002.bin") ==
              test_support::slurp(few / "texture/texture_00002.bin"));
  EXPECT_EQ(csvRows(few / "texture/texture.csv"), csvRows(all / "texture/texture.csv"));
  PvdCollection pvd(few / "texture/texture.pvd");
  pvd.load();
  EXPECT_TRUE(pvd.entries().empty());
}

TEST(TextureCommand, SameCloudOnOneAndTwoThreads) {
  const fs::path run = makeRun("texture_cli_threads");
  ASSERT_EQ(runCli("texture " + quoted(run) + " --threads 1").code, 0);
  const std::string one = test_support::slurp(run / "texture/texture_00002.bin");
  ASSERT_EQ(runCli("texture " + quoted(run) + " --threads 2 --overwrite").code, 0);
  EXPECT_EQ(test_support::slurp(run / "texture/texture_00002.bin"), one);
}

TEST(TextureCommand, RefusesBadInputBeforeWriting) {
  const fs::path unclassified = makeRun("texture_cli_nocat", false);
  auto r = runCli("texture " + quoted(unclassified));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no 'category' array: run `mistfall classify"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(unclassified / "texture"));

  // Only the last frame unclassified: refused before any file is written.
  const fs::path partly = makeRun("texture_cli_partly");
  writeFrame(partly / "frames/frame_00002.vtp", {{0.1, 0.1, 0.0, 0.0, 0, 1}}, 0.1, false);
  r = runCli("texture " + quoted(partly));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("frame_00002.vtp has no 'category' array"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(partly / "texture"));

  const fs::path no_fields = makeRun("texture_cli_nofields", true, false);
  r = runCli("texture " + quoted(no_fields));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("output.field_spacing > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(no_fields / "texture"));

  const fs::path run = makeRun("texture_cli_twice");
  ASSERT_EQ(runCli("texture " + quoted(run)).code, 0);
  r = runCli("texture " + quoted(run));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--overwrite"), std::string::npos) << r.err;

  r = runCli("texture " + quoted(run / "nope"));
  EXPECT_EQ(r.code, 1);
}

TEST(TextureCommand, CategoryIsReadAsUInt8OrInt64) {
  const fs::path dir = test_support::freshDir("texture_category");
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0};
  writePointsVtp(dir / "a.vtp", xyz, {{"category", 1, std::vector<std::uint8_t>{3, 6}}}, 0.0, false, "category");
  writePointsVtp(dir / "b.vtp", xyz, {{"category", 1, std::vector<std::int64_t>{1, 5}}}, 0.0, true, "category");
  writePointsVtp(dir / "c.vtp", xyz, {{"category", 1, std::vector<std::int64_t>{1, 300}}}, 0.0, false, "category");
  EXPECT_EQ(*readVtpByteArray(dir / "a.vtp", "category"), (std::vector<std::uint8_t>{3, 6}));
  EXPECT_EQ(*readVtpByteArray(dir / "b.vtp", "category"), (std::vector<std::uint8_t>{1, 5}));
  EXPECT_FALSE(readVtpByteArray(dir / "a.vtp", "phase").has_value());
  EXPECT_THROW(readVtpByteArray(dir / "c.vtp", "category"), std::runtime_error);
}
