// Collision model for too-close particle pairs (after Koshizuka & Oka's MPS practice): for a pair closer
// than alpha * l0 that is approaching, the normal relative velocity is reversed with restitution e,
// sharing momentum by mass (a fixed wall particle has infinite mass):
//   du_i = -(1 + e) * m_j / (m_i + m_j) * ((u_i - u_j) . n) n,   n = (r_j - r_i) / |r_j - r_i|
// Evaluated Jacobi-style from the old velocities so the result does not depend on particle order or
// thread count; the position is moved with the velocity change, r_i += dt du_i.
// `affects(i, j)` says whether j may change i's velocity (the liquid ignores open gas, eqs. (5)-(8)).
// Returns how many (i, j) reversals it made (a numerical guard: diagnostics.csv column `collisions`).
#pragma once

#include <vector>

#include "mps/neighbor_search.hpp"

namespace mistfall {

template <int D, class Affects>
std::size_t resolveCollisions(std::vector<Vec<D>>& position, std::vector<Vec<D>>& velocity,
                       const std::vector<ParticleKind>& kind, const std::vector<double>& mass,
                       const NeighborList& nl, double distance, double restitution, double dt, Affects&& affects) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  const double d2 = distance * distance;
  std::size_t reversals = 0;
#pragma omp parallel for schedule(static) reduction(+ : reversals)
  for (std::int64_t i = 0; i < n; ++i) {
    if (kind[i] != ParticleKind::Fluid) continue;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (!isActive(kind[j]) || !affects(i, j)) continue;
      const Vec<D> rij = position[j] - position[i];
      const double r2 = rij.squaredNorm();
      if (r2 >= d2 || r2 <= 0.0) continue;
      const Vec<D> normal = rij / std::sqrt(r2);
      const double approach = (velocity[i] - velocity[j]).dot(normal);
      if (approach <= 0.0) continue;
      const double share = isFixed(kind[j]) ? 1.0 : mass[j] / (mass[i] + mass[j]);
      change[i] -= (1.0 + restitution) * share * approach * normal;
      ++reversals;
    }
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    velocity[i] += change[i];
    position[i] += dt * change[i];
  }
  return reversals;
}

template <int D>
std::size_t resolveCollisions(std::vector<Vec<D>>& position, std::vector<Vec<D>>& velocity,
                       const std::vector<ParticleKind>& kind, const std::vector<double>& mass,
                       const NeighborList& nl, double distance, double restitution, double dt) {
  return resolveCollisions<D>(position, velocity, kind, mass, nl, distance, restitution, dt,
                              [](std::int64_t, std::int32_t) { return true; });
}

}  // namespace mistfall
