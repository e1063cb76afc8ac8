// One frame's povray input and exports (see frame_files.hpp).
#include "render/frame_files.hpp"

#include <chrono>
#include <optional>

#include "io/texture_files.hpp"
#include "io/vtk_writer.hpp"
#include "render/frame_scene.hpp"
#include "render/frame_volumes.hpp"
#include "render/mesh_files.hpp"
#include "render/section_mesh.hpp"
#include "render/vdb_export.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};


}  // namespace

template <int D>
FrameFiles writeFrameFiles(const fs::path& vtp, const std::string& number, const CaseConfig& config,
                           const fs::path& run_dir, const fs::path& render_dir, bool export_files) {
  FrameFiles out;
  Stopwatch clock;
  VtpFrameInfo info;
  const Particles<D> p = readVtp<D>(vtp, info);
  const fs::path tex_file = run_dir / "texture" / ("texture_" + number + ".bin");
  std::optional<TextureSnapshot> texture;
  if (fs::exists(tex_file)) texture = readTextureBinary(tex_file);
  FrameScene scene = frameScene<D>(p, info.category, config, texture ? &*texture : nullptr, info.time);
  out.read_s = clock.lap();

  const double l0 = config.numerics.particle_spacing;
  const RenderConfig& r = config.render;
  TriangleMesh mesh;
  if constexpr (D == 2) {
    ExtrusionParameters e;
    e.width = r.extrusion_width;
    e.variation = r.sheet_variation;
    e.variation_length = r.variation_length;
    e.time = info.time;
    e.bevel = 0.25 * l0;
    mesh = extrudeSection(marchingSquares(sectionField(scene.section, {l0}, scene.links)), e);
  } else {
    mesh = liquidSurface(scene.liquid, {l0});
  }
  out.mesh_s = clock.lap();
  out.triangles = mesh.triangles.size();

  const FrameVolumes volumes = frameVolumes(scene, config);
  SceneContent& c = scene.content;
  auto volumeFile = [&](const DensityGrid& g, const std::string& name, double per_value) {
    const fs::path file = render_dir / (name + "_" + number + ".df3");
    const double scale = writeDf3(file, g);
    out.intermediates.push_back(file);
    return VolumeFile{file.filename().string(), g.origin, g.upper(), scale * per_value};
  };
  if (!volumes.mist.empty()) c.mist_volume = volumeFile(volumes.mist, "mist", volumes.mist_extinction);
  if (!volumes.white_water.empty()) c.white_water = volumeFile(volumes.white_water, "white", 1.0);
  out.mist = scene.mist.size();
  out.air = scene.air.size() + scene.air_across.size();
  out.mist_volume = volumes.mist.empty() ? 0.0 : volumes.mist.integral();
  out.volumes_s = clock.lap();

  if (!mesh.triangles.empty()) {
    c.mesh_include = "mesh_" + number + ".inc";
    writePovMesh(render_dir / c.mesh_include, mesh, "Water_Surface");
    out.intermediates.push_back(render_dir / c.mesh_include);
  }
  const fs::path scene_file = render_dir / ("scene_" + number + ".pov");
  writeScene(scene_file, r, c, config.name + ", t = " + std::to_string(info.time) + " s");
  out.intermediates.push_back(scene_file);
  if (export_files) {
    fs::create_directories(render_dir / "export");
    if (!mesh.triangles.empty()) writePly(render_dir / "export" / ("water_" + number + ".ply"), mesh);
    std::vector<std::pair<std::string, const DensityGrid*>> grids;
    if (!volumes.mist.empty()) grids.emplace_back("mist", &volumes.mist);
    if (!volumes.white_water.empty()) grids.emplace_back("white_water", &volumes.white_water);
    if (!grids.empty()) writeVdb(render_dir / "export" / ("volumes_" + number + ".vdb"), grids);
  }
  out.write_s = clock.lap();
  return out;
}

template FrameFiles writeFrameFiles<2>(const fs::path&, const std::string&, const CaseConfig&, const fs::path&,
                                       const fs::path&, bool);
template FrameFiles writeFrameFiles<3>(const fs::path&, const std::string&, const CaseConfig&, const fs::path&,
                                       const fs::path&, bool);

}  // namespace mistfall
