// Motion of the gas inside a bubble (gas enclosed in the liquid, docs/two-phase.md). The bubble's pressure is one
// unknown of the liquid system (bubble_pressure.hpp), so its gas particles carry no pressure force of their own;
// they mark where the bubble is and must fill it as the liquid around it moves:
//  * velocity: the liquid's velocity at the interface extended into the bubble, a harmonic extension by Jacobi
//    sweeps of the weighted mean over neighbours, u_i <- sum_j w_ij u_j / sum_j w_ij (j: liquid, walls and the
//    bubble's gas; open gas excluded), with w of eq. (14);
//  * position: r = r* + dt (u - u*), then the gas system's pressure correction moves them without changing their
//    velocity (re-spacing: gas squeezed by the liquid spreads through the bubble instead of blocking the liquid).
#pragma once

#include <cstdint>
#include <vector>

#include "mps/neighbor_search.hpp"
#include "mps/particles.hpp"
#include "mps/phase_coupling.hpp"
#include "mps/weight.hpp"

namespace mistfall {

inline constexpr int kBubbleVelocitySweeps = 4;  // each sweep reaches re further into the bubble

// Sets the velocity of every enclosed gas particle (roles.enclosed_gas) to the extension of its neighbours'
// velocities and moves it by dt times the change. The neighbour list must reach `re`.
template <int D>
void extendVelocityIntoBubbles(Particles<D>& p, const NeighborList& nl, const CouplingRoles& roles, double re,
                               double dt) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> before(p.velocity.begin(), p.velocity.end()), next(n);
  for (int sweep = 0; sweep < kBubbleVelocitySweeps; ++sweep) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      next[i] = p.velocity[i];
      if (!roles.enclosed_gas[i]) continue;
      Vec<D> sum = Vec<D>::Zero();
      double total = 0.0;
      for (auto s = nl.begin(i); s < nl.end(i); ++s) {
        const auto j = nl.indices[s];
        if (!isActive(p.kind[j]) || p.kind[j] == ParticleKind::Dummy || roles.open_gas[j]) continue;
        const double w = weight((p.position[j] - p.position[i]).norm(), re);
        sum += w * p.velocity[j];
        total += w;
      }
      if (total > 0.0) next[i] = sum / total;
    }
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i)
      if (roles.enclosed_gas[i]) p.velocity[i] = next[i];
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (roles.enclosed_gas[i]) p.position[i] += dt * (p.velocity[i] - before[i]);
}

// Gas that has just joined the liquid system (open at the last step, enclosed now: `joined[i]`) takes the
// w-weighted mean velocity of its liquid neighbours within re: it is carried by the water from now on, and the
// gas system's velocity it brings (metres per second in a splash) would otherwise enter the water's velocity
// divergence in the pressure equation as a spike. Particles without liquid neighbours keep their velocity.
template <int D>
void adoptLiquidVelocity(Particles<D>& p, const NeighborList& nl, const std::vector<char>& joined, double re) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> next(p.velocity.begin(), p.velocity.end());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!joined[i]) continue;
    Vec<D> sum = Vec<D>::Zero();
    double total = 0.0;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (p.kind[j] != ParticleKind::Fluid || p.phase[j] != Phase::Liquid) continue;
      const double w = weight((p.position[j] - p.position[i]).norm(), re);
      sum += w * p.velocity[j];
      total += w;
    }
    if (total > 0.0) next[i] = sum / total;
  }
  p.velocity.swap(next);
}

}  // namespace mistfall
