// Tests of `mistfall classify RUN_DIR` on a tiny real two-phase run (water under air in a walled box, 400 fluid
// particles, a few steps): the category array in every frame, counts that add up, categories.csv, idempotence,
// ascii frames, the same categories as `simulate` writes inline, the [classify] table, and clear errors.
// Also the frame-count progress line and the category array's round trip through the VTK writer.
#include <gtest/gtest.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "classify/classification.hpp"
#include "cli/progress.hpp"
#include "cli/simulate.hpp"
#include "io/vtk_writer.hpp"
#include "support/case_text.hpp"
#include "support/cli.hpp"
#include "support/scratch.hpp"
#include "support/tank_walls.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::CliResult;
using test_support::freshDir;
using test_support::quoted;
using test_support::runCli;
using test_support::slurp;

namespace {

// Water (10 x 10) in the lower left of a 20 x 20 box of air, walls below and at the sides; l0 = 1 cm.
std::string twoPhaseCase(const std::string& classify_table = "") {
  return R"([case]
name = "tiny_two_phase"
dimension = 2
[domain]
min = [-0.03, -0.03]
max = [0.23, 0.23]
[numerics]
particle_spacing = 0.01
pressure_source = "mixed"
[output]
end_time = 0.02
interval = 0.01
)" + classify_table + R"(
[[region]]
name = "air"
material = "gas"
min = [0.0, 0.0]
max = [0.2, 0.2]
[[region]]
name = "water"
material = "water"
min = [0.0, 0.0]
max = [0.1, 0.1]
)" + mistfall::test_support::tankWalls(0.2, 0.2, 0.03);
}


// Simulates the two-phase case to 0.02 s (3 frames) into dir/run.
fs::path simulateTinyRun(const fs::path& dir, bool ascii = false, const std::string& classify_table = "") {
  const fs::path case_file = dir / "case.toml";
  std::ofstream(case_file, std::ios::binary) << twoPhaseCase(classify_table);
  const fs::path run = dir / "run";
  const CliResult r = runCli("simulate " + quoted(case_file) + " --out " + quoted(run) +
                             " --threads 1 --plain-progress" + (ascii ? " --ascii" : ""));
  EXPECT_EQ(0, r.code) << r.err;
  return run;
}

std::vector<fs::path> framesOf(const fs::path& run) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(run / "frames")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Rewrites every frame without its category array (as frames written before `simulate` had one).
void stripCategories(const fs::path& run) {
  for (const auto& f : framesOf(run)) {
    VtpFrameInfo info;
    const auto p = readVtp<2>(f, info);
    writeVtp<2>(f, p, info.time, info.ascii);
  }
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

TEST(ClassifyCommand, AddsTheCategoryArrayToEveryFrameAndCountsAddUp) {
  const fs::path run = simulateTinyRun(freshDir("classify_counts"));
  stripCategories(run);
  for (const auto& f : framesOf(run)) {
    VtpFrameInfo info;
    readVtp<2>(f, info);
    ASSERT_TRUE(info.category.empty()) << f;
  }
  const CliResult r = runCli("classify " + quoted(run) + " --threads 2 --plain-progress");
  ASSERT_EQ(0, r.code) << r.err;
  EXPECT_NE(r.err.find("classified 3 frames"), std::string::npos) << r.err;

  const auto csv = lines(slurp(run / "categories.csv"));
  ASSERT_EQ(4u, csv.size());
  EXPECT_EQ("frame,time,liquid_bulk,liquid_surface,droplet,gas_bulk,gas_surface,bubble", csv[0]);
  const auto frames = framesOf(run);
  ASSERT_EQ(3u, frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    SCOPED_TRACE(frames[f].string());
    VtpFrameInfo info;
    const auto p = readVtp<2>(frames[f], info);
    ASSERT_EQ(p.size(), info.category.size());
    std::array<std::size_t, kCategoryCount> counts{};
    std::size_t liquid = 0, gas = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int c = info.category[i];
      ASSERT_LT(c, kCategoryCount);
      counts[c] += 1;
      if (p.kind[i] != ParticleKind::Fluid) {
        EXPECT_EQ(0, c) << "non-fluid particle " << i;
      } else if (p.phase[i] == Phase::Liquid) {
        ++liquid;
        EXPECT_TRUE(c >= 1 && c <= 3) << "liquid particle " << i << ": " << c;
      } else {
        ++gas;
        EXPECT_TRUE(c >= 4 && c <= 6) << "gas particle " << i << ": " << c;
      }
    }
    EXPECT_EQ(100u, liquid);
    EXPECT_EQ(300u, gas);
    EXPECT_EQ(liquid, counts[1] + counts[2] + counts[3]);
    EXPECT_EQ(gas, counts[4] + counts[5] + counts[6]);
    // Still water: the top row and the column next to the air are surface, the rest bulk (walls count).
    EXPECT_GT(counts[1], 70u);
    EXPECT_GT(counts[2], 10u);
    std::ostringstream row;
    row << "0000" << f << ',' << (f == 0 ? "0" : f == 1 ? "0.01" : "0.02");
    for (int k = 1; k < kCategoryCount; ++k) row << ',' << counts[k];
    EXPECT_EQ(row.str(), csv[f + 1]);
  }
}

