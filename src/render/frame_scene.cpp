// The objects of one frame's scene (see frame_scene.hpp).
#include "render/frame_scene.hpp"

#include <algorithm>
#include <stdexcept>

#include "classify/classification.hpp"
#include "render/surface_mesh.hpp"

namespace mistfall {

namespace {

template <int D>
Vec<3> padded(const Vec<D>& x) {
  Vec<3> v = Vec<3>::Zero();
  v.head<D>() = x;
  return v;
}

// True when the segment from `from` to `to` passes through the box (slab test).
bool segmentHitsBox(const std::array<double, 3>& from, const std::array<double, 3>& to, const Box& b) {
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double d = to[k] - from[k];
    if (d == 0.0) {
      if (from[k] < b.min[k] || from[k] > b.max[k]) return false;
      continue;
    }
    double ta = (b.min[k] - from[k]) / d, tb = (b.max[k] - from[k]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

template <int D>
FrameScene frameScene(const Particles<D>& p, const std::vector<std::uint8_t>& category, const CaseConfig& config,
                      const TextureSnapshot* texture) {
  if (!category.empty() && category.size() != p.size())
    throw std::runtime_error("the category array has " + std::to_string(category.size()) + " values for " +
                             std::to_string(p.size()) + " particles");
  const double l0 = config.numerics.particle_spacing;
  const RenderConfig& r = config.render;
  FrameScene s;
  SceneContent& c = s.content;
  c.up_axis = D - 1;
  c.ground = config.domain.min[D - 1];
  c.droplet_radius = c.bubble_radius = 0.5 * l0;
  c.mist_radius = r.mist_radius;
  c.micro_bubble_radius = r.micro_bubble_radius;
  std::vector<Vec<D>> liquid;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const auto cat = category.empty() ? Category::None : static_cast<Category>(category[i]);
    if (cat == Category::Droplet) c.droplets.push_back(padded<D>(p.position[i]));
    else if (cat == Category::Bubble) c.bubbles.push_back(padded<D>(p.position[i]));
    else if (p.phase[i] == Phase::Liquid) liquid.push_back(p.position[i]);
  }
  if constexpr (D == 2) {
    s.liquid = extrudeAcross(liquid, l0, r.extrusion_width);
  } else {
    s.liquid = std::move(liquid);
  }
  for (const Region& region : config.regions) {
    if (region.material != Material::Wall || region.shape != RegionShape::Box) continue;
    Box b = region.box;
    if (D == 2) b.min[2] = -0.5 * r.extrusion_width, b.max[2] = 0.5 * r.extrusion_width;
    if (!segmentHitsBox(r.camera_location, r.camera_look_at, b)) c.walls.push_back(b);
  }
  if (texture)
    for (std::size_t i = 0; i < texture->position.size(); ++i) {
      if (texture->kind[i] == TextureKind::Mist) c.mist.push_back(texture->position[i]);
      if (texture->kind[i] == TextureKind::MicroBubble) c.micro_bubbles.push_back(texture->position[i]);
    }
  return s;
}

template FrameScene frameScene<2>(const Particles<2>&, const std::vector<std::uint8_t>&, const CaseConfig&,
                                  const TextureSnapshot*);
template FrameScene frameScene<3>(const Particles<3>&, const std::vector<std::uint8_t>&, const CaseConfig&,
                                  const TextureSnapshot*);

}  // namespace mistfall
