// The repulsive part of the pressure gradient of numerics.scheme = "stabilised" (numerics.pressure_repulsion = K):
//   <grad p>_i  +=  -K D0/n0 min(0, min_j [p_j - p_i - <grad p>_i . r_ij]) P_i sum_j r_ij w(|r_ij|) / |r_ij|^2
// (sums over the neighbours within re of the gradient; <grad p>_i the corrected gradient, corrected_gradient.hpp).
// It is the minimum-pressure term of Koshizuka & Oka's gradient (gradient.hpp: p_hat - p_i times the first moment of
// the neighbourhood, which pushes a particle away from the side where its neighbours crowd) with the pressure
// measured from the linear field of the corrected gradient instead of from p_i. In a linear pressure field (still
// water, a uniform acceleration) the bracket is zero for every neighbour, so the term vanishes whatever the
// arrangement of the particles and still water stays the exact equilibrium it is without it; where the pressure
// has a particle-scale part (the noise of a disordered neighbourhood), it pushes the particles apart as the paper's
// gradient does. P_i projects the first moment on the free surface's tangent plane, P_i = I - n n^T, for particles
// near a free surface (surface_tangent.hpp).
// Free-surface particles (Dirichlet rows) are not repelled (their tangential order has no pressure to restore it).
// Why: the corrected gradient is not repulsive, and with it alone a sloshing tank gained 13 times its potential
// energy in 1.5 s (docs/validation.md).
#pragma once

#include <algorithm>
#include <vector>

#include "mps/corrected_gradient.hpp"
#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

// The term for particle i. `gradient` is its corrected gradient, `normal` the unit surface normal (zero away from the
// free surface: no projection; surface_tangent.hpp), `difference(j, r_ij)` = p_j - p_i as in the gradient,
// `include(j)` its neighbours.
template <int D, class Include, class Difference>
Vec<D> pressureRepulsion(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                         const MpsConstants& c, double coefficient, const Vec<D>& gradient, const Vec<D>& normal,
                         Include&& include, Difference&& difference) {
  double lowest = 0.0;
  Vec<D> first = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, c.re_number_density, include,
                       [&](std::int32_t j, const Vec<D>& rij, double r2, double w) {
                         lowest = std::min(lowest, difference(j, rij) - gradient.dot(rij));
                         first += rij * (w / r2);
                       });
  first -= first.dot(normal) * normal;
  return (-coefficient * double(D) / c.n0 * lowest) * first;
}

// The stabilised scheme's gradient (corrected_gradient.hpp) plus, with `repel` and where it did not fall back, the
// term above with coefficient `k`: what the liquid's and the one equation's corrections apply.
template <int D, class Include, class Difference>
CorrectedGradient<D> repulsiveCorrectedGradient(std::size_t i, const std::vector<Vec<D>>& position,
                                                const NeighbourList& nl, const MpsConstants& c, double min_determinant,
                                                bool repel, double k, const Vec<D>& normal, Include&& include,
                                                Difference&& difference) {
  auto gradient = correctedGradientAt<D>(i, position, nl, c, min_determinant, include, difference);
  if (repel && k > 0.0 && !gradient.fell_back)
    gradient.value += pressureRepulsion<D>(i, position, nl, c, k, gradient.value, normal, include, difference);
  return gradient;
}

}  // namespace mistfall
