// `mistfall run CASE.toml --out DIR`: the whole pipeline in one command: simulate (which classifies every frame
// as it writes it), texture when the case writes flow fields (output.field_spacing > 0; skipped otherwise, with a
// note), then render. Stops at the first stage that fails and returns its exit code.
#pragma once

#include <filesystem>
#include <optional>

namespace mistfall {

struct RunOptions {
  std::filesystem::path case_file, out_dir;
  std::optional<double> until;        // simulate: stop at this time
  int threads = 0;                    // simulate and texture: OpenMP threads (0: default)
  int jobs = 0;                       // render: povray processes (0: the number of cores)
  bool preview = false;               // render: preview images
  bool keep_intermediates = false;    // render: keep scenes, meshes and densities
  bool export_files = false;          // render: PLY meshes and OpenVDB volumes
  bool overwrite = false;             // simulate and texture: replace an earlier run
  bool force_plain_progress = false;
};

// Exit codes: those of the failing stage (0 when all are done; cli/exit_codes.hpp). povray and ffmpeg are checked
// before simulating: missing ones are exit code 1 with nothing written. The run directory stays locked from
// simulate to render.
int runPipeline(const RunOptions& options);

}  // namespace mistfall
