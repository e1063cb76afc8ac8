// The loop every MPS operator sums over: each neighbour j of particle i that `include(j)` admits and that lies
// within the influence radius re (w > 0, eq. (14)), visited as visit(j, r_ij = r_j - r_i, |r_ij|^2, w(|r_ij|)).
#pragma once

#include <cmath>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/weight.hpp"

namespace mistfall {

template <int D, class Include, class Visit>
void forEachPairWithin(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                       Include&& include, Visit&& visit) {
  // Pairs this far apart are beyond re whatever the rounding of the square root: skipped before computing it (the
  // list's skin holds many).
  const double beyond2 = re * re * (1.0 + 1e-12);
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (!include(j)) continue;
    const Vec<D> rij = position[j] - position[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= beyond2) continue;
    const double w = weight(std::sqrt(r2), re);
    if (w > 0.0) visit(j, rij, r2, w);
  }
}

}  // namespace mistfall
