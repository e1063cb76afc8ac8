// Particle fields sampled onto a uniform grid, for the flow pictures of the paper (Fig. 4: gas and liquid
// velocity; Fig. 5: turbulence intensity from the SPS energy k of eqs. (25)-(26)), written as VTK XML
// ImageData (.vti). Each node x gets the weighted mean over the selected particles within the radius R,
//   f(x) = sum_j w_j f_j / sum_j w_j,   w_j = w(|x_j - x|) = R / r - 1 for 0 < r < R (MPS weight, eq. (14)),
// and the total weight sum_j w_j as "coverage" (0 where no particle is near; the mean is written as 0 there).
// The distance is floored at R/4 (w <= 3): the weight of eq. (14) is infinite at r = 0 (mps/weight.hpp returns
// 0 there, for self-pairs), so a particle on or next to a node would otherwise flip between swamping the node
// and vanishing from it. The mean of a linear field stays exact at centres of symmetry of a full lattice.
// Particles are binned into cells of edge R, so sampling costs O(N + nodes * particles per cell).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

// More grid nodes than this is taken as a mistake in the cell size (it would need tens of GB): refused by the
// sampler and the .vti reader.
inline constexpr double kMaxGridNodes = 1e9;

// The default sampling radius in particle spacings (R = 2.1 l0, the number-density radius of MPS).
inline constexpr double kGridSamplingRadiusRatio = 2.1;

// Nodes lower + h k, k = 0 .. n - 1 per axis, with n = floor((upper - lower) / h) + 1 (a node lands on `upper`
// when the box is a whole number of cells). `radius` is R above (use kGridSamplingRadiusRatio * l0).
template <int D>
struct GridSpec {
  Vec<D> lower = Vec<D>::Zero();
  Vec<D> upper = Vec<D>::Zero();
  double cell_size = 0.0;  // h [m]
  double radius = 0.0;     // R [m]
};

// Node counts per axis of `grid`; throws std::invalid_argument (one line) on a bad box, h or R.
template <int D>
std::array<std::int64_t, 3> gridNodeCounts(const GridSpec<D>& grid);

// One point-data array: `components` values per node, nodes in VTK order (x fastest, then y, then z).
struct GridArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// A uniform grid with point data, as written to / read from a .vti file. 2D grids have dims[2] == 1.
struct ImageData {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<std::int64_t, 3> dims{1, 1, 1};  // nodes per axis
  double time = 0.0;                          // written as FieldData "TimeValue"
  std::vector<GridArray> arrays;

  std::size_t nodeCount() const { return static_cast<std::size_t>(dims[0] * dims[1] * dims[2]); }
  const GridArray* find(const std::string& name) const {
    for (const auto& a : arrays)
      if (a.name == name) return &a;
    return nullptr;
  }
};

// Weighted means of a per-particle field: `values` holds `components` numbers per particle; only particles with
// selected[j] != 0 count. mean: components per node (0 where coverage is 0); coverage: sum_j w_j per node.
struct GridSamples {
  std::vector<double> mean;
  std::vector<double> coverage;
};
template <int D>
GridSamples sampleOnGrid(const GridSpec<D>& grid, const std::vector<Vec<D>>& position,
                         const std::vector<char>& selected, const std::vector<double>& values, int components);

// The flow fields of Figs. 4-5 on `grid`, with particles selected[j] != 0 split by phase:
//   gas_velocity, liquid_velocity (3 components, z = 0 in 2D), gas_sps_k, liquid_sps_k (k of eq. (25)),
//   gas_coverage, liquid_coverage. `sps_k` holds k per particle (see mps/sps_turbulence.hpp).
template <int D>
ImageData sampleFlowFieldsMasked(const GridSpec<D>& grid, const Particles<D>& p, const std::vector<double>& sps_k,
                                 const std::vector<char>& selected, double time);

// Same, selecting the active particles for which include(std::int32_t j) holds (e.g. kind Fluid: no walls).
template <int D, class Include>
ImageData sampleFlowFields(const GridSpec<D>& grid, const Particles<D>& p, const std::vector<double>& sps_k,
                           double time, Include&& include) {
  std::vector<char> selected(p.size());
  for (std::size_t j = 0; j < p.size(); ++j)
    selected[j] = isActive(p.kind[j]) && include(static_cast<std::int32_t>(j));
  return sampleFlowFieldsMasked<D>(grid, p, sps_k, selected, time);
}

// Writes `image` atomically as VTK XML ImageData: Float64 point data, appended raw little-endian with UInt64
// block headers (ascii = false) or inline text with 17 significant digits (ascii = true); the time as FieldData
// "TimeValue". Throws std::invalid_argument if an array's size does not match the grid.
void writeVti(const std::filesystem::path& file, const ImageData& image, bool ascii = false);

// Reads a .vti written by writeVti (binary or ascii). Throws std::runtime_error naming the path on bad input.
ImageData readVti(const std::filesystem::path& file);

}  // namespace mistfall
