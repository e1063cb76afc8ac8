// Pressure acceleration of the two-step method's correction, -(1/rho) grad p, with the MPS gradient model
// (gradient.hpp) and the pair density of the variable-density PPE (pressure_poisson.hpp):
//   a_i = -D0/n0 * [ sum_{j same rho} 1/rho_i (p_j - p_hat_i) + sum_{j other rho} 2/(rho_i + rho_j) (p_j - p_i) ]
//                * (r_j - r_i) / |r_ij|^2 w(|r_ij|)
// p_hat_i is the minimum pressure over i and its neighbours of the same density (the standard repulsive form);
// pairs across the interface use the plain difference. With one density it is -(1/rho) <grad p>_i exactly.
// Why not p_hat across the interface: the shift by p_hat is harmless only where the weights are symmetric; across
// a density jump of 10^3 it turns the hydrostatic pressure difference of the liquid around a bubble into a push of
// order (p_i - p_hat) / (rho_g l0) on the gas, thousands of g (found on cases/bubble_rise.toml).
// Across a liquid-gas pair the weight 2/(rho_l + rho_g) is close to 2/rho_l: the gas is hardly pushed by the
// liquid's pressure differences, while the liquid feels the gas pressure as if the gas were liquid.
#pragma once

#include <algorithm>
#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

// `include(j)`: neighbours in the sum; `in_minimum(j)`: neighbours whose pressure may set p_hat.
template <int D, class Include, class InMinimum>
Vec<D> pressureAccelerationAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<double>& p,
                              const std::vector<double>& density, const NeighborList& nl, const MpsConstants& c,
                              Include&& include, InMinimum&& in_minimum) {
  const double re = c.re_number_density;
  double p_hat = p[i];
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (in_minimum(j) && density[j] == density[i] && (position[j] - position[i]).squaredNorm() < re * re)
      p_hat = std::min(p_hat, p[j]);
  }
  const double rho_i = density[i];
  Vec<D> sum = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, re, include, [&](std::int32_t j, const Vec<D>& rij, double r2, double w) {
    if (density[j] == rho_i)
      sum += rij * ((p[j] - p_hat) * w / r2);
    else
      sum += rij * ((p[j] - p[i]) * w / r2 * (2.0 * rho_i / (rho_i + density[j])));
  });
  return -1.0 / rho_i * (sum * (double(D) / c.n0));
}

}  // namespace mistfall
