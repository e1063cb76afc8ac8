// Particle shifting of numerics.scheme = "stabilised" (numerics.particle_shifting = A): after the correction each
// fluid particle moves, without changing its velocity, by
//   delta r_i = -A l0 |u_i| dt P_i D0/n0 sum_j r_ij w(|r_ij|) / |r_ij|^2
// (the sum over the neighbours within re of the gradient, walls included). It is Fick's-law shifting (Xu, Stansby &
// Laurence 2009; Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499: delta r = -D grad C, the first moment
// of the neighbourhood standing for the concentration's gradient) with the diffusion coefficient of Skillen, Lind,
// Stansby & Rogers (2013, Comput. Methods Appl. Mech. Eng. 265, 163), D = A h |u| dt: proportional to the distance
// the particle travels in the step, so water at rest is not shifted (a fixed coefficient moved the still tank at
// 0.1-0.2 m/s within 3 s) and moving water is kept from clustering. P_i = I - n n^T near a free surface
// (surface_tangent.hpp): a truncated neighbourhood's first moment along the normal is not disorder. Near a surface
// with no pressure gradient (a jet in free fall, a droplet) no shift: there is no normal to keep.
// Why: the projection of the stabilised scheme keeps the velocity divergence-free but nothing in it keeps the
// particles evenly spaced; without a shift, moving water relies on the collision guard (docs/validation.md).
// The shift is one explicit step of a diffusion: numerics.shift_stability bounds each particle's coefficient by that
// step's stability (shift_stability.hpp).
// numerics.shifting_kernel = "wendland" (experimental) takes the concentration's gradient as Lind et al. and Skillen
// et al. wrote it, from a smooth kernel: delta r_i = -A h |u_i| dt P_i sum_j l0^D grad_i W(|r_ij|, h), Wendland's C2
// kernel W = alpha (1 - q/2)^4 (2q + 1), q = r / h, its support 2h = re, alpha = 7 / (4 pi h^2) in 2D and
// 21 / (16 pi h^3) in 3D. The MPS weight's first moment grows as 1/r^2 for a close pair (a pair at 0.15 l0 in a fast
// flow is shifted 16 l0, which numerics.shift_limit cuts); the kernel's gradient, -5 alpha q (1 - q/2)^3 / h, vanishes
// at r = 0 and is at most 1.055 alpha / h (at q = 1/2), so no one neighbour shifts a particle more than
// 1.055 alpha l0^D A |u| dt (0.53 A |u| dt in 2D at re = 2.1 l0: a third of a spacing at A = 3 and a Courant number
// of 0.2).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "case/case_config.hpp"
#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

// Wendland's C2 kernel of support re: h = re / 2 and its normalisation alpha.
template <int D>
struct WendlandC2 {
  double h, alpha;
  explicit WendlandC2(double re)
      : h(0.5 * re),
        alpha(D == 2 ? 7.0 / (4.0 * std::numbers::pi * h * h) : 21.0 / (16.0 * std::numbers::pi * h * h * h)) {}
};

// K of the shift delta r_i = -K P_i sum_j g(r_ij) for a particle moving at `speed`: A l0 |u| dt D0/n0 with the MPS
// weight's first moment, A h |u| dt with the Wendland kernel's gradient (its l0^D inside the sum).
template <int D>
double shiftCoefficient(const MpsConstants& c, double coefficient, double speed, double dt,
                        NumericsConfig::ShiftingKernel kernel) {
  if (kernel == NumericsConfig::ShiftingKernel::Wendland) return coefficient * 0.5 * c.re_number_density * speed * dt;
  return coefficient * c.l0 * speed * dt * double(D) / c.n0;
}

// sum_j l0^D grad_i W(|r_ij|, h) of the Wendland C2 kernel of support re (h = re / 2) over the neighbours within re
// that `include(j)` admits: it points towards where they crowd, as the first moment below does.
template <int D, class Include>
Vec<D> wendlandConcentrationGradient(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                                     const MpsConstants& c, Include&& include) {
  const auto [h, alpha] = WendlandC2<D>(c.re_number_density);
  const double volume = std::pow(c.l0, D);
  Vec<D> gradient = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, c.re_number_density, include,
                       [&](std::int32_t, const Vec<D>& rij, double r2, double) {
                         const double r = std::sqrt(r2);
                         const double q = r / h, rest = 1.0 - 0.5 * q;
                         // |dW/dr| r_ij / r: grad_i W(|r_i - r_j|) points from i towards j
                         if (r > 0.0) gradient += rij * (volume * 5.0 * alpha * q * rest * rest * rest / (h * r));
                       });
  return gradient;
}

// The first moment of particle i's neighbourhood, sum_j r_ij w(|r_ij|) / |r_ij|^2 over the neighbours within re that
// `include(j)` admits: it points towards where they crowd (the shift's concentration gradient; wall_slip.hpp's
// wall normal).
template <int D, class Include>
Vec<D> neighbourhoodFirstMoment(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                                Include&& include) {
  Vec<D> first = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, re, include,
                       [&](std::int32_t, const Vec<D>& rij, double r2, double w) { first += rij * (w / r2); });
  return first;
}

// delta r_i for particle i moving at `velocity` (P_i given by `normal`, zero for none; see above).
template <int D, class Include>
Vec<D> shiftingDisplacement(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                            const MpsConstants& c, double coefficient, const Vec<D>& velocity, double dt,
                            const Vec<D>& normal, Include&& include,
                            NumericsConfig::ShiftingKernel kernel = NumericsConfig::ShiftingKernel::Mps) {
  const double k = shiftCoefficient<D>(c, coefficient, velocity.norm(), dt, kernel);
  if (kernel == NumericsConfig::ShiftingKernel::Wendland) {
    Vec<D> gradient = wendlandConcentrationGradient<D>(i, position, nl, c, include);
    gradient -= gradient.dot(normal) * normal;
    return -k * gradient;
  }
  Vec<D> first = neighbourhoodFirstMoment<D>(i, position, nl, c.re_number_density, include);
  first -= first.dot(normal) * normal;
  return -k * first;
}

}  // namespace mistfall
