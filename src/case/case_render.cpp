// The optional [render] table of a case file: camera, light, image sizes and the sizes drawn for the texture
// particles of `mistfall render` (src/render; every key, default and range in docs/case-file.md). Defaults that
// depend on the case (the camera frames the domain) are computed here, so RenderConfig holds the values used.
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
// left of and in front of the camera's side.
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
}

}  // namespace

void readRender(const Reader& rd, const toml::table& root, CaseConfig& c) {
  const std::string p = "render";
  RenderConfig& r = c.render;
  r.extrusion_width = c.texture.width;
  r.mist_radius = r.micro_bubble_radius = 0.25 * c.numerics.particle_spacing;
  const toml::table& t = rd.table(root, "", p);
  rd.checkKeys(t, p,
               {"camera_location", "camera_look_at", "camera_angle", "light_location", "image_width", "image_height",
                "preview_width", "preview_height", "extrusion_width", "frame_rate", "mist_radius",
                "micro_bubble_radius"});
  rd.number(t, p, "camera_angle", {0.0, 180.0, true, true}, r.camera_angle);
  rd.integer(t, p, "image_width", 16, 8192, "[16, 8192]", r.image_width);
  rd.integer(t, p, "image_height", 16, 8192, "[16, 8192]", r.image_height);
  rd.integer(t, p, "preview_width", 16, 8192, "[16, 8192]", r.preview_width);
  rd.integer(t, p, "preview_height", 16, 8192, "[16, 8192]", r.preview_height);
  rd.number(t, p, "extrusion_width", {0.0, 1e3, true, false}, r.extrusion_width);
  rd.number(t, p, "frame_rate", {1.0, 120.0, false, false}, r.frame_rate);
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
