// Render seconds per frame: the first frame of cases/dam_break.toml (2D, 1,250 water particles: the section meshed
// and extruded across render.extrusion_width = 0.1 m) and cases/dam_break_3d.toml (3D, 2,000 water particles,
// OpenVDB), each rendered by povray with one thread at the preview size (192 x 144) and the full size (640 x 480,
// antialiased), in the natural style, as `mistfall render` does. Counters: meshing seconds, povray seconds,
// triangles, and the mesh's volume error against count * l0^D (2D: times the extrusion width). Skipped when povray
// is not installed.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "render/external_tools.hpp"
#include "render/frame_scene.hpp"
#include "render/materials.hpp"
#include "render/mesh_files.hpp"
#include "render/section_mesh.hpp"

using namespace mistfall;
namespace fs = std::filesystem;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <int D>
void renderFrame(benchmark::State& bench, const char* case_file, bool preview) {
  if (!findOnPath("povray")) {
    bench.SkipWithError("povray is not installed (scripts/install-deps.sh)");
    return;
  }
  const CaseConfig c = loadCaseFile(fs::path(MISTFALL_SOURCE_DIR) / case_file);
  const Particles<D> p = buildParticles<D>(c);
  const fs::path dir = fs::temp_directory_path() / "mistfall_bench_render";
  fs::create_directories(dir);
  installMaterials(dir);
  double mesh_s = 0.0, povray_s = 0.0, volume_error = 0.0;
  std::size_t triangles = 0;
  for (auto _ : bench) {
    FrameScene scene = frameScene<D>(p, {}, c, nullptr);
    auto start = std::chrono::steady_clock::now();
    const double l0 = c.numerics.particle_spacing;
    TriangleMesh mesh;
    double expected = 0.0;
    if constexpr (D == 2) {
      ExtrusionParameters e;
      e.width = c.render.extrusion_width;
      e.variation = c.render.sheet_variation;
      e.bevel = 0.25 * l0;
      mesh = extrudeSection(marchingSquares(sectionField(scene.section, {l0}, scene.links)), e);
      expected = scene.section.size() * l0 * l0 * e.width;
    } else {
      mesh = liquidSurface(scene.liquid, {l0});
      expected = scene.liquid.size() * std::pow(l0, 3);
    }
    mesh_s += secondsSince(start);
    triangles = mesh.triangles.size();
    volume_error = enclosedVolume(mesh) / expected - 1.0;
    writePovMesh(dir / "mesh.inc", mesh, "Water_Surface");
    scene.content.mesh_include = "mesh.inc";
    writeScene(dir / "scene.pov", c.render, scene.content, "bench");
    const int w = preview ? c.render.preview_width : c.render.image_width;
    const int h = preview ? c.render.preview_height : c.render.image_height;
    std::vector<std::string> cmd{"povray", "-D", "+FN", "+WT1", "+Iscene.pov", "+Oimage.png",
                                 "+W" + std::to_string(w), "+H" + std::to_string(h), "+Q9"};
    if (!preview) cmd.push_back("+A" + std::to_string(c.render.antialias));
    start = std::chrono::steady_clock::now();
    if (!runProcess(cmd, dir, dir / "povray.log")) bench.SkipWithError("povray failed; see /tmp/mistfall_bench_render");
    povray_s += secondsSince(start);
  }
  const double n = static_cast<double>(bench.iterations());
  bench.counters["mesh_s"] = mesh_s / n;
  bench.counters["povray_s"] = povray_s / n;
  bench.counters["frame_s"] = (mesh_s + povray_s) / n;
  bench.counters["triangles"] = static_cast<double>(triangles);
  bench.counters["volume_error_pct"] = 100.0 * volume_error;
}

void renderFrame2(benchmark::State& bench, const char* case_file, bool preview) {
  renderFrame<2>(bench, case_file, preview);
}
void renderFrame3(benchmark::State& bench, const char* case_file, bool preview) {
  renderFrame<3>(bench, case_file, preview);
}

}  // namespace

BENCHMARK_CAPTURE(renderFrame2, dam_break_2d_preview, "cases/dam_break.toml", true)
    ->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(renderFrame2, dam_break_2d_full, "cases/dam_break.toml", false)
    ->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(renderFrame3, dam_break_3d_preview, "cases/dam_break_3d.toml", true)
    ->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(renderFrame3, dam_break_3d_full, "cases/dam_break_3d.toml", false)
    ->Unit(benchmark::kSecond)->Iterations(1);
