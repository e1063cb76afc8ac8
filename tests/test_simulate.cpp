// Tests of the `simulate` command: bit-identical resume, thread-count independence, particle bookkeeping,
// bad input writing nothing, run-directory protection, clean divergence stops, the command line and
// ASCII frames. Cases are small inline TOML files (a ~200-particle 2D dam break) so each test takes seconds.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/simulate.hpp"
#include "io/checkpoint.hpp"
#include "io/diagnostics.hpp"
#include "io/grid_fields.hpp"
#include "io/pvd_collection.hpp"
#include "io/vtk_writer.hpp"
#include "support/cli.hpp"
#include "support/dam_break_case.hpp"
#include "support/same_particles.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;

namespace {

using test_support::csvFields;
using test_support::damBreakCase;
using test_support::freshDir;
using test_support::slurp;
using test_support::CliResult;
using test_support::quoted;
using test_support::runCli;

fs::path writeCase(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// A 0.1 x 0.1 block of water (100 particles) in a domain without walls whose floor is 0.02 m below the
// water: the bottom rows fall out of the domain after about 0.07 s and 0.085 s.
std::string fallingBlockCase(double max_escaped_fraction, double end_time) {
  std::ostringstream s;
  s << R"([case]
name = "falling_block"
dimension = 2

[domain]
min = [-0.05, -0.02]
max = [0.15, 0.25]

[numerics]
particle_spacing = 0.01
max_escaped_fraction = )"
    << max_escaped_fraction << "\n\n[output]\nend_time = " << end_time << R"(
interval = 0.02

[[region]]
name = "block"
material = "water"
min = [0.0, 0.0]
max = [0.1, 0.1]
)";
  return s.str();
}

SimulateOptions options(const fs::path& case_file, const fs::path& out, int threads = 1) {
  SimulateOptions o;
  o.case_file = case_file;
  o.out_dir = out;
  o.threads = threads;
  o.force_plain_progress = true;
  return o;
}

struct Captured {
  int code = -1;
  std::string err;
};

// Runs runSimulate in-process with std::cerr captured.
Captured simulate(const SimulateOptions& o) {
  std::ostringstream err;
  std::streambuf* old = std::cerr.rdbuf(err.rdbuf());
  Captured r;
  try {
    r.code = runSimulate(o);
  } catch (...) {
    std::cerr.rdbuf(old);
    throw;
  }
  std::cerr.rdbuf(old);
  r.err = err.str();
  return r;
}

using test_support::CliResult;
using test_support::quoted;
using test_support::runCli;

