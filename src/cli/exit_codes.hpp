// mistfall's exit-code contract, written once (kExitCodeContract: every command's --help and the README show it)
// and applied by every command: the commands throw (io/errors.hpp), and exitCodeOf is the one place that turns
// an error into a code.
#pragma once

#include <exception>
#include <functional>
#include <string>

namespace mistfall {

enum ExitCode : int {
  kExitDone = 0,
  kExitBadInput = 1,       // InputError (and CaseError, a command-line error)
  kExitIoFailure = 2,      // any other error: a read or write the system refused, povray or ffmpeg failing
  kExitDiverged = 3,       // DivergenceError
  kExitResourceLimit = 4,  // ResourceError, std::bad_alloc
};

// The contract as text, for --help footers.
extern const char* const kExitCodeContract;

// The exit code of an error (the one mapping).
int exitCodeOf(const std::exception_ptr& error);

// Runs `body` and returns its code; an exception is reported on stderr as "<prefix>: <message>" (the divergence's
// time and step, or what to do when memory ran out, added) and turned into its code by exitCodeOf.
int runReportingErrors(const std::string& prefix, const std::function<int()>& body);

}  // namespace mistfall
