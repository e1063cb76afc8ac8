// MPS gradient model (Koshizuka & Oka 1996):
//   <grad p>_i = D0 / n0 * sum_{j != i} (p_j - p_hat_i) / |r_ij|^2 * (r_j - r_i) w(|r_ij|)
// With p_hat_i = min(p_i, min_j p_j) over the neighbours (the standard, always repulsive form used for
// the pressure gradient), or p_hat_i = p_i (plain form, exact for linear fields on a full lattice).
#pragma once

#include <algorithm>
#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

enum class GradientForm { MinimumNeighbour, Plain };

// `include(j)`: neighbours in the sum; `in_minimum(j)`: neighbours whose value may set p_hat.
template <int D, class Include, class InMinimum>
Vec<D> gradientAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<double>& phi,
                  const NeighbourList& nl, const MpsConstants& c, GradientForm form, Include&& include,
                  InMinimum&& in_minimum) {
  const double re = c.re_number_density;
  double phi_hat = phi[i];
  if (form == GradientForm::MinimumNeighbour) {
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (in_minimum(j) && (position[j] - position[i]).squaredNorm() < re * re) phi_hat = std::min(phi_hat, phi[j]);
    }
  }
  Vec<D> sum = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, re, include, [&](std::int32_t j, const Vec<D>& rij, double r2, double w) {
    sum += rij * ((phi[j] - phi_hat) * w / r2);
  });
  return sum * (double(D) / c.n0);
}

template <int D, class Include>
Vec<D> gradientAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<double>& phi,
                  const NeighbourList& nl, const MpsConstants& c, GradientForm form, Include&& include) {
  return gradientAt<D>(i, position, phi, nl, c, form, include, include);
}

}  // namespace mistfall