// `simulate` writes the same category array inline, and classify run again changes no byte.
TEST(ClassifyCommand, IsIdempotentAndMatchesWhatSimulateWrites) {
  const fs::path run = simulateTinyRun(freshDir("classify_idempotent"));
  std::vector<std::string> from_simulate;
  for (const auto& f : framesOf(run)) {
    from_simulate.push_back(slurp(f));
    VtpFrameInfo info;
    readVtp<2>(f, info);
    EXPECT_FALSE(info.category.empty()) << f;
  }
  ASSERT_EQ(0, runCli("classify " + quoted(run) + " --plain-progress").code);
  const std::string csv = slurp(run / "categories.csv");
  const auto frames = framesOf(run);
  for (std::size_t f = 0; f < frames.size(); ++f) EXPECT_EQ(from_simulate[f], slurp(frames[f])) << frames[f];
  ASSERT_EQ(0, runCli("classify " + quoted(run) + " --plain-progress --threads 1").code);
  for (std::size_t f = 0; f < frames.size(); ++f) EXPECT_EQ(from_simulate[f], slurp(frames[f])) << frames[f];
  EXPECT_EQ(csv, slurp(run / "categories.csv"));
}

TEST(ClassifyCommand, KeepsAsciiFramesAscii) {
  const fs::path run = simulateTinyRun(freshDir("classify_ascii"), true);
  stripCategories(run);
  ASSERT_EQ(0, runCli("classify " + quoted(run) + " --plain-progress").code);
  for (const auto& f : framesOf(run)) {
    EXPECT_EQ(std::string::npos, slurp(f).find("AppendedData")) << f;
    VtpFrameInfo info;
    const auto p = readVtp<2>(f, info);
    EXPECT_TRUE(info.ascii);
    EXPECT_EQ(p.size(), info.category.size());
  }
}

// The thresholds come from the run's case.toml: with both surface tests off no particle is surface.
TEST(ClassifyCommand, UsesTheClassifyTableOfTheRunsCase) {
  const fs::path run = simulateTinyRun(freshDir("classify_table"), false,
                                       "[classify]\nsurface_number_density = 0\nsurface_gradient = 1e9\n");
  ASSERT_EQ(0, runCli("classify " + quoted(run) + " --plain-progress").code);
  const auto csv = lines(slurp(run / "categories.csv"));
  ASSERT_EQ(4u, csv.size());
  EXPECT_EQ("00000,0,100,0,0,300,0,0", csv[1]);
}

TEST(ClassifyCommand, BadInputExitsOneNamingThePathAndWritesNothing) {
  const fs::path dir = freshDir("classify_errors");
  CliResult r = runCli("classify " + quoted(dir / "nope"));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find((dir / "nope").string() + " does not exist"), std::string::npos) << r.err;

  r = runCli("classify " + quoted(dir));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find((dir / "case.toml").string() + " does not exist"), std::string::npos) << r.err;

  std::ofstream(dir / "case.toml") << twoPhaseCase();
  r = runCli("classify " + quoted(dir));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("no frames (frame_NNNNN.vtp) in " + (dir / "frames").string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "categories.csv"));

  std::ofstream(dir / "case.toml") << twoPhaseCase("[classify]\nsurface_gradiant = 0.5\n");
  r = runCli("classify " + quoted(dir));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("unknown key classify.surface_gradiant; did you mean 'surface_gradient'?"), std::string::npos)
      << r.err;

  r = runCli("classify");
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("run_dir is required"), std::string::npos) << r.err;
}

// A malformed frame is bad input: exit 1 naming it, every frame read before the first is rewritten, so no frame
// changes and there is no categories.csv.
TEST(ClassifyCommand, MalformedFrameExitsOneNamingItAndWritesNothing) {
  const fs::path run = simulateTinyRun(freshDir("classify_broken"));
  const fs::path broken = framesOf(run).back();
  std::ofstream(broken, std::ios::binary | std::ios::trunc) << "<?xml version=\"1.0\"?>\n<VTKFile";
  const std::string first = slurp(framesOf(run).front());
  const CliResult r = runCli("classify " + quoted(run) + " --plain-progress");
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find(broken.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "categories.csv"));
  EXPECT_EQ(first, slurp(framesOf(run).front()));
}

