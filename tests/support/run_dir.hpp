// Test helpers for run-directory tests: a tiny simulated run made once per test binary and copied per test, case
// files written to disk, and snapshots of a directory's files.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cli.hpp"
#include "dam_break_case.hpp"
#include "scratch.hpp"

namespace mistfall::test_support {

inline std::filesystem::path writeCaseFile(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// The tiny dam break (200 fluid particles) with flow grids, to t = 0.04 s: 3 frames. Its case is at
// scratchRoot()/tiny_run_case.toml.
inline std::string tinyRunCase() { return damBreakCase(0.04, 0.02, "", "field_spacing = 0.05\n"); }

// A fresh copy, at scratchRoot()/name, of the tiny run (simulated once by the executable).
inline std::filesystem::path tinyRun(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path master = scratchRoot() / "tiny_run_master";
  if (!fs::exists(master / "checkpoint.bin")) {
    fs::remove_all(master);
    const fs::path c = writeCaseFile(scratchRoot() / "tiny_run_case.toml", tinyRunCase());
    const CliResult r = runCli("simulate " + quoted(c) + " --out " + quoted(master) + " --threads 1 --plain-progress");
    EXPECT_EQ(0, r.code) << r.err;
  }
  const fs::path run = scratchRoot() / name;
  fs::remove_all(run);
  fs::copy(master, run, fs::copy_options::recursive);
  return run;
}

// Every regular file under `dir` with its bytes, keyed by relative path (the lock file's name only: it holds the
// last holder's pid).
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      const std::string name = std::filesystem::relative(e.path(), dir).string();
      files[name] = name == ".mistfall.lock" ? "" : slurp(e.path());
    }
  return files;
}

}  // namespace mistfall::test_support
