// TextureWriter and the saved frames of a run (see texture_frames.hpp).
#include "cli/texture_frames.hpp"

#include <cstdio>
#include <regex>

#include "io/frame_interval.hpp"
#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"

namespace fs = std::filesystem;

namespace mistfall {

std::string frameNumber(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%05d", frame);
  return buf;
}

std::vector<SavedFrame> listSavedFrames(const fs::path& run, double until) {
  PvdCollection pvd(run / "frames.pvd");
  if (!fs::exists(pvd.path()))
    throw TextureInputError(pvd.path().string() + " does not exist: not a simulate run directory");
  pvd.load();
  pvd.truncateAfter(until);
  static const std::regex name(R"(frames/frame_(\d+)\.vtp)");
  std::vector<SavedFrame> frames;
  for (const auto& e : pvd.entries()) {
    std::smatch m;
    if (!std::regex_match(e.file, m, name))
      throw TextureInputError("unexpected frame name '" + e.file + "' in frames.pvd");
    frames.push_back({e.time, run / e.file, run / ("fields/fields_" + m[1].str() + ".vti"), m[1].str()});
    if (!fs::exists(frames.back().frame)) throw TextureInputError(frames.back().frame.string() + " does not exist");
    if (!fs::exists(frames.back().fields))
      throw TextureInputError(frames.back().fields.string() +
                              " does not exist: the texture needs the flow fields; set output.field_spacing > 0 in "
                              "the case and run simulate again");
  }
  return frames;
}

std::vector<std::uint8_t> readFrameCategory(const fs::path& frame, const fs::path& run) {
  auto category = readVtpByteArray(frame, "category");
  if (!category)
    throw TextureInputError(frame.string() + " has no 'category' array: run `mistfall classify " + run.string() +
                            "` first");
  return *category;
}

TextureWriter::TextureWriter(const CaseConfig& config, fs::path out_dir, bool ascii, TextureStage::Progress progress)
    : out_(std::move(out_dir)),
      ascii_(ascii),
      output_interval_(config.output.interval),
      file_interval_(config.texture.file_interval),
      write_vtp_(config.texture.write_vtp),
      stage_(config, std::move(progress)),
      pvd_(out_ / "texture.pvd") {}

template <int D>
void TextureWriter::frame(const std::string& number, std::shared_ptr<const ImageData> grid,
                          const Particles<D>& p, const std::vector<std::uint8_t>& category, double time,
                          bool with_ids) {
  stage_.advanceTo(std::move(grid));
  std::vector<Vec3> x(p.size(), Vec3::Zero()), u(p.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.size(); ++i) x[i].head<D>() = p.position[i], u[i].head<D>() = p.velocity[i];
  stage_.spawn(x, u, category, time, with_ids ? &p.id : nullptr);
  // texture.file_interval: files only at the frames nearest its multiples (the rule of render.frame_interval)
  if (atFrameInterval(time, output_interval_, file_interval_)) {
    const std::string stem = "texture_" + number;
    writeTextureBinary(out_ / (stem + ".bin"), stage_.cloud(), time);
    if (write_vtp_) {
      writeTextureVtp(out_ / (stem + ".vtp"), stage_.cloud(), time, ascii_);
      pvd_.add(time, stem + ".vtp");
    }
    pvd_.write();  // lists the ParaView files (none without them)
  }
  rows_.push_back(stage_.row(time));
  writeTextureCsv(out_ / "texture.csv", rows_);
}

template <int D>
void TextureWriter::replay(const fs::path& run, const std::vector<SavedFrame>& frames) {
  for (const SavedFrame& f : frames) {
    auto grid = std::make_shared<ImageData>(readVti(f.fields));
    grid->time = f.time;  // the frame's time, exactly (as simulate's in-memory grid)
    VtpFrameInfo info;
    const Particles<D> p = readVtp<D>(f.frame, info);
    frame<D>(f.number, std::move(grid), p, readFrameCategory(f.frame, run), info.time, info.has_id);
  }
}

template void TextureWriter::frame<2>(const std::string&, std::shared_ptr<const ImageData>, const Particles<2>&,
                                      const std::vector<std::uint8_t>&, double, bool);
template void TextureWriter::frame<3>(const std::string&, std::shared_ptr<const ImageData>, const Particles<3>&,
                                      const std::vector<std::uint8_t>&, double, bool);
template void TextureWriter::replay<2>(const fs::path&, const std::vector<SavedFrame>&);
template void TextureWriter::replay<3>(const fs::path&, const std::vector<SavedFrame>&);

}  // namespace mistfall
