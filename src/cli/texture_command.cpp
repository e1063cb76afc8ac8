// `mistfall texture`: steps the texture cloud between the saved frames of a run (see texture_command.hpp).
// Frame 0: sources are spawned from the isolated particles, the cloud is written. Frame n > 0: the cloud is
// stepped from t_{n-1} to t_n with equal steps of at most texture.time_step through the flow grids of frames
// n-1 and n (linear in time), then frame n's newly isolated particles spawn sources, then the cloud is written.
#include "cli/texture_command.hpp"

#include <omp.h>

#include <cmath>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "case/case_file.hpp"
#include "cli/progress.hpp"
#include "io/grid_fields.hpp"
#include "io/pvd_collection.hpp"
#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"
#include "texture/texture_stage.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

struct FrameFiles {
  double time;
  fs::path frame, fields;
  std::string number;  // NNNNN
};

// Bad input: exit code 1, nothing written.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<FrameFiles> listFrames(const fs::path& run) {
  PvdCollection pvd(run / "frames.pvd");
  if (!fs::exists(pvd.path())) throw InputError(pvd.path().string() + " does not exist: not a simulate run directory");
  pvd.load();
  static const std::regex name(R"(frames/frame_(\d+)\.vtp)");
  std::vector<FrameFiles> frames;
  for (const auto& e : pvd.entries()) {
    std::smatch m;
    if (!std::regex_match(e.file, m, name)) throw InputError("unexpected frame name '" + e.file + "' in frames.pvd");
    frames.push_back({e.time, run / e.file, run / ("fields/fields_" + m[1].str() + ".vti"), m[1].str()});
    if (!fs::exists(frames.back().frame)) throw InputError(frames.back().frame.string() + " does not exist");
    if (!fs::exists(frames.back().fields))
      throw InputError(frames.back().fields.string() +
                       " does not exist: the texture needs the flow fields; set output.field_spacing > 0 in the case "
                       "and run simulate again");
  }
  if (frames.empty()) throw InputError("frames.pvd lists no frames");
  return frames;
}

std::vector<std::uint8_t> readCategory(const fs::path& frame, const fs::path& run) {
  auto category = readVtpByteArray(frame, "category");
  if (!category)
    throw InputError(frame.string() + " has no 'category' array: run `mistfall classify " + run.string() +
                     "` first");
  return *category;
}

template <int D>
void spawnFromFrame(const fs::path& frame_file, const fs::path& run, TextureStage& stage) {
  double time = 0.0;
  const Particles<D> p = readVtp<D>(frame_file, &time);
  const auto category = readCategory(frame_file, run);
  std::vector<Vec3> x(p.size(), Vec3::Zero()), u(p.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.size(); ++i) x[i].head<D>() = p.position[i], u[i].head<D>() = p.velocity[i];
  stage.spawn(x, u, category, time);
}

template <int D>
int run(const CaseConfig& config, const TextureOptions& o, const std::vector<FrameFiles>& frames) {
  const fs::path out = o.run_dir / "texture";
  ProgressReporter progress(frames.back().time, frames.front().time, std::cerr, o.force_plain_progress);
  TextureStage stage(config, [&](double t, std::int64_t step, double dt) { progress.update(t, step, dt); });
  PvdCollection pvd(out / "texture.pvd");
  std::vector<TextureCountsRow> rows;
  for (const FrameFiles& frame : frames) {
    auto grid = std::make_shared<ImageData>(readVti(frame.fields));
    grid->time = frame.time;  // the frame's time, exactly
    stage.advanceTo(std::move(grid));
    spawnFromFrame<D>(frame.frame, o.run_dir, stage);
    const std::string stem = "texture_" + frame.number;
    writeTextureBinary(out / (stem + ".bin"), stage.cloud(), frame.time);
    writeTextureVtp(out / (stem + ".vtp"), stage.cloud(), frame.time, o.ascii);
    pvd.add(frame.time, stem + ".vtp");
    pvd.write();
    rows.push_back(stage.row(frame.time));
    writeTextureCsv(out / "texture.csv", rows);
  }
  progress.finish();
  const auto& c = rows.back().counts;
  std::cerr << "mistfall: texture done, " << frames.size() << " frames in " << out << "; at t = " << rows.back().time
            << " s: " << c[0] << " droplets, " << c[1] << " mist, " << c[2] << " bubbles, " << c[3]
            << " micro-bubbles\n";
  return 0;
}

}  // namespace

int runTexture(const TextureOptions& o) {
  CaseConfig config;
  std::vector<FrameFiles> frames;
  try {
    if (!fs::is_directory(o.run_dir)) throw InputError("run directory " + o.run_dir.string() + " does not exist");
    config = loadCaseFile(o.run_dir / "case.toml");
    frames = listFrames(o.run_dir);
    for (const FrameFiles& f : frames) readCategory(f.frame, o.run_dir);  // all classified, before writing
    const fs::path out = o.run_dir / "texture";
    if (fs::exists(out) && !fs::is_empty(out) && !o.overwrite)
      throw InputError(out.string() + " exists and is not empty (use --overwrite to replace it)");
  } catch (const std::exception& e) {
    std::cerr << "mistfall texture: " << e.what() << "\n";
    return 1;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  try {
    fs::remove_all(o.run_dir / "texture");
    fs::create_directories(o.run_dir / "texture");
    return config.dimension == 2 ? run<2>(config, o, frames) : run<3>(config, o, frames);
  } catch (const InputError& e) {
    std::cerr << "mistfall texture: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "mistfall texture: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace mistfall