std::vector<fs::path> frameFiles(const fs::path& run) {
  std::vector<fs::path> files;
  if (!fs::exists(run / "frames")) return files;
  for (const auto& e : fs::directory_iterator(run / "frames")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every byte of every regular file under `dir`, keyed by relative path.
std::map<std::string, std::string> snapshotTree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

void expectSameDiagnostics(const std::vector<DiagnosticsRow>& a, const std::vector<DiagnosticsRow>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("diagnostics row " + std::to_string(i));
    EXPECT_EQ(a[i].time, b[i].time);
    EXPECT_EQ(a[i].step, b[i].step);
    EXPECT_EQ(a[i].dt, b[i].dt);
    EXPECT_EQ(a[i].liquid, b[i].liquid);
    EXPECT_EQ(a[i].gas, b[i].gas);
    EXPECT_EQ(a[i].wall, b[i].wall);
    EXPECT_EQ(a[i].dummy, b[i].dummy);
    EXPECT_EQ(a[i].escaped, b[i].escaped);
    EXPECT_EQ(a[i].max_speed, b[i].max_speed);
    EXPECT_EQ(a[i].kinetic_energy, b[i].kinetic_energy);
    EXPECT_EQ(a[i].ppe_iterations, b[i].ppe_iterations);
    EXPECT_EQ(a[i].ppe_residual, b[i].ppe_residual);
  }
}

void expectSamePvd(const fs::path& a, const fs::path& b) {
  PvdCollection ca(a), cb(b);
  ca.load();
  cb.load();
  ASSERT_EQ(ca.entries().size(), cb.entries().size());
  for (std::size_t i = 0; i < ca.entries().size(); ++i) {
    EXPECT_EQ(ca.entries()[i].time, cb.entries()[i].time) << "pvd entry " << i;
    EXPECT_EQ(ca.entries()[i].file, cb.entries()[i].file) << "pvd entry " << i;
  }
}

using test_support::expectSameParticles;

constexpr std::size_t kDamBreakFluid = 200;

// ---------------------------------------------------------------------------------------------------------
// 1. Resume and thread-count independence, for each pressure scheme (numerics.scheme; the stabilised one keeps no
// state outside the checkpoint: its deferred terms come from the saved pressure).

struct SchemeCase {
  const char* name;
  const char* numerics;  // appended to the case's [numerics]
};
const SchemeCase kSchemes[] = {
    {"paper", ""},
    {"stabilised", "scheme = \"stabilised\"\npressure_source = \"mixed\"\nsource_relaxation = 0.0\n"
                   "collision_distance = 0.8\n"},
};
class SimulateScheme : public ::testing::TestWithParam<SchemeCase> {};
INSTANTIATE_TEST_SUITE_P(Schemes, SimulateScheme, ::testing::ValuesIn(kSchemes),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_P(SimulateScheme, InterruptedAndResumedRunIsBitIdentical) {
  const fs::path dir = freshDir(std::string("resume_") + GetParam().name);
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.1, 0.02, GetParam().numerics));
  const fs::path run_a = dir / "a", run_b = dir / "b";

  ASSERT_EQ(0, simulate(options(case_file, run_a)).code);

  SimulateOptions first = options(case_file, run_b);
  first.until = 0.04;
  ASSERT_EQ(0, simulate(first).code);
  EXPECT_NEAR(readCheckpoint<2>(run_b / "checkpoint.bin").time, 0.04, 1e-12);
  EXPECT_EQ(3u, frameFiles(run_b).size());

  SimulateOptions resume;
  resume.out_dir = run_b;
  resume.resume = true;
  resume.threads = 1;
  resume.force_plain_progress = true;
  const Captured resumed = simulate(resume);
  ASSERT_EQ(0, resumed.code) << resumed.err;

  // The checkpoints agree byte for byte, and so do the frames (the last one above all).
  const std::string ckpt_a = slurp(run_a / "checkpoint.bin");
  ASSERT_FALSE(ckpt_a.empty());
  EXPECT_TRUE(ckpt_a == slurp(run_b / "checkpoint.bin")) << "final checkpoints differ";
  EXPECT_NEAR(readCheckpoint<2>(run_a / "checkpoint.bin").time, 0.1, 1e-12);

  const auto frames_a = frameFiles(run_a), frames_b = frameFiles(run_b);
  ASSERT_EQ(6u, frames_a.size());
  ASSERT_EQ(frames_a.size(), frames_b.size());
  EXPECT_EQ("frame_00005.vtp", frames_a.back().filename().string());
  for (std::size_t i = 0; i < frames_a.size(); ++i) {
    EXPECT_EQ(frames_a[i].filename(), frames_b[i].filename());
    EXPECT_TRUE(slurp(frames_a[i]) == slurp(frames_b[i])) << frames_a[i].filename() << " differs";
  }

  expectSameDiagnostics(DiagnosticsWriter::read(run_a / "diagnostics.csv"),
                        DiagnosticsWriter::read(run_b / "diagnostics.csv"));
  expectSamePvd(run_a / "frames.pvd", run_b / "frames.pvd");
  PvdCollection pvd(run_b / "frames.pvd");
  pvd.load();
  EXPECT_EQ(6u, pvd.entries().size());
}

TEST(SimulateResume, ResumingAFinishedRunChangesNothing) {
  const fs::path dir = freshDir("resume_finished");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  const fs::path run = dir / "run";
  ASSERT_EQ(0, simulate(options(case_file, run)).code);
  const auto before = snapshotTree(run);

  SimulateOptions resume;
  resume.out_dir = run;
  resume.resume = true;
  resume.threads = 1;
  resume.force_plain_progress = true;
  ASSERT_EQ(0, simulate(resume).code);
  const auto after = snapshotTree(run);
  ASSERT_EQ(before.size(), after.size());
  for (const auto& [name, bytes] : before) {
    if (name == "diagnostics.csv") continue;  // rewritten (same rows)
    EXPECT_TRUE(after.count(name) && after.at(name) == bytes) << name << " changed";
  }
  EXPECT_EQ(DiagnosticsWriter::read(run / "diagnostics.csv").size(), 3u);
}

