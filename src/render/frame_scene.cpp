// The objects of one frame's scene (see frame_scene.hpp).
#include "render/frame_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "classify/classification.hpp"
#include "render/surface_mesh.hpp"

namespace mistfall {

namespace {

constexpr int kMinSheetDroplets = 6;  // droplets in a linked chain that make it a sheet
constexpr double kFoamReach = 1.5;    // [l0] a surface particle this close to air in the water is foam

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
                      const TextureSnapshot* texture, double time) {
  if (!category.empty() && category.size() != p.size())
    throw std::runtime_error("the category array has " + std::to_string(category.size()) + " values for " +
                             std::to_string(p.size()) + " particles");
  const double l0 = config.numerics.particle_spacing;
  const RenderConfig& r = config.render;
  FrameScene s;
  SceneContent& c = s.content;
  c.up_axis = D - 1;
  c.time = time;
  c.ground = config.domain.min[D - 1];
  c.scene_box = config.domain;
  if (D == 2) {
    c.water_width = r.extrusion_width;
    c.scene_box.min[2] = -0.5 * r.extrusion_width, c.scene_box.max[2] = 0.5 * r.extrusion_width;
  }
  c.droplet_radius = c.bubble_radius = 0.5 * l0;
  c.mist_radius = r.mist_radius;
  c.micro_bubble_radius = r.micro_bubble_radius;
  std::vector<std::size_t> liquid;  // fluid liquid particles
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid && p.kind[i] != ParticleKind::Point) continue;  // points: entrained air
    const auto cat = category.empty() ? Category::None : static_cast<Category>(category[i]);
    if (p.phase[i] == Phase::Liquid) {
      liquid.push_back(i);
    } else if (cat == Category::Bubble || p.enclosed[i]) {
      if constexpr (D == 2) s.air_across.push_back(p.position[i]);
      else s.air.push_back(p.position[i]);
    }
    if (cat == Category::Bubble && !texture) c.bubbles.push_back(padded<D>(p.position[i]));
  }
  auto categoryOf = [&](std::size_t i) {
    return category.empty() ? Category::None : static_cast<Category>(category[i]);
  };
  // Foam: liquid surface particles within kFoamReach l0 of air in the water (where the jet drags air under).
  std::vector<Vec<D>> air_points;
  for (std::size_t i = 0; i < p.size(); ++i)
    if ((p.kind[i] == ParticleKind::Fluid || p.kind[i] == ParticleKind::Point) && p.phase[i] == Phase::Gas &&
        (categoryOf(i) == Category::Bubble || p.enclosed[i]))
      air_points.push_back(p.position[i]);
  for (std::size_t i : liquid) {
    if (categoryOf(i) != Category::LiquidSurface) continue;
    for (const Vec<D>& a : air_points)
      if ((a - p.position[i]).norm() < kFoamReach * l0) {
        if constexpr (D == 2) s.foam_across.push_back(p.position[i]);
        else s.foam.push_back(p.position[i]);
        break;
      }
  }
  std::vector<char> in_sheet(p.size(), 0);
  if constexpr (D == 2) {
    std::vector<Vec<2>> x, u;
    for (std::size_t i : liquid) x.push_back(p.position[i]), u.push_back(p.velocity[i]);
    JetLinkParameters jp;
    jp.spacing = l0;
    std::vector<SectionLink> links = jetLinks(x, u, jp);
    // Droplets joined by links into chains (union-find); only chains of kMinSheetDroplets droplets or more are a
    // sheet: a short chain of spray extruded across the fall would be a plate of glass.
    std::vector<int> parent(x.size());
    for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<int>(k);
    auto root = [&](int k) {
      while (parent[k] != k) k = parent[k] = parent[parent[k]];
      return k;
    };
    auto isDroplet = [&](int k) { return categoryOf(liquid[k]) == Category::Droplet; };
    for (const SectionLink& link : links)
      if (isDroplet(link.from) && isDroplet(link.to)) parent[root(link.from)] = root(link.to);
    std::vector<int> droplets_in(x.size(), 0);
    for (std::size_t k = 0; k < x.size(); ++k)
      if (isDroplet(static_cast<int>(k))) ++droplets_in[root(static_cast<int>(k))];
    for (const SectionLink& link : links) {
      const std::size_t a = liquid[link.from], b = liquid[link.to];
      // Links join droplets: between two particles of the water's body or surface they would bridge troughs.
      const int drop = isDroplet(link.from) ? link.from : isDroplet(link.to) ? link.to : -1;
      if (drop < 0 || droplets_in[root(drop)] < kMinSheetDroplets) continue;
      in_sheet[a] = in_sheet[b] = 1;
      s.links.push_back(link);
    }
  }
  std::vector<Vec<3>> sources;  // the texture's droplet sources: a place across the fall for the frame's droplets
  if (texture)
    for (std::size_t i = 0; i < texture->position.size(); ++i)
      if (texture->kind[i] == TextureKind::Droplet) sources.push_back(texture->position[i]);
  for (std::size_t i : liquid) {
    if (categoryOf(i) != Category::Droplet) {
      if constexpr (D == 2) s.section.push_back(p.position[i]);
      else s.liquid.push_back(p.position[i]);
      continue;
    }
    if (in_sheet[i]) continue;  // drawn by its links' capsules, as thin as the sheet has become
    Vec<3> x = padded<D>(p.position[i]);
    if (D == 2) {
      double best = 2.0 * l0;
      for (const Vec<3>& q : sources)
        if (const double d = std::hypot(q.x() - x.x(), q.y() - x.y()); d < best) best = d, x.z() = q.z();
    }
    c.droplets.push_back(x);
  }
  auto hidden = [&](const std::string& name) {
    return std::find(r.hidden_regions.begin(), r.hidden_regions.end(), name) != r.hidden_regions.end();
  };
  // A wall box, extruded across a 2D case, unless it stands on the camera's line of sight.
  auto drawWall = [&](Box b, const std::string& name) {
    if (D == 2) b.min[2] = -0.5 * r.extrusion_width, b.max[2] = 0.5 * r.extrusion_width;
    Box drawn = b;  // natural style, 2D: the rock is widened across the fall by bank_width
    if (D == 2 && r.style == RenderStyle::Natural) drawn.min[2] -= r.bank_width, drawn.max[2] += r.bank_width;
    if (segmentHitsBox(r.camera_location, r.camera_look_at, drawn)) return;
    c.walls.push_back(b);
    c.wall_names.push_back(name);
  };
  for (const Region& region : config.regions) {
    if (region.material != Material::Wall || region.shape != RegionShape::Box) continue;
    if (hidden(region.name)) continue;
    drawWall(region.box, region.name);
  }
  // A vent (mps/gas_vent.hpp) is a 2D case's stand-in for a flume's vent pipes through its side walls: it is drawn as
  // the wall it was cut from, unless it touches a hidden wall region (a vent in a hidden lid stays open).
  auto touches = [&](const Box& a, const Box& b) {
    for (int k = 0; k < D; ++k)
      if (a.max[k] < b.min[k] || b.max[k] < a.min[k]) return false;
    return true;
  };
  for (const Vent& vent : config.vents) {
    bool in_hidden_wall = false;
    for (const Region& region : config.regions)
      in_hidden_wall = in_hidden_wall || (region.material == Material::Wall && hidden(region.name) &&
                                          touches(region.box, vent.box));
    if (!in_hidden_wall) drawWall(vent.box, vent.name);
  }
  if (texture)
    for (std::size_t i = 0; i < texture->position.size(); ++i) {
      const Vec3& x = texture->position[i];
      switch (texture->kind[i]) {
        case TextureKind::Mist: s.mist.push_back(x); break;
        case TextureKind::MicroBubble: s.micro_bubbles.push_back(x); break;
        case TextureKind::Droplet: break;  // the frame's droplets are drawn
        case TextureKind::Bubble: c.bubbles.push_back(x); break;
      }
    }
  if (r.style == RenderStyle::Lab) {
    if (r.mist) c.mist = s.mist;
    c.micro_bubbles = s.micro_bubbles;
  }
  return s;
}

template FrameScene frameScene<2>(const Particles<2>&, const std::vector<std::uint8_t>&, const CaseConfig&,
                                  const TextureSnapshot*, double);
template FrameScene frameScene<3>(const Particles<3>&, const std::vector<std::uint8_t>&, const CaseConfig&,
                                  const TextureSnapshot*, double);

}  // namespace mistfall
