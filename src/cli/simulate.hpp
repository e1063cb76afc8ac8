// `mistfall simulate`: runs a case from its TOML file (or resumes a run directory) and writes frames,
// the .pvd collection, diagnostics.csv and a checkpoint at every output time.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

namespace mistfall {

struct SimulateOptions {
  std::filesystem::path case_file;    // empty when resuming
  std::filesystem::path out_dir;      // run directory (the resume directory when resuming)
  std::optional<double> until;        // stop at this simulated time (default: output.end_time)
  int threads = 0;                    // 0: OpenMP default
  bool ascii = false;                 // ASCII VTK instead of binary
  bool resume = false;                // continue from out_dir/checkpoint.bin
  bool overwrite = false;             // allow replacing an existing run directory
  bool force_plain_progress = false;  // log lines instead of a redrawn bar
  std::optional<std::uint64_t> trace_id;  // --trace: write this particle's stages to RUN_DIR/traces/trace_ID.csv
  double trace_from = 0.0;                // --trace-from: from the step starting at this time [s]
  bool accept_case_change = false;        // --accept-case-change: resume a case.toml edited in what it simulates
};

// Exit codes: the contract of cli/exit_codes.hpp (1 bad input: nothing written; 3 diverged: frames written so far
// kept; 4 a case too big for the memory). Holds the run directory's lock (cli/run_lock.hpp) while it works.
int runSimulate(const SimulateOptions& options);

}  // namespace mistfall