// A write the system refuses is an I/O failure: exit 2 naming the file (categories.csv is a folder here).
TEST(ClassifyCommand, RefusedWriteExitsTwoNamingTheFile) {
  const fs::path run = simulateTinyRun(freshDir("classify_refused"));
  fs::create_directories(run / "categories.csv" / "x");
  const CliResult r = runCli("classify " + quoted(run) + " --plain-progress");
  EXPECT_EQ(2, r.code);
  EXPECT_NE(r.err.find((run / "categories.csv").string()), std::string::npos) << r.err;
}

TEST(ClassifyCaseFile, DefaultsAndKeys) {
  using test_support::Parts;
  const ClassificationParameters def;
  const CaseConfig d = parseCase(Parts{}.text(), "cases/x.toml");
  EXPECT_EQ(def.isolated_number_density, d.classify.isolated_number_density);
  EXPECT_EQ(def.isolated_neighbour_fraction, d.classify.isolated_neighbour_fraction);
  EXPECT_EQ(def.surface_number_density, d.classify.surface_number_density);
  EXPECT_EQ(def.surface_gradient, d.classify.surface_gradient);
  Parts p;
  p.output += "[classify]\nisolated_number_density = 0.1\nisolated_neighbour_fraction = 0.25\n"
              "surface_number_density = 0.9\nsurface_gradient = 2\n";
  const CaseConfig c = parseCase(p.text(), "cases/x.toml");
  EXPECT_EQ(0.1, c.classify.isolated_number_density);
  EXPECT_EQ(0.25, c.classify.isolated_neighbour_fraction);
  EXPECT_EQ(0.9, c.classify.surface_number_density);
  EXPECT_EQ(2.0, c.classify.surface_gradient);
}

TEST(ClassifyCaseFile, ErrorsNameKeyValueAndRange) {
  using test_support::errorOf;
  using test_support::Parts;
  Parts p;
  p.output += "[classify]\nsurface_number_density = 1.5\n";
  EXPECT_EQ("cases/x.toml: classify.surface_number_density = 1.5 is out of range; allowed [0, 1]", errorOf(p.text()));
  p = Parts{};
  p.output += "[classify]\nsurface_gradient = -1\n";
  EXPECT_HAS(errorOf(p.text()), "classify.surface_gradient = -1 is out of range; allowed [0, ");
  p = Parts{};
  p.output += "[classify]\nisolated_neighbour_fraction = \"few\"\n";
  EXPECT_HAS(errorOf(p.text()), "classify.isolated_neighbour_fraction = \"few\" has the wrong type (string)");
  p = Parts{};
  p.output += "[classify]\nisolated_density = 0.1\n";
  EXPECT_HAS(errorOf(p.text()), "unknown key classify.isolated_density");
}

TEST(ClassifyProgress, CountsFramesInsteadOfTime) {
  ProgressSnapshot s;
  s.sim_time = 3;
  s.end_time = 10;
  s.step = 3;
  s.steps_per_second = 2.0;
  s.eta_seconds = 3.5;
  s.count_unit = "frames";
  EXPECT_EQ("progress: 3/10 frames (30%), 2.0 frames/s, ETA 0:04", formatPlainLine(s));
  const std::string bar = formatTerminalLine(s);
  EXPECT_NE(bar.find("3/10 frames  2.0 frames/s  ETA 0:04"), std::string::npos) << bar;
  EXPECT_EQ(std::string::npos, bar.find("dt="));
}

TEST(ClassifyVtk, CategoryArrayRoundTripsInBothFormats) {
  const fs::path dir = freshDir("classify_vtk");
  Particles<3> p;
  for (int i = 0; i < 7; ++i)
    p.add(Vec<3>(0.1 * i, 0.2, -0.3), Vec<3>(1.0, 2.0, 3.0), i == 0 ? ParticleKind::Wall : ParticleKind::Fluid,
          i > 3 ? Phase::Gas : Phase::Liquid);
  const std::vector<std::uint8_t> category = {0, 1, 2, 3, 4, 5, 6};
  for (bool ascii : {false, true}) {
    const fs::path f = dir / (ascii ? "a.vtp" : "b.vtp");
    writeVtp<3>(f, p, 0.25, ascii, &category);
    VtpFrameInfo info;
    const auto q = readVtp<3>(f, info);
    EXPECT_EQ(category, info.category);
    EXPECT_EQ(ascii, info.ascii);
    EXPECT_EQ(0.25, info.time);
    EXPECT_EQ(p.size(), q.size());
  }
  const std::vector<std::uint8_t> short_list = {1, 2};
  EXPECT_THROW(writeVtp<3>(dir / "c.vtp", p, 0.0, false, &short_list), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "c.vtp"));
}
