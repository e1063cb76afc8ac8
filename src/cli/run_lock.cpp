// The run-directory lock (see run_lock.hpp): flock(2) on RUN_DIR/.mistfall.lock, counted within a process.
#include "cli/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <string>

#include "io/errors.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

struct Held {
  int fd = -1;
  int count = 0;
};

std::mutex mutex;
std::map<std::string, Held> held;  // by the directory's canonical path
int keepers = 0;                   // KeepRunDirLocks alive

std::string keyOf(const fs::path& dir) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(dir, ec);
  return ec ? fs::absolute(dir).lexically_normal().string() : canonical.string();
}

// The holder's "pid N (mistfall COMMAND)" from the lock file, or a note that it is not known.
std::string holderOf(int fd) {
  char buf[256] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string text = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "another process (its pid is not written yet)" : text;
}

[[noreturn]] void refuse(const fs::path& dir, int fd) {
  const std::string holder = holderOf(fd);
  ::close(fd);
  throw InputError("run directory " + dir.string() + " is in use by " + holder +
                   ": one mistfall command at a time works on a run directory (lock " +
                   (dir / kLockFileName).string() + "); wait for it to finish or stop it");
}

void release(std::map<std::string, Held>::iterator it) {
  ::close(it->second.fd);  // closing the last descriptor releases the flock
  held.erase(it);
}

}  // namespace

RunDirLock::RunDirLock(const fs::path& dir, const std::string& command) : key_(keyOf(dir)) {
  std::lock_guard<std::mutex> guard(mutex);
  if (auto it = held.find(key_); it != held.end()) {
    it->second.count += 1;
    return;
  }
  const fs::path file = dir / kLockFileName;
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot open the lock file " + file.string() + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EWOULDBLOCK) refuse(dir, fd);
    const int err = errno;
    ::close(fd);
    throw std::runtime_error("cannot lock " + file.string() + ": " + std::strerror(err));
  }
  const std::string text = "pid " + std::to_string(::getpid()) + " (mistfall " + command + ")\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    const int err = errno;
    ::close(fd);
    throw std::runtime_error("cannot write the lock file " + file.string() + ": " + std::strerror(err));
  }
  held[key_] = {fd, 1};
}

RunDirLock::~RunDirLock() {
  std::lock_guard<std::mutex> guard(mutex);
  auto it = held.find(key_);
  if (it == held.end()) return;
  it->second.count -= 1;
  if (it->second.count <= 0 && keepers == 0) release(it);
}

void RunDirLock::checkFree(const fs::path& dir) {
  {
    std::lock_guard<std::mutex> guard(mutex);
    if (held.count(keyOf(dir))) return;  // this process holds it
  }
  const fs::path file = dir / kLockFileName;
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;  // no lock file: nobody holds it
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EWOULDBLOCK) refuse(dir, fd);
  }
  ::close(fd);
}

KeepRunDirLocks::KeepRunDirLocks() {
  std::lock_guard<std::mutex> guard(mutex);
  keepers += 1;
}

KeepRunDirLocks::~KeepRunDirLocks() {
  std::lock_guard<std::mutex> guard(mutex);
  keepers -= 1;
  if (keepers > 0) return;
  for (auto it = held.begin(); it != held.end();)
    if (it->second.count <= 0) {
      ::close(it->second.fd);
      it = held.erase(it);
    } else {
      ++it;
    }
}

}  // namespace mistfall
