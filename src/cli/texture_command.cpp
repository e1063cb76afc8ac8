// `mistfall texture`: steps the texture cloud between the saved frames of a run (see texture_command.hpp) through
// the TextureWriter that `simulate` uses inline (texture_frames.hpp).
// Frame 0: sources are spawned from the isolated particles, the cloud is written. Frame n > 0: the cloud is
// stepped from t_{n-1} to t_n with equal steps of at most texture.time_step through the flow grids of frames
// n-1 and n (linear in time), then frame n's newly isolated particles spawn sources, then the cloud is written.
#include "cli/texture_command.hpp"

#include <omp.h>

#include <iostream>

#include "case/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/progress.hpp"
#include "cli/run_lock.hpp"
#include "cli/texture_frames.hpp"
#include "io/grid_fields.hpp"
#include "io/vtk_writer.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

int run(const CaseConfig& config, const TextureOptions& o, const std::vector<SavedFrame>& frames) {
  const fs::path out = o.run_dir / "texture";
  ProgressReporter progress(frames.back().time, frames.front().time, std::cerr, o.force_plain_progress);
  TextureWriter writer(config, out, o.ascii,
                       [&](double t, std::int64_t step, double dt) { progress.update(t, step, dt); });
  if (config.dimension == 2)
    writer.replay<2>(o.run_dir, frames);
  else
    writer.replay<3>(o.run_dir, frames);
  progress.finish();
  const TextureCountsRow& last = writer.rows().back();
  const auto& c = last.counts;
  std::cerr << "mistfall: texture done, " << frames.size() << " frames in " << out << "; at t = " << last.time
            << " s: " << c[0] << " droplets, " << c[1] << " mist, " << c[2] << " bubbles, " << c[3]
            << " micro-bubbles\n";
  return 0;
}

}  // namespace

namespace {

int texture(const TextureOptions& o) {
  if (!fs::is_directory(o.run_dir))
    throw TextureInputError("run directory " + o.run_dir.string() + " does not exist");
  const RunDirLock lock(o.run_dir, "texture");
  const CaseConfig config = loadCaseFile(o.run_dir / "case.toml");
  const std::vector<SavedFrame> frames = listSavedFrames(o.run_dir);
  if (frames.empty()) throw TextureInputError("frames.pvd lists no frames");
  const fs::path out = o.run_dir / "texture";
  if (fs::exists(out) && !fs::is_empty(out) && !o.overwrite)
    throw TextureInputError(out.string() + " exists and is not empty (use --overwrite to replace it)");
  // Every input readable before anything is written: the frames with their category arrays, the flow grids.
  for (const SavedFrame& f : frames) {
    readFrameCategory(f.frame, o.run_dir);
    if (config.dimension == 2)
      readVtp<2>(f.frame);
    else
      readVtp<3>(f.frame);
    readVti(f.fields);
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  fs::remove_all(out);
  fs::create_directories(out);
  return run(config, o, frames);
}

}  // namespace

int runTexture(const TextureOptions& o) {
  return runReportingErrors("mistfall texture", [&] { return texture(o); });
}

}  // namespace mistfall
