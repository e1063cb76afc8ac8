// Buoyant rise of entrained gas below a bubble's resolution (docs/waterfall.md). Gas enclosed in the liquid in a
// region smaller than numerics.bubble_min_particles takes part in the liquid system as liquid (phase_coupling.hpp):
// it is carried by the water and has no buoyancy of its own, so the air a plunging jet drags under would stay in the
// pool for ever. Such a particle stands for bubbles smaller than l0, which rise through water at their terminal
// speed U_r (about 0.2-0.25 m/s for air bubbles of 1-10 mm; Clift, Grace & Weber 1978). The rise is made by
// exchange, not by motion: with probability P = min(1, U_r dt / l0) per step the gas particle swaps its phase with
// the liquid particle above it (the most nearly vertical liquid neighbour within 1.5 l0 at least 0.5 l0 higher and
// within 45 degrees of the vertical), so the gas climbs about one l0 per swap, at U_r on average, and the liquid
// moves down by the same volume. Positions, velocities and pressures stay where they are, so the incompressible
// liquid sees no disturbance; each phase keeps its particle count, so mass is conserved exactly. At the surface the
// gas joins the air above (it is then linked to the open gas region) and leaves the water.
// The draw is a hash of (step, particle index), and the swaps run serially in index order: the result does not
// depend on the thread count and a resumed run repeats it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "mps/enclosed_gas.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"
#include "mps/phase_coupling.hpp"
#include "mps/splitmix.hpp"

namespace mistfall {

// A uniform number in [0, 1) from (step, index): the splitmix64 finaliser of the combined key.
inline double entrainedGasDraw(std::int64_t step, std::size_t index) {
  const std::uint64_t key = static_cast<std::uint64_t>(step) * 0x9E3779B97F4A7C15ull ^
                            (static_cast<std::uint64_t>(index) + 1) * 0xD1B54A32D192ED03ull;
  return static_cast<double>(splitmixFinalise(key) >> 11) * 0x1.0p-53;
}

// Swaps entrained sub-resolution gas (gas of enclosed regions that is not a resolved bubble: roles.enclosed_gas = 0)
// with the liquid above it, as described above. `up` is the unit vector against gravity. Returns the swaps made.
template <int D>
std::size_t riseEntrainedGas(Particles<D>& p, const NeighbourList& nl, const GasRegions& regions,
                             const CouplingRoles& roles, const Vec<D>& up, double l0, double rise_speed, double dt,
                             std::int64_t step) {
  if (rise_speed <= 0.0) return 0;
  const double probability = std::min(1.0, rise_speed * dt / l0);
  const std::size_t n = p.size();
  std::vector<char> swapped(n, 0);
  std::size_t swaps = 0;
  const double reach2 = 2.25 * l0 * l0;
  for (std::size_t i = 0; i < n && i < regions.enclosed_particle.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i]) || !regions.enclosed_particle[i] || roles.enclosed_gas[i] || swapped[i])
      continue;
    if (entrainedGasDraw(step, i) >= probability) continue;
    std::int32_t partner = -1;
    double best = 0.0;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (p.kind[j] != ParticleKind::Fluid || p.phase[j] != Phase::Liquid || swapped[j]) continue;
      const Vec<D> r = p.position[j] - p.position[i];
      const double r2 = r.squaredNorm();
      const double rise = r.dot(up);
      if (r2 > reach2 || rise < 0.5 * l0 || rise * rise < 0.5 * r2) continue;  // within 45 degrees of up
      const double verticality = rise / std::sqrt(r2);
      if (verticality > best) best = verticality, partner = j;
    }
    if (partner < 0) continue;
    p.phase[i] = Phase::Liquid;
    p.phase[partner] = Phase::Gas;
    p.enclosed[partner] = p.enclosed[i];
    p.enclosed[i] = 0;
    swapped[i] = swapped[partner] = 1;
    ++swaps;
  }
  return swaps;
}

}  // namespace mistfall
