// Particle fields on a uniform grid (weighted means with the MPS weight, eq. (14)); the .vti writer and reader are
// vti_file.cpp.
#include "io/grid_fields.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/text_format.hpp"
#include "mps/weight.hpp"

namespace mistfall {

namespace {

// The distance in the weight is floored at this fraction of R (see grid_fields.hpp).
constexpr double kWeightCoreRatio = 0.25;

using Cell = std::array<std::int64_t, 3>;

}  // namespace

template <int D>
std::array<std::int64_t, 3> gridNodeCounts(const GridSpec<D>& grid) {
  if (!(grid.cell_size > 0.0) || !std::isfinite(grid.cell_size))
    throw std::invalid_argument("grid cell size must be positive, got " + text::formatDouble(grid.cell_size, 6));
  if (!(grid.radius > 0.0) || !std::isfinite(grid.radius))
    throw std::invalid_argument("grid sampling radius must be positive, got " + text::formatDouble(grid.radius, 6));
  std::array<std::int64_t, 3> n{1, 1, 1};
  double total = 1.0;
  for (int k = 0; k < D; ++k) {
    const double extent = grid.upper[k] - grid.lower[k];
    if (!std::isfinite(grid.lower[k]) || !std::isfinite(extent) || extent < 0.0)
      throw std::invalid_argument("grid box: upper corner must not lie below the lower corner (axis " +
                                  std::to_string(k) + ")");
    // The small allowance keeps a node on `upper` when extent / h is a whole number up to rounding.
    const double cells = std::floor(extent / grid.cell_size + 1e-9);
    total *= cells + 1.0;
    if (total > kMaxGridNodes)
      throw std::invalid_argument("grid of more than 1e9 nodes: cell size " + text::formatDouble(grid.cell_size, 6) +
                                  " m is too small for the box");
    n[k] = static_cast<std::int64_t>(cells) + 1;
  }
  return n;
}

template <int D>
GridSamples sampleOnGrid(const GridSpec<D>& grid, const std::vector<Vec<D>>& position,
                         const std::vector<char>& selected, const std::vector<double>& values, int components) {
  const auto nodes = gridNodeCounts<D>(grid);
  if (components < 1) throw std::invalid_argument("grid sampling: components must be at least 1");
  const std::size_t np = position.size();
  const auto comp = static_cast<std::size_t>(components);
  if (selected.size() != np || values.size() != np * comp)
    throw std::invalid_argument("grid sampling: " + std::to_string(np) + " particles but " +
                                std::to_string(selected.size()) + " selection flags and " +
                                std::to_string(values.size()) + " values (" + std::to_string(components) +
                                " per particle)");
  const double radius = grid.radius;
  const double r_core = kWeightCoreRatio * radius;

  // Bins of edge R over the box grown by R: every particle within R of a node lies in one of them.
  const Vec<D> bin_lower = grid.lower.array() - radius;
  Cell bins{1, 1, 1};
  for (int k = 0; k < D; ++k)
    bins[k] = static_cast<std::int64_t>(std::floor((grid.upper[k] - grid.lower[k] + 2.0 * radius) / radius)) + 1;
  const std::int64_t nbins = bins[0] * bins[1] * bins[2];
  auto binOf = [&](const Vec<D>& x, Cell& c) {
    c = {0, 0, 0};
    for (int k = 0; k < D; ++k) {
      const double f = std::floor((x[k] - bin_lower[k]) / radius);
      if (!(f >= 0.0) || f >= static_cast<double>(bins[k])) return false;  // also false for NaN
      c[k] = static_cast<std::int64_t>(f);
    }
    return true;
  };
  auto binIndex = [&](const Cell& c) { return (c[2] * bins[1] + c[1]) * bins[0] + c[0]; };

  // Counting sort of the selected particles into bins (index order inside a bin: thread-count independent).
  std::vector<std::int64_t> bin_of(np, -1);
  std::vector<std::int64_t> start(static_cast<std::size_t>(nbins) + 1, 0);
  for (std::size_t j = 0; j < np; ++j) {
    Cell c;
    if (selected[j] && binOf(position[j], c)) {
      bin_of[j] = binIndex(c);
      ++start[static_cast<std::size_t>(bin_of[j]) + 1];
    }
  }
  for (std::int64_t b = 0; b < nbins; ++b) start[b + 1] += start[b];
  std::vector<std::int32_t> sorted(static_cast<std::size_t>(start[nbins]));
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t j = 0; j < np; ++j)
      if (bin_of[j] >= 0) sorted[fill[bin_of[j]]++] = static_cast<std::int32_t>(j);
  }

  const std::int64_t total = nodes[0] * nodes[1] * nodes[2];
  GridSamples out;
  out.mean.assign(static_cast<std::size_t>(total) * comp, 0.0);
  out.coverage.assign(static_cast<std::size_t>(total), 0.0);
