// The texture stage between frames, independent of where the frames come from (saved files for
// `mistfall texture`; the grids and categories `simulate` holds with [texture] inline = true; both through
// cli/texture_frames.hpp). For each frame in
// order: advanceTo(frame's flow grid) steps the cloud from the previous frame's time through the previous and
// this grid (equal steps no longer than the texture step), then spawn(frame's particles and categories) adds the
// sources of the newly isolated particles (source_tracker.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "case/case_config.hpp"
#include "io/grid_fields.hpp"
#include "texture/source_tracker.hpp"
#include "texture/texture_cloud.hpp"

namespace mistfall {

// The texture parameters of a run's case: [texture] plus gravity, densities, viscosities and Ds = l0.
TextureParameters textureParametersOf(const CaseConfig& config);

// One row of texture.csv: counts at a frame and the running totals.
struct TextureCountsRow {
  double time = 0.0;
  std::array<std::int64_t, kTextureKinds> counts{};
  std::int64_t spawned_droplets = 0, spawned_bubbles = 0;
  TextureTally tally;
};

class TextureStage {
 public:
  // progress(t, steps so far, dt) after every texture step.
  using Progress = std::function<void(double, std::int64_t, double)>;

  TextureStage(const CaseConfig& config, Progress progress = {});

  void advanceTo(std::shared_ptr<const ImageData> grid);
  // Positions and velocities padded to 3D (z = 0 in 2D: a 2D run's sources get z across the width); the
  // particles' ids (nullptr: a frame written before ids, followed by proximity; source_tracker.hpp).
  void spawn(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
             const std::vector<std::uint8_t>& category, double time,
             const std::vector<std::uint64_t>* id = nullptr);

  const TextureCloud& cloud() const { return cloud_; }
  TextureCountsRow row(double time) const;

 private:
  int dimension_;
  double max_step_;
  TextureCloud cloud_;
  IsolatedParticleTracker tracker_;
  Progress progress_;
  std::shared_ptr<const ImageData> grid_;
  std::int64_t steps_ = 0, spawned_droplets_ = 0, spawned_bubbles_ = 0;
};

}  // namespace mistfall
