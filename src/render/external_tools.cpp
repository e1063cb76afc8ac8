// Finding and running povray and ffmpeg (see external_tools.hpp).
#include "render/external_tools.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace mistfall {

std::optional<std::filesystem::path> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string missingToolsMessage(const std::vector<ExternalTool>& tools) {
  std::string message;
  for (const ExternalTool& t : tools)
    if (!findOnPath(t.program))
      message += t.program + " is not installed (not found on PATH); install the Debian package '" + t.package +
                 "' (sudo apt-get install " + t.package + ", or make deps)\n";
  return message;
}

pid_t startProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                   const std::filesystem::path& log) {
  const auto program = findOnPath(argv.at(0));
  if (!program) throw std::runtime_error(argv[0] + " not found on PATH");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out < 0) throw std::runtime_error("cannot open " + log.string() + ": " + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid == 0) {  // child: only async-signal-safe calls until exec
    const int in = ::open("/dev/null", O_RDONLY);
    if (in < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(out, 2) < 0 || ::chdir(cwd.c_str()) != 0)
      ::_exit(127);
    ::execv(program->c_str(), args.data());
    ::_exit(127);
  }
  ::close(out);
  if (pid < 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(errno));
  return pid;
}

pid_t waitProcess(pid_t pid, bool& ok) {
  int status = 0;
  pid_t done;
  do done = ::waitpid(pid, &status, 0);
  while (done < 0 && errno == EINTR);
  if (done < 0) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return done;
}

bool runProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                const std::filesystem::path& log) {
  bool ok = false;
  waitProcess(startProcess(argv, cwd, log), ok);
  return ok;
}

}  // namespace mistfall
