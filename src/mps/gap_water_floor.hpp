// Water at an unresolved gap next to the air holds at least the air's pressure (numerics.gap_water_floor; the one
// equation only, solver_one_equation.cpp; docs/two-phase.md, "The sheet at the brink"):
//   p_i <- max(p_i, p_air(r_i)),   p_air(r_i) = sum_j w_ij (p_j - rho_g g . r_ij) / sum_j w_ij  over the air j within re,
// for every water particle i short of neighbours (n*_i < beta n0) with air within re. Such a particle borders a gap
// no particle fills; in two phases that gap is air below the lattice's resolution (the water is incompressible, the
// air fills the rest), and air cannot pull on the water: across the gap the pressure is continuous, so the water there
// is at no lower pressure than the air beside it. The one equation has no free surface in a closed box, so without
// this the gap's water is an unknown whose deficit of neighbours reads as tension: at a channel's brink the water
// going over the edge held -0.4 to -1.3 kPa against the air's -0.14 kPa, clung to the bed's downstream face and
// fell down it (the teapot effect), where single-phase MPS keeps a free surface at p = 0 there and the nappe springs
// clear. The single-phase analogue is the paper scheme's surface rule (p = 0 where n* < beta n0) with the air's
// pressure in place of the atmosphere's; here only the lower bound is kept, so the gap's water may still be
// compressed. It is a one-sided condition applied after the solve, so it is counted as a guard.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "mps/enclosed_gas.hpp"
#include "mps/pair_loop.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// Raises the pressure of the gap's water to the air's beside it (the floors are read from the solved pressures
// before any is raised, so the order of the particles does not matter). Returns how many were raised.
template <int D>
std::size_t floorGapWaterPressure(const Particles<D>& p, const NeighbourList& nl, double re, double beta_n0,
                                  double gas_density, const Vec<D>& gravity, std::vector<double>& pressure) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<double> floor(n, -std::numeric_limits<double>::infinity());
  auto air = [&](std::int32_t j) { return isGas(p.kind[j], p.phase[j]); };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Liquid || !(p.number_density[i] < beta_n0)) continue;
    double sum = 0.0, weight = 0.0;
    forEachPairWithin<D>(i, p.position, nl, re, air, [&](std::int32_t j, const Vec<D>& rij, double, double w) {
      sum += w * (pressure[j] - gas_density * gravity.dot(rij));
      weight += w;
    });
    if (weight > 0.0) floor[i] = sum / weight;
  }
  std::size_t raised = 0;
  for (std::int64_t i = 0; i < n; ++i)
    if (pressure[i] < floor[i]) pressure[i] = floor[i], ++raised;
  return raised;
}

}  // namespace mistfall
