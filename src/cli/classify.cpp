#include "cli/classify.hpp"

#include <omp.h>

#include <algorithm>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/progress.hpp"
#include "cli/run_lock.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/text_format.hpp"
#include "io/vtk_writer.hpp"
#include "mps/reference_density.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

constexpr const char* kCategoriesCsv = "categories.csv";

struct FrameCounts {
  std::string frame;  // the NNNNN of frame_NNNNN.vtp
  double time = 0.0;
  std::array<std::size_t, kCategoryCount> counts{};
};

// The frames of a run, frames/frame_NNNNN.vtp, in name (= time) order; temporary files and others are skipped.
std::vector<fs::path> listFrames(const fs::path& frames_dir) {
  static const std::regex name(R"(frame_[0-9]{5,}\.vtp)");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(frames_dir))
    if (e.is_regular_file() && std::regex_match(e.path().filename().string(), name)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string frameNumber(const fs::path& file) {
  const std::string stem = file.stem().string();  // frame_NNNNN
  return stem.substr(stem.find('_') + 1);
}

void writeCategoriesCsv(const fs::path& file, const std::vector<FrameCounts>& rows) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "frame,time";
    for (int k = 1; k < kCategoryCount; ++k) out << ',' << categoryName(static_cast<Category>(k));
    out << '\n';
    for (const auto& r : rows) {
      out << r.frame << ',' << text::formatDouble(r.time);
      for (int k = 1; k < kCategoryCount; ++k) out << ',' << r.counts[k];
      out << '\n';
    }
  });
}

std::string countsLine(const std::array<std::size_t, kCategoryCount>& counts) {
  std::string s;
  for (int k = 1; k < kCategoryCount; ++k)
    s += (k > 1 ? ", " : "") + std::string(categoryName(static_cast<Category>(k))) + " " + std::to_string(counts[k]);
  return s;
}

template <int D>
int classifyRun(const CaseConfig& config, const ClassifyOptions& options, const std::vector<fs::path>& frames) {
  for (const fs::path& f : frames) readVtp<D>(f);  // every frame readable before the first is rewritten
  std::vector<FrameCounts> rows;
  ProgressReporter progress(static_cast<double>(frames.size()), 0.0, std::cerr, options.force_plain_progress);
  progress.countIn("frames");
  for (std::size_t f = 0; f < frames.size(); ++f) {
    VtpFrameInfo info;
    const Particles<D> p = readVtp<D>(frames[f], info);
    const std::vector<std::uint8_t> category = categoryBytes(classifyFrame<D>(p, config));
    writeVtp<D>(frames[f], p, info.time, info.ascii, &category);
    FrameCounts row;
    row.frame = frameNumber(frames[f]);
    row.time = info.time;
    for (std::uint8_t c : category) row.counts[c] += 1;
    rows.push_back(row);
    progress.update(static_cast<double>(f + 1), static_cast<std::int64_t>(f + 1), 0.0);
  }
  writeCategoriesCsv(options.run_dir / kCategoriesCsv, rows);
  progress.finish();
  std::cerr << "mistfall: classified " << frames.size() << " frames in " << (options.run_dir / "frames")
            << "; counts per frame in " << (options.run_dir / kCategoriesCsv) << "\nmistfall: last frame (t = "
            << rows.back().time << " s): " << countsLine(rows.back().counts) << "\n";
  return 0;
}

}  // namespace

template <int D>
std::vector<Category> classifyFrame(const Particles<D>& particles, const CaseConfig& config) {
  const MpsConstants c = referenceConstants(D, config.numerics.particle_spacing, config.numerics.radius_number_density,
                                            config.numerics.radius_laplacian);
  return classifyParticles<D>(particles, c, config.classify);
}

namespace {

int classify(const ClassifyOptions& options) {
  const fs::path& dir = options.run_dir;
  if (!fs::exists(dir)) throw InputError("run directory " + dir.string() + " does not exist");
  if (!fs::is_directory(dir)) throw InputError("run directory " + dir.string() + " is not a directory");
  if (!fs::exists(dir / "case.toml"))
    throw InputError((dir / "case.toml").string() + " does not exist (is " + dir.string() +
                     " a run directory written by `mistfall simulate`?)");
  const RunDirLock lock(dir, "classify");
  const CaseConfig config = loadCaseFile(dir / "case.toml");
  std::vector<fs::path> frames;
  if (fs::is_directory(dir / "frames")) frames = listFrames(dir / "frames");
  if (frames.empty()) throw InputError("no frames (frame_NNNNN.vtp) in " + (dir / "frames").string());
  if (options.threads > 0) omp_set_num_threads(options.threads);
  return config.dimension == 2 ? classifyRun<2>(config, options, frames) : classifyRun<3>(config, options, frames);
}

}  // namespace

int runClassify(const ClassifyOptions& options) {
  return runReportingErrors("mistfall classify", [&] { return classify(options); });
}

template std::vector<Category> classifyFrame<2>(const Particles<2>&, const CaseConfig&);
template std::vector<Category> classifyFrame<3>(const Particles<3>&, const CaseConfig&);

}  // namespace mistfall
