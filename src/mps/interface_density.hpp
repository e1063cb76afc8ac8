// The interparticle density of water and air in one pressure equation (numerics.coupling = "one_equation";
// docs/two-phase.md). The variable-density projection -div((1/rho) grad p) = -div u* / dt, written with MPS pair
// sums, carries a pair weight 1/rho_ij. Across the interface the exact weight follows from the continuity of the
// flux (1/rho) dp/ds along the segment i-j: with a length d_i of it in i's phase and d_j in j's,
//   p_j - p_i = -q (rho_i d_i + rho_j d_j),   so   rho_ij = (rho_i d_i + rho_j d_j) / (d_i + d_j),
// the length-weighted mean of the densities along the segment (the effective coefficient of the ghost-fluid method
// for Poisson's equation with a jump in its coefficient: Liu, Fedkiw & Kang 2000, J. Comput. Phys. 160, 151). With
// it, water and air at rest under gravity hold (p_j - p_i)/rho_ij = g . r_ij for every pair, whichever phase each
// particle is in and wherever the interface cuts the segment, so the hydrostatic state is an exact solution; the
// arithmetic mean of the two densities is exact only where the interface lies midway between the two particles.
//
// The lengths come from each particle's distance to the interface, phi_i, interpolated linearly along the segment:
// d_i : d_j = phi_i : phi_j. A particle's volume reaches half a spacing beyond its centre (as at the free surface,
// surface_pressure.hpp), so the interface lies half a spacing beyond a particle's centre towards the nearest particle
// of the other phase:
//   phi_i = max(dmin_i - l0/2, dmin_i / 4),        dmin_i = distance to the nearest fluid particle of the other phase
// (exact for a lattice cut by a straight interface; the floor keeps phi positive for pairs squeezed closer than
// half a spacing, where the interface lies between them in the ratio of their floors). Particles with no particle of
// the other phase within the neighbour list's reach have no pair across the interface and get that reach.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// phi_i of every fluid particle (0 for walls and escaped particles; they never form a pair across the interface).
template <int D>
std::vector<double> interfaceDistances(const Particles<D>& p, const NeighborList& nl, double reach, double l0) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<double> phi(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    double nearest2 = reach * reach;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (p.kind[j] != ParticleKind::Fluid || p.phase[j] == p.phase[i]) continue;
      nearest2 = std::min(nearest2, (p.position[j] - p.position[i]).squaredNorm());
    }
    const double nearest = std::sqrt(nearest2);
    phi[i] = std::max(nearest - 0.5 * l0, 0.25 * nearest);
  }
  return phi;
}

// rho_ij of the pair (i, j) of fluid particles with densities rho_i, rho_j and interface distances phi_i, phi_j.
inline double pairDensity(double rho_i, double rho_j, double phi_i, double phi_j) {
  if (rho_i == rho_j) return rho_i;
  return (rho_i * phi_i + rho_j * phi_j) / (phi_i + phi_j);
}

}  // namespace mistfall
