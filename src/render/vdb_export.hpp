// The volumes of a frame as an OpenVDB file for Blender, Houdini and other renderers (docs/render.md, "Taking a
// run into another renderer"): one float fog-volume grid per DensityGrid, named as given, voxel (i, j, k) of the
// DensityGrid at index (i, j, k) with its centre at origin + h (i + 1/2, j + 1/2, k + 1/2) in the simulation's
// coordinates (metres); only nonzero voxels are stored. Written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/density_grid.hpp"

namespace mistfall {

void writeVdb(const std::filesystem::path& file, const std::vector<std::pair<std::string, const DensityGrid*>>& grids);

// Reads the grid `name` of a file written by writeVdb back onto `like`'s voxels (tests). Throws
// std::runtime_error naming the file when the grid is missing.
DensityGrid readVdbGrid(const std::filesystem::path& file, const std::string& name, const DensityGrid& like);

}  // namespace mistfall
