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
#pragma once

#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

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
                            const Vec<D>& normal, Include&& include) {
  Vec<D> first = neighbourhoodFirstMoment<D>(i, position, nl, c.re_number_density, include);
  first -= first.dot(normal) * normal;
  return (-coefficient * c.l0 * velocity.norm() * dt * double(D) / c.n0) * first;
}

}  // namespace mistfall
