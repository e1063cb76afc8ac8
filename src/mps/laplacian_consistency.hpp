// First-order consistency of the MPS Laplacian, eq. (13), where a particle's neighbourhood is truncated (next to the
// free surface; numerics.scheme = "stabilised"). Eq. (13) sums sum_j (p_j - p_i) w(r_ij) over the neighbours that
// exist; on a full lattice the missing ones would add the linear part of p across the gap,
//   sum_missing (grad p_i . r_ij) w(r_ij) = -grad p_i . sum_j r_ij w(r_ij),
// (the first moment of a full lattice is zero). Without it the hydrostatic field is not a solution of the pressure
// equation next to the free surface, and still water moves there (docs/validation.md). The gradient is taken from
// the last step's pressure (deferred correction: a known term, so the system keeps eq. (13)'s sparsity and
// symmetry; exact whenever the pressure's gradient does not change within a step, as in still water):
//   row i of the negated system gains  - 2D0/(n0 lambda) grad p_i^n . sum_j r_ij w(r_ij)  on its right-hand side,
// the sum running over every neighbour taking part in the Laplacian (fluid, mirrored walls, free-surface particles).
#pragma once

#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

template <int D, class Include>
double laplacianConsistencyTerm(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                                const MpsConstants& c, const Vec<D>& last_gradient, Include&& include) {
  Vec<D> moment = Vec<D>::Zero();
  forEachPairWithin<D>(i, position, nl, c.re_laplacian, include,
                       [&](std::int32_t, const Vec<D>& rij, double, double w) { moment += w * rij; });
  return -c.laplacianFactor() * last_gradient.dot(moment);
}

}  // namespace mistfall
