// Spatial order of the particle arrays (issue 17: cheaper steps). The operators visit each particle's neighbours
// and the pressure matrices have a row per particle, so particles that are neighbours in space should sit near each
// other in memory; inflows append, outflows compact and the flow mixes, so the order made by the case's lattice
// decays. Sorting the arrays by the cell of the neighbour search's grid (cells in row-major order, the last axis
// slowest; stable within a cell) restores it, and makes the build's cell lists runs of consecutive particles.
// Measured on waterfall.toml at 5.4-5.5 s (1 thread): 159 -> 118 ms a step sorted every 100 steps (solver.cpp
// kSortInterval), 103 with the search's cells a third of its reach (neighbour_search.cpp). Results change at
// round-off (sums in another order), never in kind; the order is a function of the state only, so a resumed run
// stays bit-identical.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace mistfall {

// The permutation that sorts particles by `key` (their cell, NeighbourSearch::cellKey), stable: order[k] is the
// index of the particle that goes to place k.
inline std::vector<std::size_t> orderByKey(const std::vector<std::int64_t>& key) {
  std::vector<std::size_t> order(key.size());
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
