// Mist and white-water grids of a frame (see frame_volumes.hpp).
#include "render/frame_volumes.hpp"

#include <cmath>

namespace mistfall {

namespace {
constexpr double kFoamAir = 0.5;  // air fraction of a foam particle's volume
}  // namespace

double representedVolume(const TextureConfig& t) {
  return M_PI / 6.0 * std::pow(t.fine_diameter, 3) / t.representative_ratio;
}

FrameVolumes frameVolumes(const FrameScene& s, const CaseConfig& c) {
  FrameVolumes v;
  const RenderConfig& r = c.render;
  const Box& scene = s.content.scene_box;
  const double l0 = c.numerics.particle_spacing;
  if (r.mist && r.style == RenderStyle::Natural && !s.mist.empty()) {
    v.mist = emptyGrid(boundsOf(s.mist, 2.0 * r.mist_voxel, scene), r.mist_voxel);
    splat(v.mist, s.mist, representedVolume(c.texture));
    v.mist_extinction = 3.0 / c.texture.fine_diameter;
  }
  if (r.white_water && (!s.air_across.empty() || !s.air.empty() || !s.micro_bubbles.empty() ||
                        !s.foam_across.empty() || !s.foam.empty())) {
    const double h = l0;
    std::vector<Vec<3>> corners = s.micro_bubbles;
    corners.insert(corners.end(), s.air.begin(), s.air.end());
    corners.insert(corners.end(), s.foam.begin(), s.foam.end());
    for (const auto* rows : {&s.air_across, &s.foam_across})
      for (const auto& a : *rows)
        for (double z : {scene.min[2], scene.max[2]}) corners.emplace_back(a.x(), a.y(), z);
    v.white_water = emptyGrid(boundsOf(corners, 2.0 * h + l0, scene), h);
    const double air = 3.0 / r.white_water_bubble_diameter;
    splatAcross(v.white_water, s.air_across, air * l0 * l0);
    splat(v.white_water, s.air, air * std::pow(l0, 3));
    splatAcross(v.white_water, s.foam_across, kFoamAir * air * l0 * l0);
    splat(v.white_water, s.foam, kFoamAir * air * std::pow(l0, 3));
    splat(v.white_water, s.micro_bubbles, 3.0 / c.texture.fine_diameter * representedVolume(c.texture));
  }
  return v;
}

}  // namespace mistfall