TEST(SimulateResume, ResumeWithoutCheckpointIsBadInput) {
  const fs::path dir = freshDir("resume_missing");
  SimulateOptions resume;
  resume.out_dir = dir;
  resume.resume = true;
  resume.force_plain_progress = true;
  const Captured r = simulate(resume);
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("checkpoint.bin"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_P(SimulateScheme, OneAndTwoThreadsGiveIdenticalRuns) {
  const fs::path dir = freshDir(std::string("threads_") + GetParam().name);
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.1, 0.02, GetParam().numerics));
  ASSERT_EQ(0, simulate(options(case_file, dir / "t1", 1)).code);
  ASSERT_EQ(0, simulate(options(case_file, dir / "t2", 2)).code);

  EXPECT_TRUE(slurp(dir / "t1" / "checkpoint.bin") == slurp(dir / "t2" / "checkpoint.bin"))
      << "checkpoints with 1 and 2 threads differ";
  const auto f1 = frameFiles(dir / "t1"), f2 = frameFiles(dir / "t2");
  ASSERT_EQ(f1.size(), f2.size());
  for (std::size_t i = 0; i < f1.size(); ++i)
    EXPECT_TRUE(slurp(f1[i]) == slurp(f2[i])) << f1[i].filename() << " differs between 1 and 2 threads";
  expectSameDiagnostics(DiagnosticsWriter::read(dir / "t1" / "diagnostics.csv"),
                        DiagnosticsWriter::read(dir / "t2" / "diagnostics.csv"));
}

// ---------------------------------------------------------------------------------------------------------
// 2. Particle bookkeeping

TEST(SimulateParticles, CountsAreConservedInTheDamBreak) {
  const fs::path dir = freshDir("conserve_dam");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.1, 0.02));
  const fs::path run = dir / "run";
  ASSERT_EQ(0, simulate(options(case_file, run)).code);

  const auto rows = DiagnosticsWriter::read(run / "diagnostics.csv");
  ASSERT_EQ(6u, rows.size());
  EXPECT_GT(rows[0].wall, 0u);
  EXPECT_GT(rows[0].dummy, 0u);
  for (const auto& row : rows) {
    SCOPED_TRACE("t = " + std::to_string(row.time));
    EXPECT_EQ(kDamBreakFluid, row.liquid + row.gas + row.escaped);
    EXPECT_EQ(rows[0].wall, row.wall);
    EXPECT_EQ(rows[0].dummy, row.dummy);
  }
  EXPECT_GT(rows.back().max_speed, 0.0);
  EXPECT_GT(rows.back().step, 0);

  // The last frame holds the particles the last row counts.
  const auto last = readVtp<2>(frameFiles(run).back());
  EXPECT_EQ(rows.back().liquid + rows.back().gas, last.count(ParticleKind::Fluid));
  EXPECT_EQ(rows.back().escaped, last.count(ParticleKind::Escaped));
  EXPECT_EQ(rows.back().wall, last.count(ParticleKind::Wall));
  EXPECT_EQ(rows.back().dummy, last.count(ParticleKind::Dummy));
}

TEST(SimulateParticles, EscapedParticlesAreStillCounted) {
  const fs::path dir = freshDir("conserve_escape");
  const fs::path case_file = writeCase(dir, "case.toml", fallingBlockCase(1.0, 0.1));
  const fs::path run = dir / "run";
  const Captured r = simulate(options(case_file, run));
  ASSERT_EQ(0, r.code) << r.err;

  const auto rows = DiagnosticsWriter::read(run / "diagnostics.csv");
  ASSERT_EQ(6u, rows.size());
  EXPECT_EQ(0u, rows.front().escaped);
  EXPECT_GT(rows.back().escaped, 0u) << "the case should let some water fall out of the domain";
  for (const auto& row : rows) {
    SCOPED_TRACE("t = " + std::to_string(row.time));
    EXPECT_EQ(100u, row.liquid + row.gas + row.escaped);
    EXPECT_EQ(0u, row.wall);
    EXPECT_EQ(0u, row.dummy);
  }
  const auto last = readVtp<2>(frameFiles(run).back());
  EXPECT_EQ(100u, last.size());
  EXPECT_EQ(rows.back().escaped, last.count(ParticleKind::Escaped));
}

