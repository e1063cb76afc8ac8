// The optional [render] table of a case file: style, camera, sun, image sizes, the water's extrusion and the
// volumes of `mistfall render` (src/render; every key, default and range in docs/case-file.md). Defaults that
// depend on the case (the camera frames the domain) are computed here, so RenderConfig holds the values used.
#include <algorithm>
#include <cmath>

#include "case/case_config.hpp"
#include "case/toml_reader.hpp"

namespace mistfall::detail {

namespace {

// The scene's box: the domain, and in 2D z across the extrusion.
Box sceneBox(const CaseConfig& c) {
  Box b = c.domain;
  if (c.dimension == 2) b.min[2] = -0.5 * c.render.extrusion_width, b.max[2] = 0.5 * c.render.extrusion_width;
  return b;
}

// Default camera and light: look at the scene box's centre from the front (3D: from -y, z up; 2D: from +z, y up),
// from far enough that the box's width and height fill 85 % of the view, a little from above; the light above,
// left of and in front of the camera's side. The natural style raises the camera by another half of that extent
// and turns it 35 degrees about the up axis toward +x (downstream): a three-quarter view from above.
void defaultView(const CaseConfig& c, RenderConfig& r) {
  const Box b = sceneBox(c);
  const int up = c.dimension == 3 ? 2 : 1, depth = c.dimension == 3 ? 1 : 2;
  const double toward_camera = c.dimension == 3 ? -1.0 : 1.0;
  const double extent = std::max(b.max[0] - b.min[0], b.max[up] - b.min[up]);
  const double height_ratio = static_cast<double>(r.image_height) / r.image_width;
  const double half_angle = 0.5 * r.camera_angle * M_PI / 180.0;
  const double fit = std::max(b.max[0] - b.min[0], (b.max[up] - b.min[up]) / height_ratio);
  const double distance = 0.5 * fit / 0.85 / std::tan(half_angle) + 0.5 * (b.max[depth] - b.min[depth]);
  for (int k = 0; k < 3; ++k) r.camera_look_at[k] = 0.5 * (b.min[k] + b.max[k]);
  r.camera_location = r.camera_look_at;
  r.camera_location[depth] += toward_camera * distance;
  r.camera_location[up] += 0.2 * extent;
  r.light_location = r.camera_look_at;
  r.light_location[0] -= 1.0 * extent;
  r.light_location[up] += 2.0 * extent;
  r.light_location[depth] += toward_camera * 2.0 * extent;
  if (r.style == RenderStyle::Natural) {  // from higher up: the water sits in a basin below the banks
    r.camera_location[up] += 0.5 * extent;
    const double a = 35.0 * M_PI / 180.0;
    const double dx = r.camera_location[0] - r.camera_look_at[0];
    const double dd = r.camera_location[depth] - r.camera_look_at[depth];
    r.camera_location[0] = r.camera_look_at[0] + std::cos(a) * dx + std::sin(a) * std::abs(dd);
    r.camera_location[depth] = r.camera_look_at[depth] + std::cos(a) * dd - toward_camera * std::sin(a) * dx;
  }
}

// Top of the basin's banks: the top of the water region that reaches lowest, plus 2 l0 (the domain's floor when
// there is none).
double defaultBankLevel(const CaseConfig& c) {
  const int up = c.dimension - 1;
  double bottom = 1e300, top = c.domain.min[up];
  for (const Region& region : c.regions) {
    if (region.material != Material::Water) continue;
    if (region.box.min[up] < bottom) bottom = region.box.min[up], top = region.box.max[up];  // circles: their box
  }
  return top + 2.0 * c.numerics.particle_spacing;
}

// render.hidden_regions: names of wall regions.
void readHiddenRegions(const Reader& rd, const toml::table& t, const std::string& p, CaseConfig& c) {
  const Field f = rd.field(t, p, "hidden_regions");
  if (!f.node) return;
  const std::string allowed = "an array of names of wall regions";
  const toml::array* a = f.node->as_array();
  if (!a) rd.wrongType(f, allowed);
  for (const toml::node& n : *a) {
    const auto* name = n.as_string();
    if (!name) rd.wrongType(f, allowed);
    const std::string s = name->get();
    const auto it = std::find_if(c.regions.begin(), c.regions.end(), [&](const Region& r) { return r.name == s; });
    if (it == c.regions.end() || it->material != Material::Wall) {
      std::string walls;
      for (const Region& r : c.regions)
        if (r.material == Material::Wall) walls += (walls.empty() ? "'" : ", '") + r.name + "'";
      rd.fail(f.path + " names '" + s + "', which is not a wall region; allowed " +
              (walls.empty() ? std::string("none (the case has no wall regions)") : walls));
    }
    c.render.hidden_regions.push_back(s);
  }
}

}  // namespace

void readRender(const Reader& rd, const toml::table& root, CaseConfig& c) {
  const std::string p = "render";
  RenderConfig& r = c.render;
  const double l0 = c.numerics.particle_spacing;
  r.extrusion_width = c.texture.width;
  r.mist_radius = r.micro_bubble_radius = 0.25 * l0;
  r.sheet_variation = 0.3 * l0;
  r.variation_length = 5.0 * l0;
  r.mist_voxel = l0;
  r.frame_interval = c.output.interval;
  r.bank_level = defaultBankLevel(c);
  const int up = c.dimension - 1;
  r.bank_width = 0.5 * std::max(c.domain.max[0] - c.domain.min[0], c.domain.max[up] - c.domain.min[up]);
  const toml::table& t = rd.table(root, "", p);
  rd.checkKeys(t, p,
               {"style", "camera_location", "camera_look_at", "camera_angle", "light_location", "image_width",
                "image_height", "preview_width", "preview_height", "antialias", "frame_interval", "extrusion_width",
                "sheet_variation", "variation_length", "hidden_regions", "bank_level", "bank_width", "frame_rate",
                "mist", "mist_voxel", "white_water", "white_water_bubble_diameter", "mist_radius",
                "micro_bubble_radius"});
  if (int s = rd.choice(t, p, "style", {"natural", "lab"}); s >= 0) r.style = static_cast<RenderStyle>(s);
  rd.number(t, p, "camera_angle", {0.0, 180.0, true, true}, r.camera_angle);
  rd.integer(t, p, "image_width", 16, 8192, "[16, 8192]", r.image_width);
  rd.integer(t, p, "image_height", 16, 8192, "[16, 8192]", r.image_height);
  rd.integer(t, p, "preview_width", 16, 8192, "[16, 8192]", r.preview_width);
  rd.integer(t, p, "preview_height", 16, 8192, "[16, 8192]", r.preview_height);
  rd.number(t, p, "antialias", {0.0, 3.0, false, false}, r.antialias);
  rd.number(t, p, "frame_interval", {0.0, 1e6, true, false}, r.frame_interval);
  rd.number(t, p, "extrusion_width", {0.0, 1e3, true, false}, r.extrusion_width);
  rd.number(t, p, "sheet_variation", {0.0, 1.0, false, false}, r.sheet_variation);
  rd.number(t, p, "variation_length", {0.0, 1e3, true, false}, r.variation_length);
  readHiddenRegions(rd, t, p, c);
  rd.number(t, p, "bank_level", {-1e6, 1e6, false, false}, r.bank_level);
  rd.number(t, p, "bank_width", {0.0, 1e6, false, false}, r.bank_width);
  rd.number(t, p, "frame_rate", {1.0, 120.0, false, false}, r.frame_rate);
  rd.boolean(t, p, "mist", r.mist);
  rd.number(t, p, "mist_voxel", {0.0, 1.0, true, false}, r.mist_voxel);
  rd.boolean(t, p, "white_water", r.white_water);
  rd.number(t, p, "white_water_bubble_diameter", {0.0, 1.0, true, false}, r.white_water_bubble_diameter);
  rd.number(t, p, "mist_radius", {0.0, 1.0, true, false}, r.mist_radius);
  rd.number(t, p, "micro_bubble_radius", {0.0, 1.0, true, false}, r.micro_bubble_radius);
  defaultView(c, r);
  rd.vector(t, p, "camera_location", 3, r.camera_location);
  rd.vector(t, p, "camera_look_at", 3, r.camera_look_at);
  rd.vector(t, p, "light_location", 3, r.light_location);
  double gap = 0.0;
  for (int k = 0; k < 3; ++k) gap += std::pow(r.camera_location[k] - r.camera_look_at[k], 2);
  if (!(gap > 0.0))
    rd.fail("render.camera_location equals render.camera_look_at; allowed a location away from the point looked at");
}

}  // namespace mistfall::detail
