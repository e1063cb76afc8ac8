// The exit-code contract (cli/exit_codes.hpp): written once, shown by every command's --help and the README, and
// applied by every command: the probes of issue 19 (corrupt checkpoints, malformed frames, grids and texture
// files, output paths that cannot be made, refused writes, a case too big for the machine) each give the code of
// their kind and name the file, and bad input writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/texture_frames.hpp"
#include "io/errors.hpp"
#include "mps/solver.hpp"
#include "support/run_dir.hpp"

namespace fs = std::filesystem;
using namespace mistfall;
using test_support::CliResult;
using test_support::quoted;
using test_support::runCli;
using test_support::slurp;
using test_support::snapshot;
using test_support::tinyRun;

namespace {

template <class E, class... A>
std::exception_ptr error(A... args) {
  return std::make_exception_ptr(E(args...));
}

TEST(ExitCodes, EachKindOfErrorHasItsCode) {
  const std::pair<std::exception_ptr, int> cases[] = {
      {error<InputError>("x"), 1},
      {error<CaseError>("x"), 1},
      {error<TextureInputError>("x"), 1},
      {error<std::runtime_error>("x"), 2},
      {error<fs::filesystem_error>("x", std::make_error_code(std::errc::no_space_on_device)), 2},
      {error<DivergenceError>("x", 0.1, 7), 3},
      {error<ResourceError>("x"), 4},
      {error<std::bad_alloc>(), 4},
  };
  for (const auto& [e, code] : cases) EXPECT_EQ(code, exitCodeOf(e));
}

TEST(ExitCodes, TheContractIsInEveryCommandsHelpAndInTheReadme) {
  for (const char* command : {"", "simulate", "classify", "texture", "render", "run"}) {
    SCOPED_TRACE(command);
    const CliResult r = runCli(std::string(command) + " --help");
    EXPECT_EQ(0, r.code);
    EXPECT_NE(r.out.find(kExitCodeContract), std::string::npos) << r.out;
  }
  const std::string readme = slurp(fs::path(MISTFALL_SOURCE_DIR) / "README.md");
  EXPECT_NE(readme.find(kExitCodeContract), std::string::npos) << "README.md does not hold the contract verbatim";
}

// A probe: something done to a copy of a tiny run, a command, the code it must give, words its message must hold.
struct Probe {
  const char* label;
  std::function<void(const fs::path& run)> damage;
  std::string command;  // RUN stands for the run directory, CASE for its case file
  int code;
  std::vector<std::string> says;  // RUN stands for the run directory
  bool writes_nothing = true;
};

void overwriteBytes(const fs::path& file, std::size_t at, const std::string& bytes) {
  std::string s = slurp(file);
  s.replace(at, bytes.size(), bytes);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << s;
}

void truncateFile(const fs::path& file, std::size_t size) { fs::resize_file(file, size); }

std::string substitute(std::string s, const fs::path& run, const fs::path& case_file) {
  for (auto [key, value] : {std::pair<std::string, std::string>{"RUN", run.string()}, {"CASE", case_file.string()}})
    for (std::size_t at; (at = s.find(key)) != std::string::npos;) s.replace(at, key.size(), value);
  return s;
}

TEST(ExitCodes, EveryStageGivesTheCodeOfWhatWentWrongAndNamesTheFile) {
  const auto frame = [](const fs::path& run) { return run / "frames" / "frame_00001.vtp"; };
  const auto grid = [](const fs::path& run) { return run / "fields" / "fields_00001.vti"; };
  const std::vector<Probe> probes = {
      {"checkpoint with a wrong magic", [](const fs::path& r) { overwriteBytes(r / "checkpoint.bin", 0, "XXXX"); },
       "simulate --resume RUN", 1, {"RUN/checkpoint.bin", "wrong magic"}},
      {"truncated checkpoint", [](const fs::path& r) { truncateFile(r / "checkpoint.bin", 100); },
       "simulate --resume RUN", 1, {"RUN/checkpoint.bin", "truncated"}},
      {"checkpoint with a flipped bit", [](const fs::path& r) {
         overwriteBytes(r / "checkpoint.bin", fs::file_size(r / "checkpoint.bin") / 2, "\x5a");
       }, "simulate --resume RUN", 1, {"RUN/checkpoint.bin", "checksum"}},
      {"checkpoint of the wrong dimension", [](const fs::path& r) { overwriteBytes(r / "checkpoint.bin", 16, "\x03"); },
       "simulate --resume RUN", 1, {"checkpoint is 3D but the case is 2D"}},
      {"malformed frame, classify", [&](const fs::path& r) { truncateFile(frame(r), 200); },
       "classify RUN", 1, {"RUN/frames/frame_00001.vtp", "truncated"}},
      {"malformed frame, texture", [&](const fs::path& r) { truncateFile(frame(r), 200); },
       "texture RUN", 1, {"RUN/frames/frame_00001.vtp", "truncated"}},
      {"malformed frame, render", [&](const fs::path& r) { truncateFile(frame(r), 200); },
       "render RUN --preview", 1, {"RUN/frames/frame_00001.vtp", "truncated"}},
      {"frame without its category, texture", [&](const fs::path& r) {
         std::string s = slurp(frame(r));
         s.replace(s.find("Name=\"category\""), 15, "Name=\"kategory\"");
         std::ofstream(frame(r), std::ios::binary | std::ios::trunc) << s;
       }, "texture RUN", 1, {"RUN/frames/frame_00001.vtp has no 'category' array"}},
      {"malformed grid, texture", [&](const fs::path& r) { truncateFile(grid(r), 300); },
       "texture RUN", 1, {"RUN/fields/fields_00001.vti"}},
      {"missing grid, texture", [&](const fs::path& r) { fs::remove(grid(r)); },
       "texture RUN", 1, {"RUN/fields/fields_00001.vti does not exist"}},
      {"malformed frames.pvd, resume", [](const fs::path& r) { truncateFile(r / "frames.pvd", 10); },
       "simulate --resume RUN", 1, {"RUN/frames.pvd"}},
      {"malformed texture file, render", [](const fs::path& r) {
         fs::create_directories(r / "texture");
         std::ofstream(r / "texture" / "texture.pvd") << "<VTKFile type=\"Collection\"></VTKFile>\n";
         std::ofstream(r / "texture" / "texture_00001.bin") << "MSTFTEX";
       }, "render RUN --preview", 1, {"RUN/texture/texture_00001.bin"}},
      {"--out under a file", [](const fs::path& r) { std::ofstream(r / "a_file") << "x\n"; },
       "simulate CASE --out RUN/a_file/run", 1, {"RUN/a_file, which is not a directory"}},
      {"--out that cannot be made", [](const fs::path&) {},
       "simulate CASE --out /proc/mistfall_cannot_be_made", 2, {"/proc/mistfall_cannot_be_made"}},
      {"categories.csv in the way, classify", [](const fs::path& r) { fs::create_directories(r / "categories.csv/x"); },
       "classify RUN", 2, {"RUN/categories.csv"}, false},
      {"a case that cannot fit in memory", [](const fs::path& r) {
         std::string text = test_support::tinyRunCase();
         text.replace(text.find("particle_spacing = 0.01"), 23, "particle_spacing = 2e-6");
         test_support::writeCaseFile(r / "huge.toml", text);
       }, "simulate RUN/huge.toml --out RUN/huge", 4, {"RUN/huge.toml: the case needs about", "is available"}},
  };
  const fs::path case_file = test_support::scratchRoot() / "tiny_run_case.toml";
  for (const Probe& p : probes) {
    SCOPED_TRACE(p.label);
    const fs::path run = tinyRun("probe");
    p.damage(run);
    const auto before = snapshot(run);
    const CliResult r = runCli(substitute(p.command, run, case_file) + " --plain-progress");
    EXPECT_EQ(p.code, r.code) << r.err;
    for (const std::string& s : p.says) EXPECT_NE(r.err.find(substitute(s, run, case_file)), std::string::npos) << r.err;
    if (p.writes_nothing) {
      EXPECT_TRUE(before == snapshot(run)) << "the run directory changed";
      EXPECT_FALSE(fs::exists(run / "render"));
    }
  }
}

}  // namespace