// ---------------------------------------------------------------------------------------------------------
// 3. Bad input writes nothing

struct BadCase {
  const char* label;
  std::string text;
  const char* must_mention;
};

std::vector<BadCase> badCases() {
  std::string overlapping = damBreakCase(0.1, 0.02);
  overlapping += R"(
[[region]]
name = "second_column"
material = "water"
min = [0.05, 0.1]
max = [0.15, 0.25]
)";
  return {
      {"out_of_range", damBreakCase(0.1, 0.02, "courant = 2\n"), "numerics.courant"},
      {"unknown_key", damBreakCase(0.1, 0.02, "courrant = 0.1\n"), "numerics.courrant"},
      {"overlap", overlapping, "overlaps"},
  };
}

TEST(SimulateBadInput, ReturnsOneAndCreatesNoRunDirectory) {
  const fs::path dir = freshDir("bad_input");
  for (const auto& bad : badCases()) {
    SCOPED_TRACE(bad.label);
    const fs::path case_file = writeCase(dir, std::string(bad.label) + ".toml", bad.text);
    const fs::path out = dir / (std::string(bad.label) + "_parent") / "run";
    const Captured r = simulate(options(case_file, out));
    EXPECT_EQ(1, r.code);
    EXPECT_NE(r.err.find(bad.must_mention), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.parent_path()));
  }
  // A bad --until is bad input too.
  const fs::path good = writeCase(dir, "good.toml", damBreakCase(0.1, 0.02));
  SimulateOptions o = options(good, dir / "bad_until");
  o.until = -1.0;
  EXPECT_EQ(1, simulate(o).code);
  EXPECT_FALSE(fs::exists(dir / "bad_until"));
  // So is one past the case's end_time (0.1 s), which would stop at end_time without saying so.
  o.until = 0.5;
  const Captured past = simulate(o);
  EXPECT_EQ(1, past.code);
  EXPECT_NE(past.err.find("output.end_time"), std::string::npos) << past.err;
  EXPECT_FALSE(fs::exists(dir / "bad_until"));
  // So is a missing case file.
  const Captured missing = simulate(options(dir / "no_such_case.toml", dir / "missing_case"));
  EXPECT_EQ(1, missing.code);
  EXPECT_NE(missing.err.find("no_such_case.toml"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "missing_case"));
}

