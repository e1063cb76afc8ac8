// Roles of the particles in the two pressure systems of the gas-liquid coupling, eqs. (5)-(8)
// (MODEL.md section 1; the discretisation is written out in docs/two-phase.md):
//  * the liquid system, eqs. (5), (7), (9): liquid particles and walls carry unknowns; the gas of each bubble
//    (delta_gl = 1: a gas region enclosed in the liquid, of at least bubble_min_particles particles) counts in n*
//    and shares one pressure unknown P_B, which pushes on the liquid around it (the force of eq. (7));
//    bubble_pressure.hpp. Enclosed regions smaller than that are below a bubble's resolution and take part as
//    liquid. Open gas is invisible: liquid next to it is a free surface.
//  * the gas system, eqs. (6), (8), (17): every gas particle (open and bubble gas) carries an unknown; it is solved
//    after the liquid has moved, with every wall or liquid particle within re of gas as a moving wall (it carries
//    its velocity and a pressure unknown of the gas system, like a wall particle of single-phase MPS); deeper
//    particles are dummies (number density only). Open gas is corrected by it; bubble gas is only re-spaced
//    (bubble_gas_motion.hpp).
#pragma once

#include <vector>

#include "mps/enclosed_gas.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"

namespace mistfall {

struct CouplingRoles {
  std::vector<char> open_gas;          // gas fluid particles with delta_gl = 0
  std::vector<char> enclosed_gas;      // gas of bubbles: delta_gl = 1 and a region of >= bubble_min_particles
  std::vector<char> in_liquid_system;  // every active particle but open gas
  std::vector<char> gas_side_wall;     // walls of the gas system (set by markGasSideWalls)
  std::size_t gas_count = 0;           // gas fluid particles (the gas system's fluid)
  std::size_t enclosed_count = 0;      // gas particles of bubbles
  std::size_t entrained_count = 0;     // gas particles of enclosed regions below a bubble's size (moved as liquid)

  bool inGasSystem(std::size_t i) const { return open_gas[i] || enclosed_gas[i]; }

  // Roles for particles appended since assignCouplingRoles (inflow water): liquid-system particles.
  void extendForLiquid(std::size_t n) {
    open_gas.resize(n, 0);
    enclosed_gas.resize(n, 0);
    in_liquid_system.resize(n, 1);
    gas_side_wall.resize(n, 0);
  }
};

// From the gas regions of this step: bubble gas = gas fluid particles of enclosed regions of at least
// `min_bubble_particles`; open gas = gas outside enclosed regions; the gas of smaller enclosed regions is neither.
template <int D>
void assignCouplingRoles(const Particles<D>& p, const GasRegions& regions, CouplingRoles& roles,
                         std::size_t min_bubble_particles = 1) {
  const std::size_t n = p.size();
  const std::vector<std::size_t> region_size = regions.regionSizes();
  roles.open_gas.assign(n, 0);
  roles.enclosed_gas.assign(n, 0);
  roles.in_liquid_system.assign(n, 0);
  roles.gas_side_wall.assign(n, 0);
  roles.gas_count = 0;
  roles.enclosed_count = 0;
  roles.entrained_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!isActive(p.kind[i])) continue;
    const bool gas = isGas(p.kind[i], p.phase[i]);
    const bool enclosed = gas && i < regions.enclosed_particle.size() && regions.enclosed_particle[i];
    const bool resolved = enclosed && region_size[regions.region_of[i]] >= min_bubble_particles;
    roles.open_gas[i] = gas && !enclosed;
    roles.enclosed_gas[i] = resolved;
    roles.in_liquid_system[i] = !roles.open_gas[i];
    roles.gas_count += gas;
    roles.enclosed_count += resolved;
    roles.entrained_count += enclosed && !resolved;
  }
}

// Walls of the gas system: wall particles and liquid fluid particles within `radius` of a gas particle. Dummies
// never carry an unknown. The neighbour list must reach `radius`.
template <int D>
void markGasSideWalls(const Particles<D>& p, const NeighbourList& nl, double radius, CouplingRoles& roles) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  roles.gas_side_wall.assign(n, 0);
  const double r2max = radius * radius;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (roles.inGasSystem(i) || !hasPressureUnknown(p.kind[i])) continue;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (roles.inGasSystem(j) && (p.position[j] - p.position[i]).squaredNorm() < r2max) {
        roles.gas_side_wall[i] = 1;
        break;
      }
    }
  }
}

}  // namespace mistfall
