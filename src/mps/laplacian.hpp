// MPS Laplacian model, eq. (13):
//   <lap phi>_i = 2 D0 / (n0 lambda) * sum_{j != i} (phi_j - phi_i) w(|r_j - r_i|)
// phi may be a scalar (pressure) or a vector (velocity, for the viscous term).
#pragma once

#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

// `include(j)` selects which neighbours take part (e.g. skip escaped or other-phase particles).
template <int D, class T, class Include>
T laplacianAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<T>& phi,
              const NeighbourList& nl, const MpsConstants& c, Include&& include) {
  T sum = phi[i] * 0.0;
  forEachPairWithin<D>(i, position, nl, c.re_laplacian, include,
                       [&](std::int32_t j, const Vec<D>&, double, double w) { sum += (phi[j] - phi[i]) * w; });
  return sum * c.laplacianFactor();
}

}  // namespace mistfall
