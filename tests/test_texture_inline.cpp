// The texture inline with `simulate` ([texture] inline = true): the same files as the post-process
// `mistfall texture RUN_DIR` over the same run, byte for byte (binary and ASCII VTK); the same cloud on 1 and 2 threads; a resumed run
// ends with the same texture as an uninterrupted one; inline without flow grids is refused. The case is a tiny 2D
// dam break (l0 = 1 cm, 200 water particles) with a lone water particle in the air (a droplet: mist) and a lone
// air particle in the column (a bubble: micro-bubbles), run for 0.1 s.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "io/texture_files.hpp"
#include "support/cli.hpp"
#include "support/dam_break_case.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::freshDir;
using test_support::quoted;
using test_support::runCli;
using test_support::slurp;

namespace {

// The dam break plus a lone air particle in the column (after it: it wins) and a lone water particle in the air;
// the [texture] table: `texture_extra` appended.
std::string tinyCase(const std::string& output_extra, const std::string& texture_extra) {
  return test_support::damBreakCase(0.1, 0.02, "", output_extra) + R"(
[[region]]
name = "bubble"
material = "gas"
min = [0.05, 0.05]
max = [0.06, 0.06]
[[region]]
name = "drop"
material = "water"
min = [0.2, 0.2]
max = [0.21, 0.21]
[texture]
representatives_per_source = 40
source_lifetime = 0.06
fluctuation = "langevin"
seed = 7
)" + texture_extra;
}

const std::string kInline = "inline = true\n";
const std::string kFields = "field_spacing = 0.02\n";

fs::path writeCase(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml", std::ios::binary) << text;
  return dir / "case.toml";
}

int simulate(const fs::path& case_file, const fs::path& run, int threads, const std::string& extra = "") {
  const auto r = runCli("simulate " + quoted(case_file) + " --out " + quoted(run) + " --threads " +
                        std::to_string(threads) + " --plain-progress " + extra);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code;
}

// Every file of `dir` by name, with its bytes.
std::map<std::string, std::string> filesOf(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = slurp(e.path());
  return files;
}

void expectSameFiles(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b,
                     const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (const auto& [name, bytes] : a) {
    ASSERT_TRUE(b.count(name)) << name << " missing (" << what << ")";
    EXPECT_TRUE(b.at(name) == bytes) << name << " differs (" << what << ")";
  }
}

}  // namespace

TEST(TextureInline, SimulateWritesTheSameFilesAsThePostProcess) {
  const fs::path dir = freshDir("texture_inline_agree");
  const fs::path run = dir / "run";
  ASSERT_EQ(simulate(writeCase(dir, tinyCase(kFields, kInline)), run, 1), 0);
  const auto inline_files = filesOf(run / "texture");
  // 6 frames: .bin and .vtp each, texture.pvd, texture.csv.
  ASSERT_EQ(inline_files.size(), 14u);
  const TextureSnapshot last = readTextureBinary(run / "texture/texture_00005.bin");
  EXPECT_NEAR(last.time, 0.1, 1e-12);
  std::array<int, kTextureKinds> counts{};
  for (auto k : last.kind) ++counts[static_cast<int>(k)];
  EXPECT_GE(counts[static_cast<int>(TextureKind::Mist)], 1) << "the lone droplet sheds mist";
  EXPECT_GE(counts[static_cast<int>(TextureKind::MicroBubble)] + counts[static_cast<int>(TextureKind::Bubble)], 1)
      << "the lone bubble is a source";

  const auto r = runCli("texture " + quoted(run) + " --overwrite --threads 1 --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  expectSameFiles(inline_files, filesOf(run / "texture"), "inline vs post-process");

  // ASCII frames and grids (17 significant digits) read back exactly too.
  const fs::path ascii = dir / "ascii";
  ASSERT_EQ(simulate(dir / "case.toml", ascii, 1, "--ascii --until 0.06"), 0);
  const auto ascii_files = filesOf(ascii / "texture");
  ASSERT_EQ(ascii_files.size(), 10u);
  ASSERT_EQ(runCli("texture " + quoted(ascii) + " --overwrite --ascii --threads 1 --plain-progress").code, 0);
  expectSameFiles(ascii_files, filesOf(ascii / "texture"), "inline vs post-process, ascii");
}

TEST(TextureInline, SameCloudOnOneAndTwoThreads) {
  const fs::path dir = freshDir("texture_inline_threads");
  const fs::path case_file = writeCase(dir, tinyCase(kFields, kInline));
  ASSERT_EQ(simulate(case_file, dir / "t1", 1), 0);
  ASSERT_EQ(simulate(case_file, dir / "t2", 2), 0);
  expectSameFiles(filesOf(dir / "t1/texture"), filesOf(dir / "t2/texture"), "1 vs 2 threads");
}

TEST(TextureInline, ResumedRunEndsWithTheSameTexture) {
  const fs::path dir = freshDir("texture_inline_resume");
  const fs::path case_file = writeCase(dir, tinyCase(kFields, kInline));
  ASSERT_EQ(simulate(case_file, dir / "a", 1), 0);
  ASSERT_EQ(simulate(case_file, dir / "b", 1, "--until 0.04"), 0);
  ASSERT_EQ(filesOf(dir / "b/texture").size(), 8u);  // frames 0-2
  // A stale file from the interrupted run's future must not survive the resume.
  std::ofstream(dir / "b/texture/texture_00009.bin") << "stale";
  const auto r = runCli("simulate --resume " + quoted(dir / "b") + " --threads 1 --plain-progress");
  ASSERT_EQ(r.code, 0) << r.err;
  expectSameFiles(filesOf(dir / "a/texture"), filesOf(dir / "b/texture"), "uninterrupted vs resumed");
}

TEST(TextureInline, OffByDefaultAndRefusedWithoutFlowGrids) {
  const fs::path dir = freshDir("texture_inline_off");
  ASSERT_EQ(simulate(writeCase(dir / "off", tinyCase(kFields, "")), dir / "off/run", 1, "--until 0.02"), 0);
  EXPECT_FALSE(fs::exists(dir / "off/run/texture"));

  const fs::path no_grids = writeCase(dir / "nogrids", tinyCase("", kInline));
  const auto r = runCli("simulate " + quoted(no_grids) + " --out " + quoted(dir / "nogrids/run"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("texture.inline = true needs the flow grids"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("output.field_spacing > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "nogrids/run"));
}
