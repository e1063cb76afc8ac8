// Spatial order of the particle arrays (issue 17: cheaper steps). The operators visit each particle's neighbours
// and the pressure matrices have a row per particle, so particles that are neighbours in space should sit near each
// other in memory; inflows append, outflows compact and the flow mixes, so the order made by the case's lattice
// decays. Sorting the arrays by the cell of a grid (spacing `cell`, about the neighbour radius; cells in row-major
// order, the last axis slowest; stable within a cell) restores it. Measured on waterfall.toml at 5.4-5.5 s (1
// thread): 159 -> 115 ms a step sorted every 100 steps (solver.cpp kSortInterval). Results change at round-off (sums in another
// order), never in kind; the order is a function of the state only, so a resumed run stays bit-identical.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "mps/vector.hpp"

namespace mistfall {

// The permutation that sorts `position` by cell: order[k] is the index of the particle that goes to place k.
template <int D>
std::vector<std::size_t> spatialOrder(const std::vector<Vec<D>>& position, const Vec<D>& lower,
                                      const Vec<D>& upper, double cell) {
  std::array<std::uint64_t, D> cells{};
  for (int d = 0; d < D; ++d)
    cells[d] = static_cast<std::uint64_t>(std::max(1.0, std::ceil((upper[d] - lower[d]) / cell))) + 1;
  std::vector<std::uint64_t> key(position.size());
  for (std::size_t i = 0; i < position.size(); ++i) {
    std::uint64_t k = 0;
    for (int d = D - 1; d >= 0; --d) {
      const double x = (position[i][d] - lower[d]) / cell;  // outside the domain or not finite: the edge cell
      const auto c = std::isfinite(x) ? static_cast<std::uint64_t>(std::clamp(x, 0.0, double(cells[d] - 1))) : 0;
      k = k * cells[d] + c;
    }
    key[i] = k;
  }
  std::vector<std::size_t> order(position.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return order;
}

// Puts entry order[k] of every array at place k.
template <class... Arrays>
void permuteAll(const std::vector<std::size_t>& order, Arrays&... arrays) {
  auto apply = [&](auto& array) {
    auto copy = array;
    for (std::size_t k = 0; k < order.size(); ++k) array[k] = copy[order[k]];
  };
  (apply(arrays), ...);
}

}  // namespace mistfall
