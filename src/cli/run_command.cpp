// `mistfall run`: simulate, texture (when the case writes flow fields) and render in turn (see run_command.hpp).
#include "cli/run_command.hpp"

#include <iostream>

#include "case/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/render_command.hpp"
#include "cli/run_lock.hpp"
#include "cli/simulate.hpp"
#include "cli/texture_command.hpp"
#include "io/errors.hpp"
#include "render/external_tools.hpp"

namespace mistfall {

namespace {

int pipeline(const RunOptions& o) {
  const CaseConfig config = loadCaseFile(o.case_file);
  if (const std::string missing = missingToolsMessage({kPovray, kFfmpeg}); !missing.empty())
    throw InputError(missing.substr(0, missing.size() - 1));
  const KeepRunDirLocks keep;  // the run directory stays locked from simulate to render
  SimulateOptions sim;
  sim.case_file = o.case_file;
  sim.out_dir = o.out_dir;
  sim.until = o.until;
  sim.threads = o.threads;
  sim.overwrite = o.overwrite;
  sim.force_plain_progress = o.force_plain_progress;
  std::cerr << "mistfall run: 1/3 simulate (frames are classified as they are written)\n";
  if (int code = runSimulate(sim); code != 0) return code;
  if (config.output.field_spacing > 0.0) {
    std::cerr << "mistfall run: 2/3 texture\n";
    TextureOptions tex;
    tex.run_dir = o.out_dir;
    tex.threads = o.threads;
    tex.overwrite = true;  // the run directory was just written
    tex.force_plain_progress = o.force_plain_progress;
    if (int code = runTexture(tex); code != 0) return code;
  } else {
    std::cerr << "mistfall run: 2/3 texture skipped: the case writes no flow fields (output.field_spacing = 0)\n";
  }
  std::cerr << "mistfall run: 3/3 render\n";
  RenderOptions ren;
  ren.run_dir = o.out_dir;
  ren.preview = o.preview;
  ren.keep_intermediates = o.keep_intermediates;
  ren.export_files = o.export_files;
  ren.jobs = o.jobs;
  ren.force_plain_progress = o.force_plain_progress;
  return runRender(ren);
}

}  // namespace

int runPipeline(const RunOptions& o) {
  return runReportingErrors("mistfall run", [&] { return pipeline(o); });
}

}  // namespace mistfall
