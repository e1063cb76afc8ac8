// POV-Ray scene text of one frame (see scene_writer.hpp).
#include "render/scene_writer.hpp"

#include <sstream>

#include "io/atomic_file.hpp"

namespace mistfall {

namespace {

std::string vec(const std::array<double, 3>& v) {
  std::ostringstream s;
  s.precision(9);
  s << '<' << v[0] << ", " << v[1] << ", " << v[2] << '>';
  return s.str();
}

std::string vec(const Vec<3>& v) { return vec(std::array<double, 3>{v.x(), v.y(), v.z()}); }

std::array<double, 3> axis(int k, double length = 1.0) {
  std::array<double, 3> a{0.0, 0.0, 0.0};
  a[k] = length;
  return a;
}

// A union of equal spheres with one material; nothing for no spheres (POV-Ray rejects an empty union).
void spheres(std::ostream& out, const std::vector<Vec<3>>& centres, double radius, const char* material,
             const char* comment, bool shadows = true) {
  if (centres.empty()) return;
  out << "\n// " << comment << ": " << centres.size() << "\nunion {\n";
  for (const auto& c : centres) out << "  sphere { " << vec(c) << ", " << radius << " }\n";
  if (centres.size() == 1) out << "  sphere { " << vec(centres[0]) << ", 0 }\n";  // a union needs two objects
  out << "  material { " << material << " }\n" << (shadows ? "" : "  no_shadow\n") << "}\n";
}

}  // namespace

std::string sceneText(const RenderConfig& r, const SceneContent& c, const std::string& title) {
  std::ostringstream out;
  out.precision(9);
  out << "// " << title << " -- written by mistfall render; materials in materials.inc\n"
      << "#version 3.7;\n#include \"materials.inc\"\n"
      << "global_settings { assumed_gamma 1.0 max_trace_level 16 }\n"
      << "background { C_Background }\n\n"
      << "camera {\n  perspective\n  location " << vec(r.camera_location) << "\n  sky " << vec(axis(c.up_axis))
      << "\n  up " << vec(axis(c.up_axis)) << "\n  right -x * image_width / image_height  // right-handed\n"
      << "  angle " << r.camera_angle << "\n  look_at " << vec(r.camera_look_at) << "\n}\n"
      << "light_source { " << vec(r.light_location) << " color rgb 1.0 }\n"
      << "light_source { " << vec(r.camera_location) << " color rgb 0.3 shadowless }\n\n"
      << "plane { " << vec(axis(c.up_axis)) << ", " << c.ground << " texture { T_Ground } }\n";
  for (const Box& w : c.walls) out << "box { " << vec(w.min) << ", " << vec(w.max) << " texture { T_Wall } }\n";
  if (!c.mesh_include.empty())
    out << "\n#include \"" << c.mesh_include << "\"\nobject { Water_Surface material { M_Water } }\n";
  spheres(out, c.droplets, c.droplet_radius, "M_Droplet", "droplets");
  spheres(out, c.bubbles, c.bubble_radius, "M_Bubble", "bubbles");
  spheres(out, c.mist, c.mist_radius, "M_Mist", "mist", false);
  spheres(out, c.micro_bubbles, c.micro_bubble_radius, "M_MicroBubble", "micro-bubbles", false);
  return out.str();
}

void writeScene(const std::filesystem::path& file, const RenderConfig& render, const SceneContent& content,
                const std::string& title) {
  const std::string text = sceneText(render, content, title);
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace mistfall
