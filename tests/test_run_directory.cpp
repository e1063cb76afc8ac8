// What a run directory guarantees: one mistfall command at a time works on it (a second is refused naming the
// holder's pid, also after the holder was killed the lock is free again), --overwrite removes everything mistfall
// derived from the old run and keeps what it did not write, a resume is refused when its checkpoint was written
// for another case (naming what differs) and allowed after harmless edits, and render redoes images older than
// their inputs and drops images of frames the run no longer has.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/run_lock.hpp"
#include "support/run_dir.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::CliResult;
using test_support::quoted;
using test_support::runCli;
using test_support::scratchRoot;
using test_support::slurp;
using test_support::snapshot;
using test_support::tinyRun;

namespace {

fs::path tinyCase() { return scratchRoot() / "tiny_run_case.toml"; }

std::string withRun(std::string command, const fs::path& run) {
  for (std::size_t at; (at = command.find("RUN")) != std::string::npos;) command.replace(at, 3, run.string());
  for (std::size_t at; (at = command.find("CASE")) != std::string::npos;) command.replace(at, 4, tinyCase().string());
  return command + " --plain-progress";
}

const char* const kEveryCommand[] = {"simulate CASE --out RUN --overwrite", "simulate --resume RUN", "classify RUN",
                                     "texture RUN --overwrite", "render RUN --preview", "run CASE --out RUN --overwrite"};

TEST(RunDirectoryLock, EveryCommandIsRefusedWhileAnotherHoldsTheRun) {
  const fs::path run = tinyRun("locked");
  {
    const RunDirLock lock(run, "test holder");  // held by this process; the commands below are other processes
    const auto before = snapshot(run);
    for (const char* command : kEveryCommand) {
      SCOPED_TRACE(command);
      const CliResult r = runCli(withRun(command, run));
      EXPECT_EQ(1, r.code) << r.err;
      EXPECT_NE(r.err.find("is in use by pid " + std::to_string(::getpid()) + " (mistfall test holder)"),
                std::string::npos)
          << r.err;
      EXPECT_TRUE(before == snapshot(run)) << "a refused command changed the run directory";
    }
  }
  const CliResult freed = runCli(withRun("classify RUN", run));
  EXPECT_EQ(0, freed.code) << freed.err;
}

// A holder killed with SIGKILL leaves the lock file, not the lock.
TEST(RunDirectoryLock, AKilledHolderReleasesTheLock) {
  const fs::path run = tinyRun("killed_holder");
  int ready[2];
  ASSERT_EQ(0, ::pipe(ready));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const RunDirLock lock(run, "child");
    (void)!::write(ready[1], "x", 1);
    ::pause();
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(1, ::read(ready[0], &c, 1));
  const CliResult held = runCli(withRun("classify RUN", run));
  EXPECT_EQ(1, held.code);
  EXPECT_NE(held.err.find("is in use by pid " + std::to_string(child) + " (mistfall child)"), std::string::npos)
      << held.err;
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  const CliResult freed = runCli(withRun("classify RUN", run));
  EXPECT_EQ(0, freed.code) << freed.err;
  EXPECT_TRUE(fs::exists(run / ".mistfall.lock"));
}

// Within one process the lock is counted: `mistfall run` holds it across its stages.
TEST(RunDirectoryLock, AProcessMayTakeItsOwnLockAgain) {
  const fs::path run = tinyRun("nested");
  const RunDirLock outer(run, "outer");
  { const RunDirLock inner(run, "inner"); }
  EXPECT_NO_THROW(RunDirLock::checkFree(run));
  EXPECT_NE(slurp(run / ".mistfall.lock").find("(mistfall outer)"), std::string::npos);
}

TEST(RunDirectoryOverwrite, RemovesEverythingMistfallDerivedAndKeepsTheRest) {
  const fs::path run = tinyRun("overwrite_all");
  for (const char* f : {"categories.csv", "texture/texture_00000.bin", "render/png/frame_00009.png",
                        "render/small_dam_break.mp4", "plots/frame_00002.png", "fields/fields_00009.vti",
                        "frames/frame_00009.vtp", "diverged.txt", "case_changes.txt", "notes.txt", "mine/keep.txt"}) {
    fs::create_directories((run / f).parent_path());
    std::ofstream(run / f) << "old\n";
  }
  const fs::path short_case = test_support::writeCaseFile(scratchRoot() / "short.toml",
                                                          test_support::damBreakCase(0.02, 0.02));
  const CliResult r = runCli("simulate " + quoted(short_case) + " --out " + quoted(run) +
                             " --overwrite --threads 1 --plain-progress");
  ASSERT_EQ(0, r.code) << r.err;
  for (const char* gone : {"categories.csv", "texture", "render", "plots", "fields", "diverged.txt", "case_changes.txt",
                           "frames/frame_00002.vtp", "frames/frame_00009.vtp"})
    EXPECT_FALSE(fs::exists(run / gone)) << gone;
  EXPECT_TRUE(fs::exists(run / "frames/frame_00001.vtp"));
  EXPECT_EQ("old\n", slurp(run / "notes.txt"));
  EXPECT_EQ("old\n", slurp(run / "mine/keep.txt"));
  EXPECT_NE(r.err.find("kept what mistfall did not write: mine, notes.txt"), std::string::npos) << r.err;
}

// ---------------------------------------------------------------------------------------------------------
// Resume

void editCase(const fs::path& run, const std::string& from, const std::string& to) {
  std::string text = slurp(run / "case.toml");
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(run / "case.toml", std::ios::binary | std::ios::trunc) << text;
}

struct ResumeEdit {
  const char* label;
  const char* from;
  const char* to;
  const char* refusal;  // the key named; null: the resume goes on
};

TEST(RunDirectoryResume, EditsThatChangeTheSimulationAreRefusedNamingTheKey) {
  const ResumeEdit edits[] = {
      {"l0", "particle_spacing = 0.01", "particle_spacing = 0.008",
       "numerics.particle_spacing = 0.01 in the checkpoint, 0.008 in case.toml"},
      {"density", "[physics]\n", "[physics]\nliquid = { density = 998.0 }\n",
       "physics.liquid.density = (absent) in the checkpoint, 998 in case.toml"},
      {"interval", "interval = 0.02", "interval = 0.01", "output.interval = 0.02 in the checkpoint, 0.01"},
      {"a region", "max = [0.1, 0.2]", "max = [0.1, 0.21]", "region[0].max"},
      {"harmless: end time, classify, render, name", "end_time = 0.04\ninterval = 0.02\nfield_spacing = 0.05\n",
       "end_time = 0.06\ninterval = 0.02\nfield_spacing = 0.05\n[classify]\nsurface_gradient = 0.5\n[render]\n"
       "image_width = 320\n", nullptr},
  };
  for (const ResumeEdit& e : edits) {
    SCOPED_TRACE(e.label);
    const fs::path run = tinyRun("resume_edit");
    editCase(run, e.from, e.to);
    const auto before = snapshot(run);
    const CliResult r = runCli("simulate --resume " + quoted(run) + " --threads 1 --plain-progress");
    if (e.refusal) {
      EXPECT_EQ(1, r.code) << r.err;
      EXPECT_NE(r.err.find("its checkpoint was written for another case"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(e.refusal), std::string::npos) << r.err;
      EXPECT_TRUE(before == snapshot(run)) << "a refused resume changed the run directory";
    } else {
      EXPECT_EQ(0, r.code) << r.err;
      EXPECT_NE(r.err.find("keys that do not change the simulation"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("classify.surface_gradient = (absent) in the checkpoint, 0.5"), std::string::npos) << r.err;
      EXPECT_TRUE(fs::exists(run / "frames/frame_00003.vtp"));
    }
  }
}

// --accept-case-change (a developer's what-if on a copy of a run): the edit the test above refuses goes on, is named
// in a note and recorded in case_changes.txt with the time it took effect, and the next checkpoint carries the
// edited case, so a plain --resume of the run goes on; without --resume the flag is refused.
TEST(RunDirectoryResume, AcceptCaseChangeGoesOnAndRecordsTheChange) {
  const fs::path run = tinyRun("accept_change");
  editCase(run, "end_time = 0.04", "end_time = 0.08");
  editCase(run, "[physics]\n", "[physics]\nliquid = { density = 998.0 }\n");
  CliResult r = runCli("simulate --resume " + quoted(run) + " --accept-case-change --until 0.06 --threads 1 "
                       "--plain-progress");
  ASSERT_EQ(0, r.code) << r.err;
  EXPECT_NE(r.err.find("accepted by --accept-case-change: from t = 0.04"), std::string::npos) << r.err;
  const std::string record = slurp(run / "case_changes.txt");
  EXPECT_NE(record.find("resumed at t = 0.04"), std::string::npos) << record;
  EXPECT_NE(record.find("physics.liquid.density = (absent) in the checkpoint, 998 in case.toml"), std::string::npos)
      << record;
  r = runCli("simulate --resume " + quoted(run) + " --threads 1 --plain-progress");
  EXPECT_EQ(0, r.code) << r.err;
  EXPECT_TRUE(fs::exists(run / "frames/frame_00004.vtp"));
  EXPECT_EQ(record, slurp(run / "case_changes.txt"));  // nothing changed since: nothing added
  // the output interval numbers the frames: changing it is refused even with the flag, before anything is written
  // (a finer interval had left the resume stepping nowhere, forever)
  const fs::path fine = tinyRun("accept_interval");
  editCase(fine, "interval = 0.02", "interval = 0.01");
  const auto untouched = snapshot(fine);
  r = runCli("simulate --resume " + quoted(fine) + " --accept-case-change --threads 1 --plain-progress");
  EXPECT_EQ(1, r.code) << r.err;
  EXPECT_NE(r.err.find("output.interval changed"), std::string::npos) << r.err;
  EXPECT_TRUE(untouched == snapshot(fine)) << "a refused resume changed the run directory";
  r = runCli("simulate " + quoted(run / "case.toml") + " --out " + quoted(scratchRoot() / "accept_new") +
             " --accept-case-change --threads 1");
  EXPECT_EQ(1, r.code) << r.err;
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratchRoot() / "accept_new"));
}

TEST(RunDirectoryResume, ACheckpointFromAnotherRunIsRefused) {
  // Another case (l0 = 0.008): its checkpoint copied into the tiny run.
  const fs::path other_case = test_support::writeCaseFile(scratchRoot() / "other.toml",
      [] { std::string t = test_support::tinyRunCase(); t.replace(t.find("0.01\n"), 5, "0.008\n"); return t; }());
  const fs::path other = scratchRoot() / "other_run";
  ASSERT_EQ(0, runCli("simulate " + quoted(other_case) + " --out " + quoted(other) + " --until 0.02 --threads 1 "
                      "--plain-progress").code);
  const fs::path run = tinyRun("foreign_checkpoint");
  fs::copy_file(other / "checkpoint.bin", run / "checkpoint.bin", fs::copy_options::overwrite_existing);
  CliResult r = runCli("simulate --resume " + quoted(run) + " --plain-progress");
  EXPECT_EQ(1, r.code) << r.err;
  EXPECT_NE(r.err.find("numerics.particle_spacing = 0.008 in the checkpoint, 0.01 in case.toml"), std::string::npos)
      << r.err;

  // The same simulation run further (to 0.06 s; its end_time differs, which is harmless): a checkpoint later
  // than the run's frames.
  const fs::path longer_case = test_support::writeCaseFile(scratchRoot() / "longer.toml",
                                                           test_support::damBreakCase(0.06, 0.02, "", "field_spacing = 0.05\n"));
  const fs::path longer = scratchRoot() / "longer_run";
  ASSERT_EQ(0, runCli("simulate " + quoted(longer_case) + " --out " + quoted(longer) + " --threads 1 "
                      "--plain-progress").code);
  fs::copy_file(longer / "checkpoint.bin", run / "checkpoint.bin", fs::copy_options::overwrite_existing);
  r = runCli("simulate --resume " + quoted(run) + " --plain-progress");
  EXPECT_EQ(1, r.code) << r.err;
  EXPECT_NE(r.err.find(" s, 4 frames written) does not match " +
                       (run / "frames.pvd").string() + ": it lists 3 frames up to that time"),
            std::string::npos)
      << r.err;
}

// ---------------------------------------------------------------------------------------------------------
// Render

TEST(RunDirectoryRender, ImagesOlderThanTheirFrameAreRenderedAgainAndOrphansRemoved) {
  const fs::path run = tinyRun("render_stale");
  fs::remove_all(run / "frames/frame_00002.vtp");  // two frames are enough
  const std::string render = "render " + quoted(run) + " --preview --jobs 2 --plain-progress";
  ASSERT_EQ(0, runCli(render).code);
  fs::last_write_time(run / "frames/frame_00001.vtp", fs::file_time_type::clock::now() + std::chrono::seconds(5));
  std::ofstream(run / "render/preview/frame_00007.png") << "an image of a frame the run does not have";
  const CliResult r = runCli(render);
  ASSERT_EQ(0, r.code) << r.err;
  EXPECT_NE(r.err.find("1 of 2 frames already rendered"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 images older than their frame, texture or case.toml are rendered again"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("removed 1 images of frames the run does not have (the first: frame_00007.png)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(run / "render/preview/frame_00007.png"));
}

}  // namespace
