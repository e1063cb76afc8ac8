// MPS divergence model:  <div u>_i = D0 / n0 * sum_{j != i} (u_j - u_i) . (r_j - r_i) / |r_ij|^2 * w(|r_ij|)
// (the divergence counterpart of the gradient model; exact for linear velocity fields on a full lattice).
#pragma once

#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

template <int D, class Include>
double divergenceAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<Vec<D>>& u,
                    const NeighbourList& nl, const MpsConstants& c, Include&& include) {
  double sum = 0.0;
  forEachPairWithin<D>(
      i, position, nl, c.re_number_density, include,
      [&](std::int32_t j, const Vec<D>& rij, double r2, double w) { sum += (u[j] - u[i]).dot(rij) * w / r2; });
  return sum * (double(D) / c.n0);
}

}  // namespace mistfall
