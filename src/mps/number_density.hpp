// MPS particle number density:  n_i = sum_{j != i} w(|r_j - r_i|),  w from eq. (14).
#pragma once

#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/weight.hpp"

namespace mistfall {

// The volume-weighted number density: n_i = sum_{j != i} w(|r_j - r_i|) V_j / l0^D over the neighbours `include(j)`
// admits, with `volume(j)` = V_j / l0^D (n0 / n_j for a particle whose own number density is n_j; 1 at the lattice
// spacing, where it is numberDensityAt). On a lattice compressed uniformly to a spacing s l0 it stays near n0 where
// the particle count gives n0 / s^D (tests/test_operators.cpp).
template <int D, class Include, class Volume>
double volumeWeightedNumberDensityAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                                     double re, Include&& include, Volume&& volume) {
  double n = 0.0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (include(j)) n += weight((position[j] - position[i]).norm(), re) * volume(j);
  }
  return n;
}

// Number density counting only the neighbours `include(j)` admits (one phase's view in the two-phase model): the
// volume-weighted one with every neighbour at the lattice spacing.
template <int D, class Include>
double numberDensityAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                       Include&& include) {
  return volumeWeightedNumberDensityAt<D>(i, position, nl, re, include, [](std::int32_t) { return 1.0; });
}

// How many neighbours j with include(j) lie within re (the neighbour count; a full lattice has
// latticeNeighbourCount of enclosed_gas.hpp: 12 in 2D and 32 in 3D for re = 2.1 l0).
template <int D, class Include>
int neighbourCountAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                     Include&& include) {
  int count = 0;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (include(j) && (position[j] - position[i]).squaredNorm() < re * re) ++count;
  }
  return count;
}

// Number density counting every neighbour in the list (the list never holds escaped particles).
template <int D>
double numberDensityAt(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re) {
  return numberDensityAt<D>(i, position, nl, re, [](std::int32_t) { return true; });
}

}  // namespace mistfall
