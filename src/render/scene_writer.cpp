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

void volume(std::ostream& out, const std::string& prefix, const VolumeFile& v) {
  out << "#declare " << prefix << "_File = \"" << v.file << "\";\n#declare " << prefix << "_Min = " << vec(v.min)
      << ";\n#declare " << prefix << "_Max = " << vec(v.max) << ";\n#declare " << prefix
      << "_Extinction = " << v.extinction << ";  // [1/m] at density 1\n";
}

}  // namespace

std::string styleInclude(RenderStyle style) { return style == RenderStyle::Natural ? "natural.inc" : "lab.inc"; }

std::string sceneText(const RenderConfig& r, const SceneContent& c, const std::string& title) {
  std::ostringstream out;
  out.precision(9);
  out << "// " << title << " -- written by mistfall render; the look is in materials.inc and "
      << styleInclude(r.style) << "\n#version 3.7;\n"
      << "global_settings { assumed_gamma 1.0 max_trace_level 8 adc_bailout 0.01 }\n\n"
      << "#declare Frame_Time = " << c.time << ";\n"
      << "#declare Up = " << vec(axis(c.up_axis)) << ";\n"
      << "#declare Camera_Location = " << vec(r.camera_location) << ";\n"
      << "#declare Camera_Look_At = " << vec(r.camera_look_at) << ";\n"
      << "#declare Sun_Location = " << vec(r.light_location) << ";\n"
      << "#declare Scene_Min = " << vec(c.scene_box.min) << ";\n"
      << "#declare Scene_Max = " << vec(c.scene_box.max) << ";\n"
      << "#declare Ground_Level = " << c.ground << ";\n"
      << "#declare Water_Width = " << c.water_width << ";  // across a 2D run's fall (0 in 3D)\n"
      << "#declare Bank_Level = " << r.bank_level << ";\n"
      << "#declare Bank_Width = " << r.bank_width << ";\n"
      << "#declare Wall_Count = " << c.walls.size() << ";\n";
  if (!c.walls.empty()) {
    out << "#declare Wall_Min = array[" << c.walls.size() << "] {";
    for (std::size_t i = 0; i < c.walls.size(); ++i) out << (i ? ", " : " ") << vec(c.walls[i].min);
    out << " };\n#declare Wall_Max = array[" << c.walls.size() << "] {";
    for (std::size_t i = 0; i < c.walls.size(); ++i) out << (i ? ", " : " ") << vec(c.walls[i].max);
    out << " };\n#declare Wall_Name = array[" << c.walls.size() << "] {";
    for (std::size_t i = 0; i < c.walls.size(); ++i) out << (i ? ", \"" : " \"") << c.wall_names[i] << '"';
    out << " };\n";
  }
  out << "\ncamera {\n  perspective\n  location Camera_Location\n  sky Up\n  up Up\n"
      << "  right -x * image_width / image_height  // right-handed\n  angle " << r.camera_angle
      << "\n  look_at Camera_Look_At\n}\n\n#include \"materials.inc\"\n#include \"" << styleInclude(r.style)
      << "\"\n";
  if (!c.mesh_include.empty()) {
    out << "\n#include \"" << c.mesh_include << "\"\n";
    if (c.white_water) volume(out, "White_Water", *c.white_water);
    out << "Water(" << (c.white_water ? "true" : "false") << ")\n";
  }
  spheres(out, c.droplets, c.droplet_radius, "M_Droplet", "droplets");
  spheres(out, c.bubbles, c.bubble_radius, "M_Bubble", "bubbles");
  spheres(out, c.mist, c.mist_radius, "M_Mist", "mist", false);
  spheres(out, c.micro_bubbles, c.micro_bubble_radius, "M_MicroBubble", "micro-bubbles", false);
  if (c.mist_volume) {
    out << "\n// mist: a participating medium\n";
    volume(out, "Mist", *c.mist_volume);
    out << "Mist()\n";
  }
  return out.str();
}

void writeScene(const std::filesystem::path& file, const RenderConfig& render, const SceneContent& content,
                const std::string& title) {
  const std::string text = sceneText(render, content, title);
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace mistfall
