// MPS Laplacian model, eq. (13):
//   <lap phi>_i = 2 D0 / (n0 lambda) * sum_{j != i} (phi_j - phi_i) w(|r_j - r_i|)
// phi may be a scalar (pressure) or a vector (velocity, for the viscous term).
#pragma once

#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/reference_density.hpp"
#include "mps/weight.hpp"

namespace mistfall {

// `include(j)` selects which neighbours take part (e.g. skip escaped or other-phase particles).
template <int D, class T, class Include>
T laplacianAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<T>& phi,
              const NeighborList& nl, const MpsConstants& c, Include&& include) {
  T sum = phi[i] * 0.0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (!include(j)) continue;
    const double w = weight((position[j] - position[i]).norm(), c.re_laplacian);
    if (w > 0.0) sum += (phi[j] - phi[i]) * w;
  }
  return sum * c.laplacianFactor();
}

}  // namespace mistfall
