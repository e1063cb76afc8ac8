// `mistfall render`: meshes, scenes, povray in parallel, ffmpeg (see render_command.hpp).
#include "cli/render_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <regex>
#include <stdexcept>
#include <thread>

#include "case/case_file.hpp"
#include "cli/progress.hpp"
#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"
#include "render/external_tools.hpp"
#include "render/frame_scene.hpp"
#include "render/materials.hpp"
#include "render/mesh_files.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

struct Frame {
  fs::path vtp;
  std::string number;  // NNNNN
};

std::vector<Frame> listFrames(const fs::path& dir) {
  static const std::regex name(R"(frame_([0-9]{5,})\.vtp)");
  std::vector<Frame> frames;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      std::smatch m;
      const std::string file = e.path().filename().string();
      if (e.is_regular_file() && std::regex_match(file, m, name)) frames.push_back({e.path(), m[1].str()});
    }
  std::sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.vtp < b.vtp; });
  return frames;
}

struct Layout {
  fs::path render, images, logs, video_stem;
};

// Meshes the frame and writes mesh_NNNNN.{inc,ply} and scene_NNNNN.pov; returns the mesher's seconds.
template <int D>
double writeFrameFiles(const Frame& f, const CaseConfig& config, const fs::path& run, const Layout& out) {
  VtpFrameInfo info;
  const Particles<D> p = readVtp<D>(f.vtp, info);
  const fs::path tex_file = run / "texture" / ("texture_" + f.number + ".bin");
  std::optional<TextureSnapshot> texture;
  if (fs::exists(tex_file)) texture = readTextureBinary(tex_file);
  FrameScene scene = frameScene<D>(p, info.category, config, texture ? &*texture : nullptr);
  const auto start = std::chrono::steady_clock::now();
  const TriangleMesh mesh = liquidSurface(scene.liquid, {config.numerics.particle_spacing});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!mesh.triangles.empty()) {
    scene.content.mesh_include = "mesh_" + f.number + ".inc";
    writePovMesh(out.render / scene.content.mesh_include, mesh, "Water_Surface");
    writePly(out.render / ("mesh_" + f.number + ".ply"), mesh);
  }
  writeScene(out.render / ("scene_" + f.number + ".pov"), config.render, scene.content,
             config.name + ", t = " + std::to_string(info.time) + " s");
  return seconds;
}

std::vector<std::string> povrayCommand(const Frame& f, const CaseConfig& c, const RenderOptions& o,
                                       const Layout& out) {
  const int w = o.preview ? c.render.preview_width : c.render.image_width;
  const int h = o.preview ? c.render.preview_height : c.render.image_height;
  const fs::path image = fs::relative(out.images, out.render) / ("tmp_frame_" + f.number + ".png");
  std::vector<std::string> cmd{"povray", "-D", "+FN", "+WT1", "+I" + ("scene_" + f.number + ".pov"),
                               "+O" + image.string(), "+W" + std::to_string(w), "+H" + std::to_string(h), "+Q8"};
  if (!o.preview) cmd.push_back("+A0.2");
  return cmd;
}

