// The external programs of the render stage (povray, ffmpeg): finding them on PATH with a message naming the
// Debian package when one is missing, and running them as child processes, several at a time.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mistfall {

struct ExternalTool {
  std::string program;  // looked up on PATH
  std::string package;  // the Debian package that provides it
};

inline const ExternalTool kPovray{"povray", "povray"};
inline const ExternalTool kFfmpeg{"ffmpeg", "ffmpeg"};

// The executable `program` on $PATH, or nullopt.
std::optional<std::filesystem::path> findOnPath(const std::string& program);

// Empty when every tool is on PATH; otherwise one line per missing tool naming its Debian package.
std::string missingToolsMessage(const std::vector<ExternalTool>& tools);

// Starts `argv` (argv[0] looked up on PATH) in directory `cwd` with stdout and stderr appended to `log` and stdin
// from /dev/null. Throws std::runtime_error when the process cannot be started.
pid_t startProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                   const std::filesystem::path& log);

// Waits for the child `pid` (or any child for pid = -1); returns its pid and sets `ok` when it exited with 0.
pid_t waitProcess(pid_t pid, bool& ok);

// Runs `argv` to completion; true when it exited with 0.
bool runProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                const std::filesystem::path& log);

}  // namespace mistfall
