// The texture files of a run, frame by frame: the one code path of both texture modes. `mistfall texture RUN_DIR`
// (post-process, the paper's way) replays the saved frames and flow grids through a TextureWriter;
// `mistfall simulate` with texture.inline = true hands it each frame's particles, categories and grid from memory
// as it writes them (and, on --resume, replays the saved frames up to the checkpoint first). The saved files
// store every double exactly (binary, or 17 significant digits), so both modes feed the TextureStage the same
// values in the same order and write the same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/case_config.hpp"
#include "io/errors.hpp"
#include "io/grid_fields.hpp"
#include "io/pvd_collection.hpp"
#include "mps/particles.hpp"
#include "texture/texture_stage.hpp"

namespace mistfall {

// Bad input to the texture (exit code 1 for `mistfall texture`): a missing file, an unclassified frame.
struct TextureInputError : InputError {
  using InputError::InputError;
};

// A saved frame of a run: its time (from frames.pvd), frame and flow-grid files, and its number NNNNN.
struct SavedFrame {
  double time = 0.0;
  std::filesystem::path frame, fields;
  std::string number;
};

// The frames RUN_DIR/frames.pvd lists with time <= until (+1e-12, as PvdCollection::truncateAfter), each with
// its frame and fields/fields_NNNNN.vti present. Throws TextureInputError naming the path otherwise.
std::vector<SavedFrame> listSavedFrames(const std::filesystem::path& run,
                                        double until = std::numeric_limits<double>::infinity());

// The frame's `category` array; throws TextureInputError ("run `mistfall classify RUN_DIR` first") without one.
std::vector<std::uint8_t> readFrameCategory(const std::filesystem::path& frame, const std::filesystem::path& run);

// RUN_DIR/texture/: texture_NNNNN.bin and .vtp per frame, texture.pvd and texture.csv rewritten after each frame
// (all atomically). Starts a fresh pvd and csv: the caller empties the folder first.
class TextureWriter {
 public:
  TextureWriter(const CaseConfig& config, std::filesystem::path out_dir, bool ascii,
                TextureStage::Progress progress = {});

  // One frame: steps the cloud to the grid's time (grid->time must be the frame's time), spawns the sources of
  // the frame's newly isolated particles (followed by their ids; by proximity when `with_ids` is false, for frames
  // written before the frames had ids), writes the files.
  template <int D>
  void frame(const std::string& number, std::shared_ptr<const ImageData> grid, const Particles<D>& particles,
             const std::vector<std::uint8_t>& category, double time, bool with_ids = true);

  // frame() for each saved frame in order, read from its files.
  template <int D>
  void replay(const std::filesystem::path& run, const std::vector<SavedFrame>& frames);

  // texture.csv's rows so far (empty before the first frame).
  const std::vector<TextureCountsRow>& rows() const { return rows_; }

 private:
  std::filesystem::path out_;
  bool ascii_;
  double output_interval_, file_interval_;  // output.interval, texture.file_interval
  bool write_vtp_;
  TextureStage stage_;
  PvdCollection pvd_;
  std::vector<TextureCountsRow> rows_;
};

// The frame number as in the file names: 00042.
std::string frameNumber(int frame);

}  // namespace mistfall
