// The files povray reads for one frame, and the exports for other renderers (docs/render.md). From the frame
// RUN_DIR/frames/frame_NNNNN.vtp (and RUN_DIR/texture/texture_NNNNN.bin when there is one) into RENDER_DIR:
//   mesh_NNNNN.inc     the water surface (POV-Ray mesh2, `#declare Water_Surface`): a 2D run's section meshed and
//                      extruded (section_mesh.hpp), a 3D run's particles through OpenVDB (surface_mesh.hpp);
//   mist_NNNNN.df3     the mist's density, white_NNNNN.df3 the white water's (frame_volumes.hpp), when present;
//   scene_NNNNN.pov    the scene (scene_writer.hpp).
// These are the intermediates: `mistfall render` deletes them once the frame's image exists, unless asked to keep
// them. With exports on (`render --export`) it also writes, kept: export/water_NNNNN.ply (binary PLY with normals) and
// export/volumes_NNNNN.vdb (OpenVDB float grids "mist" (volume fraction of water in the air) and "white_water"
// (extinction [1/m]), in the simulation's coordinates, metres).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "case/case_config.hpp"

namespace mistfall {

struct FrameFiles {
  std::vector<std::filesystem::path> intermediates;  // to delete after povray
  double read_s = 0.0, mesh_s = 0.0, volumes_s = 0.0, write_s = 0.0;  // seconds of each step
  std::size_t triangles = 0, mist = 0, air = 0;  // triangles of the water, mist representatives, air particles
  double mist_volume = 0.0;                      // [m^3] represented by the mist grid
};

template <int D>
FrameFiles writeFrameFiles(const std::filesystem::path& vtp, const std::string& number, const CaseConfig& config,
                           const std::filesystem::path& run_dir, const std::filesystem::path& render_dir,
                           bool export_files);

}  // namespace mistfall