#pragma omp parallel
  {
    std::vector<double> acc(comp);
#pragma omp for schedule(static)
    for (std::int64_t node = 0; node < total; ++node) {
      const Cell idx{node % nodes[0], (node / nodes[0]) % nodes[1], node / (nodes[0] * nodes[1])};
      Vec<D> x;
      for (int k = 0; k < D; ++k) x[k] = grid.lower[k] + grid.cell_size * static_cast<double>(idx[k]);
      Cell c, lo{0, 0, 0}, hi{0, 0, 0};
      binOf(x, c);  // nodes lie inside the grown box
      for (int k = 0; k < D; ++k) {
        lo[k] = std::max<std::int64_t>(c[k] - 1, 0);
        hi[k] = std::min<std::int64_t>(c[k] + 1, bins[k] - 1);
      }
      std::fill(acc.begin(), acc.end(), 0.0);
      double wsum = 0.0;
      for (std::int64_t bz = lo[2]; bz <= hi[2]; ++bz)
        for (std::int64_t by = lo[1]; by <= hi[1]; ++by)
          for (std::int64_t bx = lo[0]; bx <= hi[0]; ++bx) {
            const std::int64_t b = binIndex({bx, by, bz});
            for (std::int64_t s = start[b]; s < start[b + 1]; ++s) {
              const auto j = static_cast<std::size_t>(sorted[s]);
              const double w = weight(std::max((position[j] - x).norm(), r_core), radius);
              if (w <= 0.0) continue;
              wsum += w;
              for (std::size_t a = 0; a < comp; ++a) acc[a] += w * values[j * comp + a];
            }
          }
      const auto n = static_cast<std::size_t>(node);
      out.coverage[n] = wsum;
      if (wsum > 0.0)
        for (std::size_t a = 0; a < comp; ++a) out.mean[n * comp + a] = acc[a] / wsum;
    }
  }
  return out;
}

template <int D>
ImageData sampleFlowFieldsMasked(const GridSpec<D>& grid, const Particles<D>& p, const std::vector<double>& sps_k,
                                 const std::vector<char>& selected, double time) {
  const auto nodes = gridNodeCounts<D>(grid);
  if (sps_k.size() != p.size())
    throw std::invalid_argument("flow fields: " + std::to_string(sps_k.size()) + " SPS k values for " +
                                std::to_string(p.size()) + " particles");
  if (selected.size() != p.size())
    throw std::invalid_argument("flow fields: " + std::to_string(selected.size()) + " selection flags for " +
                                std::to_string(p.size()) + " particles");
  ImageData image;
  image.dims = nodes;
  image.time = time;
  for (int k = 0; k < 3; ++k) {
    image.origin[k] = k < D ? grid.lower[k] : 0.0;
    image.spacing[k] = grid.cell_size;
  }
  // Velocity (D components) and k packed per particle, so each phase is sampled in one pass.
  constexpr int kComp = D + 1;
  std::vector<double> packed(p.size() * kComp);
  for (std::size_t j = 0; j < p.size(); ++j) {
    for (int a = 0; a < D; ++a) packed[j * kComp + a] = p.velocity[j][a];
    packed[j * kComp + D] = sps_k[j];
  }
  const std::size_t total = image.nodeCount();
  std::vector<GridArray> velocities, energies, coverages;
  for (const auto& [phase, name] : {std::pair{Phase::Gas, "gas"}, std::pair{Phase::Liquid, "liquid"}}) {
    std::vector<char> mask(p.size());
    for (std::size_t j = 0; j < p.size(); ++j) mask[j] = selected[j] && p.phase[j] == phase;
    GridSamples s = sampleOnGrid<D>(grid, p.position, mask, packed, kComp);
    GridArray u{std::string(name) + "_velocity", 3, std::vector<double>(3 * total, 0.0)};
    GridArray k{std::string(name) + "_sps_k", 1, std::vector<double>(total)};
    for (std::size_t n = 0; n < total; ++n) {
      for (int a = 0; a < D; ++a) u.values[3 * n + a] = s.mean[n * kComp + a];
      k.values[n] = s.mean[n * kComp + D];
    }
    velocities.push_back(std::move(u));
    energies.push_back(std::move(k));
    coverages.push_back({std::string(name) + "_coverage", 1, std::move(s.coverage)});
  }
  for (auto* group : {&velocities, &energies, &coverages})
    for (auto& a : *group) image.arrays.push_back(std::move(a));
  return image;
}

template std::array<std::int64_t, 3> gridNodeCounts<2>(const GridSpec<2>&);
template std::array<std::int64_t, 3> gridNodeCounts<3>(const GridSpec<3>&);
template GridSamples sampleOnGrid<2>(const GridSpec<2>&, const std::vector<Vec<2>>&, const std::vector<char>&,
                                     const std::vector<double>&, int);
template GridSamples sampleOnGrid<3>(const GridSpec<3>&, const std::vector<Vec<3>>&, const std::vector<char>&,
                                     const std::vector<double>&, int);
template ImageData sampleFlowFieldsMasked<2>(const GridSpec<2>&, const Particles<2>&, const std::vector<double>&,
                                             const std::vector<char>&, double);
template ImageData sampleFlowFieldsMasked<3>(const GridSpec<3>&, const Particles<3>&, const std::vector<double>&,
                                             const std::vector<char>&, double);

}  // namespace mistfall
