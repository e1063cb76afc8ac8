// `mistfall texture RUN_DIR`: the sub-particle-scale texture of a simulated and classified run (section 3.2),
// as a post-process over the saved frames (the paper's way). Reads RUN_DIR/case.toml ([texture] table,
// docs/case-file.md), frames.pvd, the frames' `category` array (written by `simulate`, rewritten by
// `mistfall classify`) and the flow grids fields/fields_NNNNN.vti; writes RUN_DIR/texture/texture_NNNNN.{bin,vtp},
// texture.pvd and texture.csv: the same bytes as `simulate` with [texture] inline = true (texture_frames.hpp).
#pragma once

#include <filesystem>

namespace mistfall {

struct TextureOptions {
  std::filesystem::path run_dir;
  int threads = 0;                    // 0: OpenMP default
  bool ascii = false;                 // ASCII VTK
  bool overwrite = false;             // replace an existing RUN_DIR/texture
  bool force_plain_progress = false;  // log lines instead of a redrawn bar
};

// Exit codes: cli/exit_codes.hpp (1 bad input, found before anything is written: every frame and grid is read
// first; 2 I/O failure).
int runTexture(const TextureOptions& options);

}  // namespace mistfall
