// `mistfall classify RUN_DIR`: the six-category classification (src/classify, section 3.1) of every frame of a run.
// Reads RUN_DIR/case.toml (the copy `simulate` keeps) and each RUN_DIR/frames/frame_NNNNN.vtp, and rewrites each
// frame with a `category` point array (UInt8: 1 liquid bulk, 2 liquid surface, 3 droplet, 4 gas bulk, 5 gas
// surface, 6 bubble, 0 not fluid), in the frame's own format (binary or ascii), the arrays `simulate` writes kept
// bit for bit (readVtp/writeVtp round-trip them exactly).
// Each frame is replaced atomically; RUN_DIR/categories.csv (one row per frame: frame, time and the six counts) is
// written when every frame is done. Running it again gives the same files.
#pragma once

#include <filesystem>

#include "case/case_config.hpp"
#include "classify/classification.hpp"
#include "mps/particles.hpp"

namespace mistfall {

struct ClassifyOptions {
  std::filesystem::path run_dir;
  int threads = 0;                    // 0: OpenMP default
  bool force_plain_progress = false;  // log lines instead of a redrawn bar
};

// Exit codes: cli/exit_codes.hpp. 1 bad input (no such run directory, no case.toml or a bad one, no frames, a
// malformed frame: every frame is read before the first is rewritten, so nothing is written); 2 a write the system
// refused (frames already done keep their category array; no categories.csv).
int runClassify(const ClassifyOptions& options);

// The classification of one frame of a case: constants and thresholds from `config` ([numerics], [classify]).
// Used by `classify` and by `simulate`, which writes the category array with every frame.
template <int D>
std::vector<Category> classifyFrame(const Particles<D>& particles, const CaseConfig& config);

}  // namespace mistfall
