// One writer per run directory: every command that works on a run directory (simulate, classify, texture,
// render, run) holds an advisory lock on RUN_DIR/.mistfall.lock (flock(2)) while it does, and a second one is
// refused (bad input) with a message naming the holder's pid and command. The lock is released when the holder
// exits, however it ends (even by kill -9); the file stays (it holds the last holder's pid and command).
#pragma once

#include <filesystem>
#include <string>

namespace mistfall {

inline constexpr const char* kLockFileName = ".mistfall.lock";

class RunDirLock {
 public:
  // Takes the lock of `dir` (an existing directory) for `command` ("simulate", "render", ...); throws InputError
  // when another process holds it. A process that holds it already takes it again (the holds are counted).
  RunDirLock(const std::filesystem::path& dir, const std::string& command);
  ~RunDirLock();
  RunDirLock(const RunDirLock&) = delete;
  RunDirLock& operator=(const RunDirLock&) = delete;

  // Throws InputError, as the constructor, when another process holds the lock of `dir`; writes nothing.
  static void checkFree(const std::filesystem::path& dir);

 private:
  std::string key_;
};

// While one exists, locks this process releases stay held until it ends: `mistfall run` keeps its run directory
// between the stages.
class KeepRunDirLocks {
 public:
  KeepRunDirLocks();
  ~KeepRunDirLocks();
  KeepRunDirLocks(const KeepRunDirLocks&) = delete;
  KeepRunDirLocks& operator=(const KeepRunDirLocks&) = delete;
};

}  // namespace mistfall
