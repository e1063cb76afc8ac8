// TextureStage: the per-frame sequence of the texture (see texture_stage.hpp).
#include "texture/texture_stage.hpp"

#include <cmath>

namespace mistfall {

TextureParameters textureParametersOf(const CaseConfig& c) {
  const TextureConfig& t = c.texture;
  TextureParameters p;
  p.seed = static_cast<std::uint64_t>(t.seed);
  p.shedding.fine_diameter = t.fine_diameter;
  p.shedding.representatives_per_source = t.representatives_per_source;
  p.shedding.representative_ratio = t.representative_ratio;
  p.shedding.source_lifetime = t.source_lifetime;
  p.fluctuation.model = t.fluctuation;
  p.fluctuation.time_scale_constant = t.langevin_time_scale;
  p.fluctuation.ds = c.numerics.particle_spacing;
  p.added_mass = t.added_mass;
  p.source_diameter = t.source_diameter;
  p.birth_grace = t.birth_grace;
  p.width = t.width;
  p.gravity = Vec3(c.physics.gravity[0], c.physics.gravity[1], c.physics.gravity[2]);
  p.liquid_density = c.physics.liquid.density;
  p.liquid_viscosity = c.physics.liquid.kinematic_viscosity;
  p.gas_density = c.physics.gas.density;
  p.gas_viscosity = c.physics.gas.kinematic_viscosity;
  return p;
}

TextureStage::TextureStage(const CaseConfig& config, Progress progress)
    : dimension_(config.dimension),
      max_step_(config.texture.time_step),
      cloud_(textureParametersOf(config)),
      tracker_(config.texture.match_radius * config.numerics.particle_spacing),
      progress_(std::move(progress)) {}

void TextureStage::advanceTo(std::shared_ptr<const ImageData> grid) {
  if (grid_) {
    const GridFlow flow(grid_, grid, dimension_);
    const double t0 = grid_->time, span = grid->time - t0;
    const auto n = static_cast<std::int64_t>(std::ceil(span / max_step_ - 1e-9));
    for (std::int64_t s = 0; s < n; ++s) {
      cloud_.step(flow, t0 + span * s / n, span / n);
      ++steps_;
      if (progress_) progress_(t0 + span * (s + 1) / n, steps_, span / n);
    }
  }
  grid_ = std::move(grid);
}

void TextureStage::spawn(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
                         const std::vector<std::uint8_t>& category, double time,
                         const std::vector<std::uint64_t>* id) {
  for (const SourceBirth& b : tracker_.update(position, velocity, category, time, id)) {
    const std::uint64_t id = cloud_.addSource(b.kind, b.position, b.velocity, time);
    if (dimension_ == 2) cloud_.position.back()[2] = cloud_.acrossPosition(id);
    ++(b.kind == TextureKind::Droplet ? spawned_droplets_ : spawned_bubbles_);
  }
}

TextureCountsRow TextureStage::row(double time) const {
  TextureCountsRow r;
  r.time = time;
  r.counts = cloud_.counts();
  r.spawned_droplets = spawned_droplets_;
  r.spawned_bubbles = spawned_bubbles_;
  r.tally = cloud_.tally();
  return r;
}

}  // namespace mistfall