TEST(CliBadInput, ExitsOneNamesTheKeyAndCreatesNothing) {
  const fs::path dir = freshDir("cli_bad_input");
  for (const auto& bad : badCases()) {
    SCOPED_TRACE(bad.label);
    const fs::path case_file = writeCase(dir, std::string(bad.label) + ".toml", bad.text);
    const fs::path out = dir / (std::string(bad.label) + "_run");
    const CliResult r = runCli("simulate " + quoted(case_file) + " --out " + quoted(out) + " --threads 1");
    EXPECT_EQ(1, r.code) << r.err;
    EXPECT_NE(r.err.find(bad.must_mention), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// ---------------------------------------------------------------------------------------------------------
// 4. Run-directory protection

TEST(SimulateOverwrite, RefusesANonEmptyRunDirectoryAndReplacesItWithOverwrite) {
  const fs::path dir = freshDir("overwrite");
  const fs::path long_case = writeCase(dir, "long.toml", damBreakCase(0.1, 0.02));
  const fs::path short_case = writeCase(dir, "short.toml", damBreakCase(0.04, 0.02));
  const fs::path run = dir / "run";

  // An existing empty directory is fine.
  fs::create_directories(run);
  ASSERT_EQ(0, simulate(options(long_case, run)).code);
  ASSERT_EQ(6u, frameFiles(run).size());
  const auto before = snapshotTree(run);

  // A second run into it is refused, and nothing changes.
  const Captured refused = simulate(options(short_case, run));
  EXPECT_EQ(1, refused.code);
  EXPECT_NE(refused.err.find("overwrite"), std::string::npos) << refused.err;
  EXPECT_TRUE(before == snapshotTree(run)) << "a refused run changed the run directory";

  // A directory holding anything at all (not only a run) is refused too.
  const fs::path other = dir / "other";
  fs::create_directories(other);
  std::ofstream(other / "notes.txt") << "keep me\n";
  EXPECT_EQ(1, simulate(options(short_case, other)).code);
  EXPECT_EQ("keep me\n", slurp(other / "notes.txt"));
  EXPECT_EQ(1u, snapshotTree(other).size());

  // With overwrite the run is replaced: the stale frames of the longer run are gone.
  SimulateOptions o = options(short_case, run);
  o.overwrite = true;
  const Captured replaced = simulate(o);
  ASSERT_EQ(0, replaced.code) << replaced.err;
  EXPECT_EQ(3u, frameFiles(run).size());
  EXPECT_EQ(3u, DiagnosticsWriter::read(run / "diagnostics.csv").size());
  PvdCollection pvd(run / "frames.pvd");
  pvd.load();
  EXPECT_EQ(3u, pvd.entries().size());
  EXPECT_NEAR(readCheckpoint<2>(run / "checkpoint.bin").time, 0.04, 1e-12);
  EXPECT_EQ(slurp(short_case), slurp(run / "case.toml"));
}

TEST(SimulateOverwrite, AnOutputPathThatIsAFileIsBadInput) {
  const fs::path dir = freshDir("out_is_file");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  const fs::path empty_file = dir / "empty_file", full_file = dir / "full_file";
  std::ofstream(empty_file).close();
  std::ofstream(full_file) << "data\n";
  for (bool overwrite : {false, true}) {
    SCOPED_TRACE(overwrite ? "overwrite" : "no overwrite");
    for (const fs::path& out : {empty_file, full_file, full_file / "run"}) {
      SCOPED_TRACE(out.string());
      SimulateOptions o = options(case_file, out);
      o.overwrite = overwrite;
      const Captured r = simulate(o);
      EXPECT_EQ(1, r.code) << r.err;
      EXPECT_FALSE(r.err.empty());
    }
  }
  EXPECT_TRUE(fs::is_regular_file(empty_file));
  EXPECT_EQ("", slurp(empty_file));
  EXPECT_EQ("data\n", slurp(full_file));

  const CliResult cli = runCli("simulate " + quoted(case_file) + " --out " + quoted(full_file / "run"));
  EXPECT_EQ(1, cli.code) << cli.err;
  EXPECT_EQ("data\n", slurp(full_file));
}

// ---------------------------------------------------------------------------------------------------------
// 5. Divergence

void expectDivergedRunIsReadable(const fs::path& run) {
  PvdCollection pvd(run / "frames.pvd");
  pvd.load();
  ASSERT_GE(pvd.entries().size(), 2u);
  const auto frames = frameFiles(run);
  ASSERT_EQ(pvd.entries().size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    double t = -1;
    const auto p = readVtp<2>(run / pvd.entries()[i].file, &t);
    EXPECT_EQ(100u, p.size());
    EXPECT_NEAR(0.02 * static_cast<double>(i), t, 1e-12);
    EXPECT_EQ(pvd.entries()[i].time, t);
  }
  const auto ckpt = readCheckpoint<2>(run / "checkpoint.bin");
  EXPECT_EQ(pvd.entries().back().time, ckpt.time);
  EXPECT_EQ(static_cast<int>(frames.size()), ckpt.next_frame);
  const auto rows = DiagnosticsWriter::read(run / "diagnostics.csv");
  ASSERT_EQ(frames.size(), rows.size());
  EXPECT_EQ(ckpt.time, rows.back().time);
  EXPECT_EQ(ckpt.step, rows.back().step);
  for (const auto& e : fs::recursive_directory_iterator(run))
    EXPECT_NE(".tmp", e.path().extension().string()) << e.path();
}

TEST(SimulateDivergence, StopsWithCodeThreeAndKeepsTheFrames) {
  const fs::path dir = freshDir("diverge");
  const fs::path case_file = writeCase(dir, "case.toml", fallingBlockCase(0.1, 0.2));
  const fs::path run = dir / "run";
  const Captured r = simulate(options(case_file, run));
  EXPECT_EQ(3, r.code) << r.err;
  EXPECT_NE(r.err.find("diverged at t ="), std::string::npos) << r.err;
  expectDivergedRunIsReadable(run);
  // It diverged between the last frame and the next output time.
  const auto ckpt = readCheckpoint<2>(run / "checkpoint.bin");
  EXPECT_LT(ckpt.time, 0.2);
  // diverged.txt records the time (after the last frame), the step and the reason.
  std::ifstream record(run / "diverged.txt");
  ASSERT_TRUE(record) << "no diverged.txt";
  std::string time_key, eq, step_key, eq2;
  double time = 0.0;
  long step = 0;
  record >> time_key >> eq >> time >> step_key >> eq2 >> step;
  EXPECT_EQ("time", time_key);
  EXPECT_GT(time, ckpt.time);
  EXPECT_EQ("step", step_key);
  EXPECT_GT(step, ckpt.step);
  // Then the steps before it: consecutive, ending with the one that diverged. The block falls freely out of the
  // domain, so each step's fastest particle is water at g t.
  std::string line, header;
  std::vector<std::vector<std::string>> steps;
  while (std::getline(record, line)) {
    if (line.rfind("time,step,dt,id,role,x,y,speed,pressure", 0) == 0) header = line;
    if (header.empty() || line == header || line.empty()) continue;
    const std::vector<std::string> fields = csvFields(line);
    ASSERT_EQ(9u, fields.size()) << line;
    steps.push_back(fields);
  }
  ASSERT_FALSE(header.empty()) << "no table of the last steps";
  ASSERT_FALSE(steps.empty());
  EXPECT_LE(steps.size(), 200u);
  for (std::size_t k = 1; k < steps.size(); ++k) EXPECT_EQ(std::stol(steps[k][1]), std::stol(steps[k - 1][1]) + 1);
  EXPECT_LE(step - std::stol(steps.back()[1]), 1);
  EXPECT_GE(step - std::stol(steps.back()[1]), 0);
  for (const auto& s : steps) {
    EXPECT_EQ("liquid", s[4]);
    EXPECT_NEAR(9.81 * std::stod(s[0]), std::stod(s[7]), 1e-6 + 1e-3 * 9.81 * std::stod(s[0])) << "t = " << s[0];
  }
  // Overwriting the run removes the stale record with the rest of the old run.
  auto again = options(case_file, run);
  again.overwrite = true;
  again.until = ckpt.time / 2.0;
  EXPECT_EQ(0, simulate(again).code);
  EXPECT_FALSE(fs::exists(run / "diverged.txt"));
}

TEST(CliDivergence, ReportsTimeAndStepOnStderr) {
  const fs::path dir = freshDir("cli_diverge");
  const fs::path case_file = writeCase(dir, "case.toml", fallingBlockCase(0.1, 0.2));
  const fs::path run = dir / "run";
  const CliResult r =
      runCli("simulate " + quoted(case_file) + " --out " + quoted(run) + " --threads 1 --plain-progress");
  EXPECT_EQ(3, r.code) << r.err;
  const auto at = r.err.find("diverged at t = ");
  ASSERT_NE(at, std::string::npos) << r.err;
  // A number follows "t = ", then the step.
  const std::string rest = r.err.substr(at + std::strlen("diverged at t = "));
  char* end = nullptr;
  const double t = std::strtod(rest.c_str(), &end);
  EXPECT_NE(end, rest.c_str()) << r.err;
  const auto ckpt = readCheckpoint<2>(run / "checkpoint.bin");
  EXPECT_GT(t, ckpt.time);
  EXPECT_LT(t, ckpt.time + 0.02 + 1e-9);
  EXPECT_NE(rest.find("step"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("max_escaped_fraction"), std::string::npos) << r.err;
  expectDivergedRunIsReadable(run);
}

// ---------------------------------------------------------------------------------------------------------
// 6. Command line

TEST(CliVersion, PrintsTheVersion) {
  const CliResult r = runCli("--version");
  EXPECT_EQ(0, r.code);
  EXPECT_NE(r.out.find(MISTFALL_VERSION), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mistfall"), std::string::npos) << r.out;
}

TEST(CliHelp, SimulateHelpMentionsResume) {
  const CliResult r = runCli("simulate --help");
  EXPECT_EQ(0, r.code);
  EXPECT_NE(r.out.find("--resume"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--out"), std::string::npos) << r.out;
}

TEST(CliArguments, CaseFileAndResumeTogetherIsAnError) {
  const fs::path dir = freshDir("cli_both");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  const fs::path run = dir / "run";
  fs::create_directories(run);
  const CliResult r = runCli("simulate " + quoted(case_file) + " --resume " + quoted(run));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(run));
}

TEST(CliArguments, MissingCaseFileIsAnError) {
  const fs::path dir = freshDir("cli_missing");
  const CliResult r = runCli("simulate " + quoted(dir / "nope.toml") + " --out " + quoted(dir / "run"));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("nope.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "run"));
}

TEST(CliArguments, MissingOutIsAnError) {
  const fs::path dir = freshDir("cli_no_out");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  const CliResult r = runCli("simulate " + quoted(case_file));
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

TEST(CliArguments, UnknownOptionIsAnError) {
  const CliResult r = runCli("simulate --no-such-option");
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("no-such-option"), std::string::npos) << r.err;
}

TEST(CliArguments, NoSubcommandIsAnError) {
  const CliResult r = runCli("");
  EXPECT_EQ(1, r.code);
  EXPECT_NE(r.err.find("subcommand"), std::string::npos) << r.err;
}

TEST(CliSimulate, RunsAndResumesThroughTheExecutable) {
  const fs::path dir = freshDir("cli_run");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  const fs::path run = dir / "run";
  const CliResult first = runCli("simulate " + quoted(case_file) + " --out " + quoted(run) +
                                 " --until 0.02 --threads 1 --plain-progress");
  ASSERT_EQ(0, first.code) << first.err;
  EXPECT_EQ(2u, frameFiles(run).size());
  const CliResult resumed = runCli("simulate --resume " + quoted(run) + " --threads 1 --plain-progress");
  ASSERT_EQ(0, resumed.code) << resumed.err;
  EXPECT_EQ(3u, frameFiles(run).size());
  EXPECT_NEAR(readCheckpoint<2>(run / "checkpoint.bin").time, 0.04, 1e-12);
}

// --trace writes particle ID's stages and changes no result: the traced run's checkpoint is the untraced one's, byte
// for byte, and the trace's last row of the particle holds its place in that checkpoint.
TEST(CliSimulate, ATraceFollowsTheParticleAndChangesNoResult) {
  const fs::path dir = freshDir("cli_trace");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.02, 0.02));
  const std::string args = "simulate " + quoted(case_file) + " --threads 1 --plain-progress --out ";
  ASSERT_EQ(0, runCli(args + quoted(dir / "plain")).code);
  const CliResult traced = runCli(args + quoted(dir / "traced") + " --trace 5 --trace-from 0.01");
  ASSERT_EQ(0, traced.code) << traced.err;
  EXPECT_TRUE(slurp(dir / "plain" / "checkpoint.bin") == slurp(dir / "traced" / "checkpoint.bin"));

  std::ifstream in(dir / "traced" / "traces" / "trace_5.csv");
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(0u, line.rfind("time,step,stage,row,id,", 0)) << line;
  std::size_t self_rows = 0;
  std::vector<std::string> last;
  std::map<std::string, int> stages;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = csvFields(line);
    ASSERT_GE(cells.size(), 12u) << line;
    EXPECT_GE(std::stod(cells[0]), 0.01 - 1e-12);
    if (cells[3] != "self") continue;
    EXPECT_EQ("5", cells[4]);
    ++self_rows, ++stages[cells[2]], last = cells;
  }
  EXPECT_GT(self_rows, 0u);
  EXPECT_EQ(stages["predict"], stages["collision"]);  // every step's stages
  EXPECT_EQ(stages["predict"], stages["open boundaries"]);
  const auto state = readCheckpoint<2>(dir / "traced" / "checkpoint.bin");
  const auto& p = state.particles;
  const auto at = std::find(p.id.begin(), p.id.end(), 5u) - p.id.begin();
  ASSERT_LT(static_cast<std::size_t>(at), p.size());
  EXPECT_NEAR(p.position[at].x(), std::stod(last[9]), 1e-9);
  EXPECT_NEAR(p.position[at].y(), std::stod(last[10]), 1e-9);
}

TEST(CliSimulate, TraceFromWithoutTraceIsAnError) {
  const fs::path dir = freshDir("cli_trace_from");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.02, 0.02));
  const CliResult r = runCli("simulate " + quoted(case_file) + " --out " + quoted(dir / "run") + " --trace-from 0.01");
  EXPECT_NE(0, r.code);
  EXPECT_FALSE(fs::exists(dir / "run"));
}

// ---------------------------------------------------------------------------------------------------------
// 7. ASCII frames

TEST(SimulateAscii, AsciiFramesReadBackEqualToBinaryOnes) {
  const fs::path dir = freshDir("ascii");
  const fs::path case_file = writeCase(dir, "case.toml", damBreakCase(0.04, 0.02));
  ASSERT_EQ(0, simulate(options(case_file, dir / "binary")).code);
  SimulateOptions o = options(case_file, dir / "ascii");
  o.ascii = true;
  ASSERT_EQ(0, simulate(o).code);

  const auto binary = frameFiles(dir / "binary"), ascii = frameFiles(dir / "ascii");
  ASSERT_EQ(3u, binary.size());
  ASSERT_EQ(binary.size(), ascii.size());
  for (std::size_t i = 0; i < binary.size(); ++i) {
    SCOPED_TRACE(binary[i].filename().string());
    const std::string ascii_text = slurp(ascii[i]);
    EXPECT_NE(ascii_text.find("format=\"ascii\""), std::string::npos);
    EXPECT_EQ(ascii_text.find("AppendedData"), std::string::npos);
    EXPECT_NE(slurp(binary[i]).find("AppendedData"), std::string::npos);
    double tb = -1, ta = -2;
    const auto pb = readVtp<2>(binary[i], &tb);
    const auto pa = readVtp<2>(ascii[i], &ta);
    EXPECT_EQ(tb, ta);
    // ASCII doubles are written with 17 significant digits, so they read back exactly.
    expectSameParticles(pb, pa);
  }
  // The checkpoints do not depend on the frame format.
  EXPECT_TRUE(slurp(dir / "binary" / "checkpoint.bin") == slurp(dir / "ascii" / "checkpoint.bin"));
}

}  // namespace

// output.field_spacing > 0: every frame also writes fields/fields_NNNNN.vti (io/grid_fields.hpp) on that grid over
// the domain, with the liquid's velocity where the water is and none where it is not.
TEST(SimulateFields, FieldsAreWrittenPerFrameOnTheRequestedGrid) {
  const fs::path dir = freshDir("fields");
  std::string text = damBreakCase(0.04, 0.02);
  text.replace(text.find("interval = 0.02"), std::strlen("interval = 0.02"), "interval = 0.02\nfield_spacing = 0.02");
  const fs::path case_file = writeCase(dir, "case.toml", text);
  const fs::path run = dir / "run";
  const Captured r = simulate(options(case_file, run));
  ASSERT_EQ(0, r.code) << r.err;
  for (int k = 0; k < 3; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "fields_%05d.vti", k);
    ASSERT_TRUE(fs::exists(run / "fields" / name)) << name;
  }
  const ImageData image = readVti(run / "fields" / "fields_00002.vti");
  EXPECT_NEAR(0.04, image.time, 1e-12);
  EXPECT_DOUBLE_EQ(0.02, image.spacing[0]);
  EXPECT_EQ(20, image.dims[0]);  // (0.34 - (-0.04)) / 0.02 + 1 nodes
  const GridArray* coverage = image.find("liquid_coverage");
  const GridArray* velocity = image.find("liquid_velocity");
  ASSERT_TRUE(coverage && velocity);
  // Node (x, y) = (0.04, 0.06) lies in the falling column, (0.3, 0.26) far from any water.
  auto node = [&](double x, double y) {
    const auto i = static_cast<std::size_t>(std::lround((x - image.origin[0]) / image.spacing[0]));
    const auto j = static_cast<std::size_t>(std::lround((y - image.origin[1]) / image.spacing[1]));
    return i + static_cast<std::size_t>(image.dims[0]) * j;
  };
  EXPECT_GT(coverage->values[node(0.04, 0.06)], 0.0);
  EXPECT_EQ(0.0, coverage->values[node(0.3, 0.26)]);
  EXPECT_LT(velocity->values[3 * node(0.04, 0.06) + 1], 0.0);  // the column is falling at t = 0.04 s
}
