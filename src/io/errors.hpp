// The kinds of failure behind mistfall's exit codes. cli/exit_codes.cpp maps them to codes, in one place:
//   InputError       1  bad input: the command line, a case file, a run directory in the wrong state (missing, not
//                       empty, in use by another mistfall), or a file mistfall reads that is missing, malformed or
//                       belongs to another run. Messages name the key or the file and what is wrong.
//   (mps) DivergenceError 3  the simulation diverged.
//   ResourceError    4  the case needs more memory than the machine has (std::bad_alloc counts too).
//   anything else    2  I/O failure: the system refused a read or a write (permission, disk full, a file in the
//                       way), or povray or ffmpeg failed.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace mistfall {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ResourceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A file that could not be opened for reading: an InputError when it does not exist (or is not a regular file),
// an I/O failure (std::runtime_error) otherwise. `what` names the kind of file ("VTK file", "checkpoint").
[[noreturn]] inline void throwCannotOpen(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(what + " '" + file.string() + "' does not exist");
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(what + " '" + file.string() + "' is not a regular file");
  throw std::runtime_error("cannot open " + what + " '" + file.string() + "' for reading");
}

}  // namespace mistfall
