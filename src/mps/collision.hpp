// Collision model for too-close particle pairs (after Koshizuka & Oka's MPS practice): for a pair closer
// than alpha * l0 that is approaching, the normal relative velocity is reversed with restitution e,
// sharing momentum by mass (a fixed wall particle has infinite mass):
//   du_i = -(1 + e) * m_j / (m_i + m_j) * ((u_i - u_j) . n) n,   n = (r_j - r_i) / |r_j - r_i|
// Evaluated Jacobi-style from the old velocities so the result does not depend on particle order or
// thread count; the position is moved with the velocity change, r_i += dt du_i.
// `affects(i, j)` says whether j may change i's velocity (the liquid ignores open gas, eqs. (5)-(8)).
// Returns how many (i, j) reversals it made (a numerical guard: diagnostics.csv column `collisions`).
//
// The wall limit (numerics.collision_wall_limit; a guard, counted in `collision_wall_limits`). Jacobi-style, a pair
// with a wall is judged on the old velocity only: a particle between a wall it is leaving and a particle approaching
// it from the other side is reversed by the second pair straight into the wall, and nothing in the pass sees it.
// Traced on waterfall_small (runs/wfs_wr27b, docs/waterfall.md): an air particle beside the downstream wall, moving
// off it at 0.85 m/s after the gas correction, was sent back at 2.07 m/s by a water particle approaching at 1.66 m/s,
// every step for 20 steps, until it sat in the wall's row (n = 14 against 6.5) and the gas rows threw it out. With
// the limit, a particle whose velocity the pass changed keeps no approach to a wall or dummy particle j within the
// distance: in the order of its list,
//   u_i <- u_i - max(0, u_i . n_ij) n_ij,
// the collision model's inelastic limit (e = 0) against a particle of infinite mass, as wall_stop.hpp applies it to
// displacements. The position moves with the whole velocity change, as before.
#pragma once

#include <vector>

#include "mps/neighbour_search.hpp"

namespace mistfall {

// The model's controls (numerics.collision_distance * l0, collision_restitution, collision_wall_limit).
struct CollisionModel {
  double distance = 0.0;
  double restitution = 0.0;
  bool wall_limit = false;
};

// What a pass did: pairs reversed, and velocities the wall limit changed.
struct CollisionCount {
  std::size_t reversals = 0;
  std::size_t wall_limits = 0;
};

template <int D, class Affects>
CollisionCount resolveCollisions(std::vector<Vec<D>>& position, std::vector<Vec<D>>& velocity,
                                 const std::vector<ParticleKind>& kind, const std::vector<double>& mass,
                                 const NeighbourList& nl, const CollisionModel& model, double dt, Affects&& affects) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  const double distance = model.distance, restitution = model.restitution;
  const double d2 = distance * distance;
  std::size_t reversals = 0, wall_limits = 0;
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
  if (model.wall_limit) {  // the wall limit (above), on the velocities the pass changed
#pragma omp parallel for schedule(static) reduction(+ : wall_limits)
    for (std::int64_t i = 0; i < n; ++i) {
      if (change[i].squaredNorm() == 0.0) continue;
      Vec<D> u = velocity[i] + change[i];
      bool limited = false;
      for (auto s = nl.begin(i); s < nl.end(i); ++s) {
        const auto j = nl.indices[s];
        if (!isFixed(kind[j]) || !affects(i, j)) continue;
        const Vec<D> rij = position[j] - position[i];
        const double r2 = rij.squaredNorm();
        if (r2 >= d2 || r2 <= 0.0) continue;
        const double approach = u.dot(rij);
        if (approach <= 0.0) continue;
        u -= (approach / r2) * rij;
        limited = true;
      }
      if (limited) change[i] = u - velocity[i], ++wall_limits;
    }
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    velocity[i] += change[i];
    position[i] += dt * change[i];
  }
  return {reversals, wall_limits};
}

// `passes` passes of the model (numerics.collision_passes; 1 = the model as published), each from the velocities and
// places the one before left, stopping early when a pass reverses nothing. A Jacobi pass's reversal can send a
// particle into a third one within the distance that no pair of it saw; the next pass reverses that approach
// (traced on waterfall_small: an air particle reversed off the water straight at another air particle, to 0.26 l0,
// which the gas rows then threw out at 446 m/s; docs/waterfall.md, twenty-ninth session). Counts add up.
template <int D, class Affects>
CollisionCount resolveCollisionPasses(int passes, std::vector<Vec<D>>& position, std::vector<Vec<D>>& velocity,
                                      const std::vector<ParticleKind>& kind, const std::vector<double>& mass,
                                      const NeighbourList& nl, const CollisionModel& model, double dt,
                                      Affects&& affects) {
  CollisionCount total;
  for (int pass = 0; pass < passes; ++pass) {
    const CollisionCount count = resolveCollisions<D>(position, velocity, kind, mass, nl, model, dt, affects);
    total.reversals += count.reversals, total.wall_limits += count.wall_limits;
    if (count.reversals == 0) break;
  }
  return total;
}

template <int D>
CollisionCount resolveCollisions(std::vector<Vec<D>>& position, std::vector<Vec<D>>& velocity,
                                 const std::vector<ParticleKind>& kind, const std::vector<double>& mass,
                                 const NeighbourList& nl, const CollisionModel& model, double dt) {
  return resolveCollisions<D>(position, velocity, kind, mass, nl, model, dt,
                              [](std::int64_t, std::int32_t) { return true; });
}

}  // namespace mistfall
