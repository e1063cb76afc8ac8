// The stability bound of the explicit particle shift (numerics.shift_stability = beta; particle_shifting.hpp):
// the shift delta r_i = -K sum_j g(r_ij), with K = A l0 |u_i| dt D0/n0 and g(r) = r w(r) / |r|^2 ("mps"), or
// K = A h |u_i| dt and g(r) = l0^D grad W(|r|) ("wendland"), is one explicit step of a diffusion of the particles'
// concentration (Fick's law, Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499), and a forward-Euler
// diffusion step is stable only below a limit on its coefficient over the spacing squared (von Neumann's Fourier
// number). Here the limit is taken per particle. Its Jacobian in a neighbour's position is K dg/dr, whose norm for
// g = r f(|r|)/|r| is max(|f'(r)|, f(r)/r). One step is stable where the eigenvalues of K J lie in (-2, 0]; for a
// particle between two neighbours on a line at distance d (the mode that alternates) that is
//   K sum_j |f'(r_ij)| < 1,
// and on a full 2D lattice at re = 2.1 l0 the bound is about twice that. So the shift's coefficient is taken as
//   K_i <- K_i min(1, beta / (K_i S_i)),   S_i = sum_j max(|f'(r_ij)|, f(r_ij)/r_ij)
// over the neighbours the shift sums: beta = 1 keeps the alternating mode of a chain from growing, beta = 0.5 keeps it
// from overshooting. For the MPS weight w = re/r - 1, f = w/r and |f'(r)| = (2 re - r)/r^3 > f/r. On the still,
// evenly spaced water the bound is beta / (K S) with S = 17.8 / l0^2: at beta = 1 it caps A |u| dt / l0 at 0.18,
// which the shipped A = 3 reaches at a Courant number of 0.06. Why: on the 5 mm waterfall (runs/wf5_nl54b) a water
// particle at 2.6 m/s between two neighbours at 0.8 l0 (K S = 1.55 from those two alone) was shifted back and forth,
// 0.04, 0.08, 0.14, 0.20, 0.35, 0.70 and 2.07 l0 in seven steps (docs/waterfall.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "case/case_config.hpp"
#include "mps/pair_loop.hpp"
#include "mps/particle_shifting.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

// S_i above: the sum over the neighbours within re that `include(j)` admits of the norm of the pair term's
// Jacobian, per unit of K (shiftCoefficient, particle_shifting.hpp) [1/m^2].
template <int D, class Include>
double shiftStiffness(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                      const MpsConstants& c, Include&& include, NumericsConfig::ShiftingKernel kernel) {
  const double re = c.re_number_density;
  double sum = 0.0;
  if (kernel == NumericsConfig::ShiftingKernel::Wendland) {
    // W' = -5 alpha q (1 - q/2)^3 / h, W'' = -5 alpha (1 - q/2)^2 (1 - 2q) / h^2, q = r/h: norm max(|W''|, |W'|/r)
    // (times l0^D, which the shift's sum carries)
    const auto [h, alpha] = WendlandC2<D>(re);
    const double volume = std::pow(c.l0, D);
    forEachPairWithin<D>(i, position, nl, re, include, [&](std::int32_t, const Vec<D>&, double r2, double) {
      const double q = std::sqrt(r2) / h, rest = 1.0 - 0.5 * q;
      const double second = 5.0 * alpha * rest * rest * std::abs(1.0 - 2.0 * q) / (h * h);
      const double first_over_r = 5.0 * alpha * rest * rest * rest / (h * h);
      sum += volume * std::max(second, first_over_r);
    });
    return sum;
  }
  forEachPairWithin<D>(i, position, nl, re, include, [&](std::int32_t, const Vec<D>&, double r2, double) {
    const double r = std::sqrt(r2);
    if (r > 0.0) sum += (2.0 * re - r) / (r2 * r);
  });
  return sum;
}

// The factor in (0, 1] that the bound puts on particle i's shift (1: not bounded); beta <= 0 is no bound.
template <int D, class Include>
double shiftStabilityFactor(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                            const MpsConstants& c, double coefficient, double speed, double dt, double beta,
                            Include&& include,
                            NumericsConfig::ShiftingKernel kernel = NumericsConfig::ShiftingKernel::Mps) {
  if (beta <= 0.0 || coefficient <= 0.0 || speed <= 0.0) return 1.0;
  const double ks =
      shiftCoefficient<D>(c, coefficient, speed, dt, kernel) * shiftStiffness<D>(i, position, nl, c, include, kernel);
  return ks > beta ? beta / ks : 1.0;
}

}  // namespace mistfall
