// MPS particle number density:  n_i = sum_{j != i} w(|r_j - r_i|),  w from eq. (14).
#pragma once

#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/weight.hpp"

namespace mistfall {

template <int D>
double numberDensityAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighborList& nl, double re) {
  double n = 0.0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    n += weight((position[j] - position[i]).norm(), re);
  }
  return n;
}

// Number density counting only the neighbours `include(j)` admits (one phase's view in the two-phase model).
template <int D, class Include>
double numberDensityAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighborList& nl, double re,
                       Include&& include) {
  double n = 0.0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (include(j)) n += weight((position[j] - position[i]).norm(), re);
  }
  return n;
}

// Number density of every active particle (escaped particles get 0).
template <int D>
void computeNumberDensity(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                          const NeighborList& nl, double re, std::vector<double>& n) {
  const std::int64_t count = static_cast<std::int64_t>(position.size());
  n.resize(count);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i)
    n[i] = isActive(kind[i]) ? numberDensityAt<D>(i, position, nl, re) : 0.0;
}

}  // namespace mistfall
