// Corrected MPS gradient (Khayyer & Gotoh 2011, J. Comput. Phys. 230, 3093, "gradient correction"):
//   <grad p>_i = C_i D0/n0 sum_j (p_j - p_i) r_ij w(|r_ij|) / |r_ij|^2,
//   C_i = (D0/n0 sum_j w(|r_ij|) r_ij r_ij^T / |r_ij|^2)^-1,
// exact for every linear field whatever the arrangement of the neighbours (C_i = I on a full lattice). It is used by
// numerics.scheme = "stabilised" (docs/validation.md). Where the neighbours do not span the space (a splash, a
// chain of particles) det(C_i^-1) falls below numerics.gradient_correction_min_determinant and the standard,
// always repulsive form is used instead (gradient.hpp, p_hat = min(p_i, min_j p_j)); the caller counts these
// fallbacks (a numerical guard, reported in diagnostics.csv as gradient_fallbacks).
// `difference(j, r_ij)` gives p_j - p_i for neighbour j (a mirrored wall particle has its own rule,
// wall_mirror.hpp); `include(j)` selects the neighbours.
#pragma once

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

template <int D>
struct CorrectedGradient {
  Vec<D> value = Vec<D>::Zero();
  bool fell_back = false;  // the standard form was used (too few or one-sided neighbours)
};

template <int D, class Include, class Difference>
CorrectedGradient<D> correctedGradientAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                                         const MpsConstants& c, double min_determinant, Include&& include,
                                         Difference&& difference) {
  Vec<D> sum = Vec<D>::Zero(), first = Vec<D>::Zero();
  Eigen::Matrix<double, D, D> moment = Eigen::Matrix<double, D, D>::Zero();
  double lowest = 0.0;  // p_hat - p_i of the standard form
  forEachPairWithin<D>(i, position, nl, c.re_number_density, include,
                       [&](std::int32_t j, const Vec<D>& rij, double r2, double w) {
                         const double d = difference(j, rij);
                         sum += rij * (d * w / r2);
                         first += rij * (w / r2);
                         lowest = std::min(lowest, d);
                         moment += (w / r2) * rij * rij.transpose();
                       });
  const double scale = double(D) / c.n0;
  moment *= scale;
  if (moment.determinant() < min_determinant) return {scale * (sum - lowest * first), true};
  return {moment.inverse() * (scale * sum), false};
}

}  // namespace mistfall
