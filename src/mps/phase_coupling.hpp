// Roles of the particles in the two pressure systems of the gas-liquid coupling, eqs. (5)-(8)
// (MODEL.md section 1; the discretisation is written out in docs/two-phase.md):
//  * the liquid system, eqs. (5) and (7): liquid particles, walls, dummies and the gas enclosed in the liquid
//    (delta_gl = 1). Open gas is invisible to it: liquid next to open gas is a free surface.
//  * the gas system, eqs. (6) and (8): open gas particles, solved after the liquid has moved, with every wall,
//    liquid or enclosed-gas particle within re of an open gas particle as a moving wall (it carries its velocity
//    and a pressure unknown of the gas system, like a wall particle of single-phase MPS); deeper particles are
//    dummies (number density only).
#pragma once

#include <vector>

#include "mps/enclosed_gas.hpp"
#include "mps/neighbor_search.hpp"
#include "mps/particles.hpp"

namespace mistfall {

struct CouplingRoles {
  std::vector<char> open_gas;          // gas fluid particles with delta_gl = 0
  std::vector<char> in_liquid_system;  // every other active particle
  std::vector<char> gas_side_wall;     // walls of the gas system (set by markGasSideWalls)
  std::size_t open_gas_count = 0;
};

// From the gas regions of this step: open gas = gas fluid particles outside enclosed regions.
template <int D>
void assignCouplingRoles(const Particles<D>& p, const GasRegions& regions, CouplingRoles& roles) {
  const std::size_t n = p.size();
  roles.open_gas.assign(n, 0);
  roles.in_liquid_system.assign(n, 0);
  roles.gas_side_wall.assign(n, 0);
  roles.open_gas_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!isActive(p.kind[i])) continue;
    const bool enclosed = i < regions.enclosed_particle.size() && regions.enclosed_particle[i];
    roles.open_gas[i] = isGas(p.kind[i], p.phase[i]) && !enclosed;
    roles.in_liquid_system[i] = !roles.open_gas[i];
    roles.open_gas_count += roles.open_gas[i];
  }
}

// Walls of the gas system: wall particles and liquid / enclosed-gas fluid particles within `radius` of an open gas
// particle. Dummies never carry an unknown. The neighbour list must reach `radius`.
template <int D>
void markGasSideWalls(const Particles<D>& p, const NeighborList& nl, double radius, CouplingRoles& roles) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  roles.gas_side_wall.assign(n, 0);
  const double r2max = radius * radius;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (roles.open_gas[i] || !(p.kind[i] == ParticleKind::Wall || p.kind[i] == ParticleKind::Fluid)) continue;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (roles.open_gas[j] && (p.position[j] - p.position[i]).squaredNorm() < r2max) {
        roles.gas_side_wall[i] = 1;
        break;
      }
    }
  }
}

}  // namespace mistfall
