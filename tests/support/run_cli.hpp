// Test helper: runs the real `mistfall` executable (MISTFALL_BINARY) with arguments and captures its exit code,
// stdout and stderr (in the scratch folder).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "scratch.hpp"

namespace mistfall::test_support {

struct CliResult {
  int code = -1;
  std::string out, err;
};

// Runs the real `mistfall` executable with `args` (already shell-quoted as needed).
inline CliResult runCli(const std::string& args) {
  static int counter = 0;
  std::filesystem::create_directories(test_support::scratchRoot());
  const std::string tag = std::to_string(counter++);
  const std::filesystem::path out = test_support::scratchRoot() / ("cli_stdout_" + tag + ".txt");
  const std::filesystem::path err = test_support::scratchRoot() / ("cli_stderr_" + tag + ".txt");
  const std::string cmd = std::string("'") + MISTFALL_BINARY + "' " + args + " >'" + out.string() + "' 2>'" +
                          err.string() + "' </dev/null";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

}  // namespace mistfall::test_support
