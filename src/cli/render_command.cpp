// `mistfall render`: meshes, scenes, povray in parallel, ffmpeg (see render_command.hpp).
#include "cli/render_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <stdexcept>
#include <thread>

#include "case/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/progress.hpp"
#include "cli/run_lock.hpp"
#include "io/errors.hpp"
#include "io/frame_interval.hpp"
#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"
#include "render/external_tools.hpp"
#include "render/frame_files.hpp"
#include "render/materials.hpp"

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

// The frames nearest to the multiples of render.frame_interval (frame n is at n * output.interval).
std::vector<Frame> selectFrames(const std::vector<Frame>& all, const CaseConfig& c) {
  std::vector<Frame> out;
  for (const Frame& f : all)
    if (atFrameInterval(std::stod(f.number) * c.output.interval, c.output.interval, c.render.frame_interval))
      out.push_back(f);
  return out;
}

std::vector<std::string> povrayCommand(const Frame& f, const CaseConfig& c, const RenderOptions& o,
                                       const Layout& out) {
  const int w = o.preview ? c.render.preview_width : c.render.image_width;
  const int h = o.preview ? c.render.preview_height : c.render.image_height;
  const fs::path image = fs::relative(out.images, out.render) / ("tmp_frame_" + f.number + ".png");
  // +Q9: media (the mist and the white water) are drawn from quality 9 on.
  std::vector<std::string> cmd{"povray", "-D", "+FN", "+WT" + std::to_string(std::max(1, o.povray_threads)),
                               "+I" + ("scene_" + f.number + ".pov"), "+O" + image.string(),
                               "+W" + std::to_string(w), "+H" + std::to_string(h), "+Q9"};
  // Adaptive antialiasing one level deep (+R1: 4 samples where a pixel differs from its neighbours by more than
  // the threshold); POV-Ray's default depth 3 costs 15 % more on the waterfall's frames for no visible change.
  if (!o.preview && c.render.antialias > 0.0)
    cmd.insert(cmd.end(), {"+A" + std::to_string(c.render.antialias), "+R1"});
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

// One line per rendered frame in render/timings.csv: the seconds of each step, povray's measured from its start
// to its end (with `jobs` frames at once they share the cores).
class TimingLog {
 public:
  explicit TimingLog(const fs::path& file) : out_(file, std::ios::app) {
    if (fs::file_size(file) == 0)
      out_ << "frame,read_s,mesh_s,volumes_s,write_s,povray_s,triangles,mist,air,mist_volume_m3\n";
  }
  void add(const std::string& number, const FrameFiles& f, double povray_s) {
    out_ << number << ',' << f.read_s << ',' << f.mesh_s << ',' << f.volumes_s << ',' << f.write_s << ','
         << povray_s << ',' << f.triangles << ',' << f.mist << ',' << f.air << ',' << f.mist_volume << '\n';
    out_.flush();
  }

 private:
  std::ofstream out_;
};

fs::path textureFile(const fs::path& run, const Frame& f) {
  return run / "texture" / ("texture_" + f.number + ".bin");
}

// The frames to render: those without an image, or whose image is older than the frame, its texture file or
// case.toml (a run classified, textured or re-cased since). Every one is read first (frame and texture file), so
// that a malformed input is reported before anything is written; frames without a texture file while the run has
// one are reported too.
template <int D>
std::vector<const Frame*> framesToRender(const fs::path& run, const std::vector<Frame>& frames, const Layout& out) {
  std::error_code ec;
  const auto case_time = fs::last_write_time(run / "case.toml", ec);
  const bool textured = fs::exists(run / "texture" / "texture.pvd");
  std::vector<const Frame*> todo;
  std::size_t stale = 0;
  std::vector<std::string> no_texture;
  for (const Frame& f : frames) {
    const fs::path image = out.images / ("frame_" + f.number + ".png");
    const fs::path tex = textureFile(run, f);
    const bool has_texture = fs::exists(tex);
    if (textured && !has_texture) no_texture.push_back(f.number);
    if (fs::exists(image)) {
      const auto made = fs::last_write_time(image, ec);
      const bool newer = !ec && made >= fs::last_write_time(f.vtp) && made >= case_time &&
                         (!has_texture || made >= fs::last_write_time(tex));
      if (newer) continue;
      ++stale;
    }
    readVtp<D>(f.vtp);
    if (has_texture) readTextureBinary(tex);
    todo.push_back(&f);
  }
  const std::size_t skipped = frames.size() - todo.size();
  if (skipped > 0)
    std::cerr << "mistfall render: " << skipped << " of " << frames.size() << " frames already rendered in "
              << out.images << " (their images are newer than the frame, its texture and case.toml)\n";
  if (stale > 0)
    std::cerr << "mistfall render: " << stale << " images older than their frame, texture or case.toml are "
              << "rendered again\n";
  if (!no_texture.empty())
    std::cerr << "mistfall render: note: " << (run / "texture") << " has no texture file for " << no_texture.size()
              << " of " << frames.size() << " frames (the first: " << no_texture.front() << ", the last: "
              << no_texture.back() << "): they are rendered without mist and micro-bubbles\n";
  return todo;
}

template <int D>
int render(const CaseConfig& c, const RenderOptions& o, const std::vector<const Frame*>& todo, const Layout& out) {
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  ProgressReporter progress(static_cast<double>(todo.size()), 0.0, std::cerr, o.force_plain_progress);
  progress.countIn("frames");
  struct Running {
    const Frame* frame;
    FrameFiles files;
    std::chrono::steady_clock::time_point start;
  };
  std::map<pid_t, Running> running;
  std::ofstream(out.render / "timings.csv", std::ios::app).close();
  TimingLog timings(out.render / "timings.csv");
  std::size_t done = 0;
  double prepare_s = 0.0, mesh_s = 0.0, volumes_s = 0.0, povray_s = 0.0;
  const auto start = std::chrono::steady_clock::now();
  auto finishOne = [&] {
    bool ok = false;
    const pid_t pid = waitProcess(-1, ok);
    Running r = std::move(running.at(pid));
    running.erase(pid);
    const Frame* f = r.frame;
    const fs::path tmp = out.images / ("tmp_frame_" + f->number + ".png");
    if (!ok || !fs::exists(tmp))
      throw std::runtime_error("povray failed on " + (out.render / ("scene_" + f->number + ".pov")).string() +
                               "; see " + (out.logs / ("frame_" + f->number + ".log")).string());
    fs::rename(tmp, out.images / ("frame_" + f->number + ".png"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    povray_s += seconds;
    timings.add(f->number, r.files, seconds);
    if (!o.keep_intermediates)
      for (const fs::path& file : r.files.intermediates) fs::remove(file);
    ++done;
    progress.update(static_cast<double>(done), static_cast<std::int64_t>(done), 0.0);
  };
  try {
    for (const Frame* f : todo) {
      FrameFiles files = writeFrameFiles<D>(f->vtp, f->number, c, o.run_dir, out.render, o.export_files);
      prepare_s += files.read_s + files.mesh_s + files.volumes_s + files.write_s;
      mesh_s += files.mesh_s;
      volumes_s += files.volumes_s;
      while (static_cast<int>(running.size()) >= jobs) finishOne();
      const fs::path log = out.logs / ("frame_" + f->number + ".log");
      fs::remove(log);
      const pid_t pid = startProcess(povrayCommand(*f, c, o, out), out.render, log);
      running[pid] = Running{f, std::move(files), std::chrono::steady_clock::now()};
    }
    while (!running.empty()) finishOne();
  } catch (...) {
    for (const auto& [pid, r] : running) {  // let the other frames finish: their images are complete
      bool ok = false;
      waitProcess(pid, ok);
      const std::string& n = r.frame->number;
      if (ok) fs::rename(out.images / ("tmp_frame_" + n + ".png"), out.images / ("frame_" + n + ".png"));
    }
    throw;
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!todo.empty()) {
    const double n = static_cast<double>(todo.size());
    std::cerr << "mistfall render: " << todo.size() << " frames in " << seconds << " s, " << seconds / n
              << " s a frame (" << jobs << " povray jobs of " << std::max(1, o.povray_threads)
              << " threads); a frame's files " << prepare_s / n << " s (meshing " << mesh_s / n << " s, volumes "
              << volumes_s / n << " s), povray " << povray_s / n << " s; render/timings.csv\n";
  }
  joinImages(c, out);
  std::cerr << "mistfall render: images in " << out.images << ", animation " << out.video_stem.string()
            << ".mp4 and .gif\n";
  return 0;
}

}  // namespace

namespace {

int renderRun(const RenderOptions& o) {
  if (!fs::is_directory(o.run_dir)) throw InputError("run directory " + o.run_dir.string() + " does not exist");
  if (!fs::exists(o.run_dir / "case.toml"))
    throw InputError((o.run_dir / "case.toml").string() + " does not exist (is " + o.run_dir.string() +
                     " a run directory written by `mistfall simulate`?)");
  const RunDirLock lock(o.run_dir, "render");
  const CaseConfig config = loadCaseFile(o.run_dir / "case.toml");
  const std::vector<Frame> all = listFrames(o.run_dir / "frames");
  if (all.empty()) throw InputError("no frames (frame_NNNNN.vtp) in " + (o.run_dir / "frames").string());
  const std::vector<Frame> frames = selectFrames(all, config);  // render.frame_interval
  if (const std::string missing = missingToolsMessage({kPovray, kFfmpeg}); !missing.empty())
    throw InputError(missing.substr(0, missing.size() - 1));
  Layout out;
  out.render = o.run_dir / "render";
  out.images = o.preview ? out.render / "preview" : out.render / "png";
  out.logs = out.render / "log";
  out.video_stem = (o.preview ? out.images : out.render) / config.name;
  const std::vector<const Frame*> todo = config.dimension == 2 ? framesToRender<2>(o.run_dir, frames, out)
                                                               : framesToRender<3>(o.run_dir, frames, out);
  fs::create_directories(out.images);
  fs::create_directories(out.logs);
  std::vector<std::string> orphans;  // images of frames the run no longer has would join the animation
  for (const auto& e : fs::directory_iterator(out.images)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("tmp_frame_", 0) == 0) fs::remove(e.path());  // an interrupted render's partial images
    static const std::regex image(R"(frame_([0-9]{5,})\.png)");
    std::smatch m;
    if (std::regex_match(name, m, image) &&
        std::none_of(frames.begin(), frames.end(), [&](const Frame& f) { return f.number == m[1].str(); }))
      orphans.push_back(name);
  }
  for (const auto& name : orphans) fs::remove(out.images / name);
  if (!orphans.empty())
    std::cerr << "mistfall render: removed " << orphans.size() << " images of frames the run does not have (the "
              << "first: " << orphans.front() << ")\n";
  installMaterials(out.render);
  return config.dimension == 2 ? render<2>(config, o, todo, out) : render<3>(config, o, todo, out);
}

}  // namespace

int runRender(const RenderOptions& o) {
  return runReportingErrors("mistfall render", [&] { return renderRun(o); });
}

}  // namespace mistfall
