// MPS divergence model:  <div u>_i = D0 / n0 * sum_{j != i} (u_j - u_i) . (r_j - r_i) / |r_ij|^2 * w(|r_ij|)
// (the divergence counterpart of the gradient model; exact for linear velocity fields on a full lattice).
#pragma once

#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/reference_density.hpp"
#include "mps/weight.hpp"

namespace mistfall {

template <int D, class Include>
double divergenceAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<Vec<D>>& u,
                    const NeighborList& nl, const MpsConstants& c, Include&& include) {
  const double re = c.re_number_density;
  double sum = 0.0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (!include(j)) continue;
    const Vec<D> rij = position[j] - position[i];
    const double r2 = rij.squaredNorm();
    const double w = weight(std::sqrt(r2), re);
    if (w > 0.0) sum += (u[j] - u[i]).dot(rij) * w / r2;
  }
  return sum * (double(D) / c.n0);
}

}  // namespace mistfall
