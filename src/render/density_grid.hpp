// Volumes of the render stage (docs/render.md): points splatted into a regular grid of voxels, for the mist and the
// white water drawn as POV-Ray media (density_file df3) and exported as OpenVDB (vdb_export.hpp).
//
// Each point carries an amount (a volume, say); it is spread over the 3 x 3 x 3 voxels around it with the
// quadratic B-spline weights, whose sum is exactly 1, so the grid's integral (sum of values * h^3) is the sum of
// the amounts of the points inside the grid: value = amount density (amount per m^3).
// A 2D point (a line across the fall) is spread over all the voxels across z at its (x, y), amount per metre.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "case/case_config.hpp"
#include "mps/vector.hpp"

namespace mistfall {

struct DensityGrid {
  Vec<3> origin = Vec<3>::Zero();  // the grid's lower corner; voxel (i, j, k) spans origin + h [i, i+1] x ...
  double h = 0.0;
  std::array<int, 3> n{0, 0, 0};
  std::vector<float> value;        // x fastest, then y, then z

  bool empty() const { return value.empty(); }
  float& at(int i, int j, int k) { return value[(static_cast<std::size_t>(k) * n[1] + j) * n[0] + i]; }
  float at(int i, int j, int k) const { return value[(static_cast<std::size_t>(k) * n[1] + j) * n[0] + i]; }
  Vec<3> upper() const { return origin + h * Vec<3>(n[0], n[1], n[2]); }
  double integral() const;  // sum of values * h^3
  float maximum() const;
};

// A grid of voxel `h` over `bounds` (rounded out to whole voxels), all zero. Empty for an empty box.
DensityGrid emptyGrid(const Box& bounds, double h);

// The box around `points` grown by `margin`, clipped to `clip`; an empty box (min > max) for no points.
Box boundsOf(const std::vector<Vec<3>>& points, double margin, const Box& clip);

// Adds each point's `amount` (amount / h^3 to the values). Points whose kernel leaves the grid lose that part.
void splat(DensityGrid& grid, const std::vector<Vec<3>>& points, double amount);
// 2D points at (x, y), spread evenly across the grid's z: `amount` per metre across.
void splatAcross(DensityGrid& grid, const std::vector<Vec<2>>& points, double amount_per_metre);

// POV-Ray's density file: three big-endian uint16 sizes, then uint16 voxels (x fastest), value / scale * 65535
// rounded; returns scale (the grid's maximum, 1 for an all-zero grid). Written atomically.
double writeDf3(const std::filesystem::path& file, const DensityGrid& grid);

}  // namespace mistfall
