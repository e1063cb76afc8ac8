// The exit-code contract (see exit_codes.hpp): the text users read and the one mapping from errors to codes.
#include "cli/exit_codes.hpp"

#include <iostream>
#include <new>
#include <sstream>

#include "io/errors.hpp"
#include "mps/solver.hpp"

namespace mistfall {

const char* const kExitCodeContract =
    "Exit codes (every command):\n"
    "  0  done\n"
    "  1  bad input: the command line, the case file, a run directory that is missing, not empty (without\n"
    "     --overwrite) or in use by another mistfall, a file of the run that is missing, malformed or from another\n"
    "     run (a checkpoint whose case differs), povray or ffmpeg not installed; found before anything is written\n"
    "  2  I/O failure: the system refused a read or a write (permission, disk full, a file in the way), or povray\n"
    "     or ffmpeg failed; the message names the file or the log\n"
    "  3  the simulation diverged: frames written before are kept, RUN_DIR/diverged.txt says when and why\n"
    "  4  resource limit: the case needs more memory than is available (refused before anything is written),\n"
    "     or memory ran out\n";

int exitCodeOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError&) {
    return kExitBadInput;
  } catch (const DivergenceError&) {
    return kExitDiverged;
  } catch (const ResourceError&) {
    return kExitResourceLimit;
  } catch (const std::bad_alloc&) {
    return kExitResourceLimit;
  } catch (...) {
    return kExitIoFailure;
  }
}

namespace {

std::string messageOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const DivergenceError& e) {
    std::ostringstream s;
    s << "the run diverged at t = " << e.time() << " s, step " << e.step() << ": " << e.what();
    return s.str();
  } catch (const std::bad_alloc&) {
    return "out of memory (std::bad_alloc): the machine has less memory free than this step needs; free memory "
           "or use a coarser numerics.particle_spacing";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace

int runReportingErrors(const std::string& prefix, const std::function<int()>& body) {
  try {
    return body();
  } catch (...) {
    const std::exception_ptr error = std::current_exception();
    std::cerr << prefix << ": " << messageOf(error) << "\n";
    return exitCodeOf(error);
  }
}

}  // namespace mistfall