// ffmpeg: the images to <stem>.mp4 and <stem>.gif, each under a temporary name first.
void joinImages(const CaseConfig& c, const Layout& out) {
  const std::string rate = std::to_string(c.render.frame_rate);
  const std::vector<std::string> input{"ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-pattern_type",
                                       "glob", "-i", (fs::absolute(out.images) / "frame_*.png").string()};
  const std::map<std::string, std::vector<std::string>> outputs{
      {".mp4", {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"}},
      {".gif", {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"}}};
  for (const auto& [ext, args] : outputs) {
    const fs::path final_file = out.video_stem.string() + ext;
    const fs::path tmp = fs::absolute(out.video_stem).string() + ".tmp" + ext;
    std::vector<std::string> cmd = input;
    cmd.insert(cmd.end(), args.begin(), args.end());
    cmd.push_back(tmp.string());
    const fs::path log = out.logs / ("ffmpeg" + ext + ".log");
    fs::remove(log);
    if (!runProcess(cmd, out.render, log)) {
      fs::remove(tmp);
      throw std::runtime_error("ffmpeg failed to write " + final_file.string() + "; see " + log.string());
    }
    fs::rename(tmp, final_file);
  }
}

template <int D>
int render(const CaseConfig& c, const RenderOptions& o, const std::vector<Frame>& frames, const Layout& out) {
  std::vector<const Frame*> todo;
  for (const Frame& f : frames)
    if (!fs::exists(out.images / ("frame_" + f.number + ".png"))) todo.push_back(&f);
  const std::size_t skipped = frames.size() - todo.size();
  if (skipped > 0)
    std::cerr << "mistfall render: " << skipped << " of " << frames.size() << " frames already rendered in "
              << out.images << "\n";
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  ProgressReporter progress(static_cast<double>(todo.size()), 0.0, std::cerr, o.force_plain_progress);
  progress.countIn("frames");
  std::map<pid_t, const Frame*> running;
  std::size_t done = 0;
  double mesh_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  auto finishOne = [&] {
    bool ok = false;
    const pid_t pid = waitProcess(-1, ok);
    const Frame* f = running.at(pid);
    running.erase(pid);
    const fs::path tmp = out.images / ("tmp_frame_" + f->number + ".png");
    if (!ok || !fs::exists(tmp))
      throw std::runtime_error("povray failed on " + (out.render / ("scene_" + f->number + ".pov")).string() +
                               "; see " + (out.logs / ("frame_" + f->number + ".log")).string());
    fs::rename(tmp, out.images / ("frame_" + f->number + ".png"));
    ++done;
    progress.update(static_cast<double>(done), static_cast<std::int64_t>(done), 0.0);
  };
  try {
    for (const Frame* f : todo) {
      mesh_seconds += writeFrameFiles<D>(*f, c, o.run_dir, out);
      while (static_cast<int>(running.size()) >= jobs) finishOne();
      const fs::path log = out.logs / ("frame_" + f->number + ".log");
      fs::remove(log);
      running[startProcess(povrayCommand(*f, c, o, out), out.render, log)] = f;
    }
    while (!running.empty()) finishOne();
  } catch (...) {
    for (const auto& [pid, f] : running) {  // let the other frames finish: their images are complete
      bool ok = false;
      waitProcess(pid, ok);
      if (ok) fs::rename(out.images / ("tmp_frame_" + f->number + ".png"), out.images / ("frame_" + f->number + ".png"));
    }
    throw;
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!todo.empty())
    std::cerr << "mistfall render: " << todo.size() << " frames in " << seconds << " s (" << seconds / todo.size()
              << " s a frame with " << jobs << " povray jobs; meshing " << mesh_seconds / todo.size()
              << " s a frame)\n";
  joinImages(c, out);
  std::cerr << "mistfall render: images in " << out.images << ", animation " << out.video_stem.string()
            << ".mp4 and .gif\n";
  return 0;
}

}  // namespace

int runRender(const RenderOptions& o) {
  CaseConfig config;
  std::vector<Frame> frames;
  try {
    if (!fs::is_directory(o.run_dir)) throw InputError("run directory " + o.run_dir.string() + " does not exist");
    if (!fs::exists(o.run_dir / "case.toml"))
      throw InputError((o.run_dir / "case.toml").string() + " does not exist (is " + o.run_dir.string() +
                       " a run directory written by `mistfall simulate`?)");
    config = loadCaseFile(o.run_dir / "case.toml");
    frames = listFrames(o.run_dir / "frames");
    if (frames.empty()) throw InputError("no frames (frame_NNNNN.vtp) in " + (o.run_dir / "frames").string());
    if (const std::string missing = missingToolsMessage({kPovray, kFfmpeg}); !missing.empty())
      throw InputError(missing.substr(0, missing.size() - 1));
  } catch (const std::exception& e) {
    std::cerr << "mistfall render: " << e.what() << "\n";
    return 1;
  }
  Layout out;
  out.render = o.run_dir / "render";
  out.images = o.preview ? out.render / "preview" : out.render / "png";
  out.logs = out.render / "log";
  out.video_stem = (o.preview ? out.images : out.render) / config.name;
  try {
    fs::create_directories(out.images);
    fs::create_directories(out.logs);
    for (const auto& e : fs::directory_iterator(out.images))  // an interrupted render's partial images
      if (e.path().filename().string().rfind("tmp_frame_", 0) == 0) fs::remove(e.path());
    installMaterials(out.render);
    return config.dimension == 2 ? render<2>(config, o, frames, out) : render<3>(config, o, frames, out);
  } catch (const std::exception& e) {
    std::cerr << "\nmistfall render: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace mistfall
