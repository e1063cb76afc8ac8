// A position-only displacement stopped at the walls (numerics.shift_wall_stop; a guard, counted). Two stages move a
// particle without changing its velocity: the particle shifting of the stabilised liquid (particle_shifting.hpp) and
// the gas system's re-spacing of a bubble's gas (correctGas; the bubble's gas takes the water's velocity,
// bubble_gas_motion.hpp). The collision model (collision.hpp) acts on approaching velocities, so it never sees such a
// displacement, and either can carry a particle onto a wall particle: traced on the waterfall at 5 mm, a bubble's gas
// particle re-spaced 0.06 l0 a step into the floor's first wall row (n = 22, 41, 113), then taken 12.7 m by the next
// correction; at 7 mm, a water particle shifted one spacing to 0.09 l0 from the floor, then given 1,700 m/s
// (docs/waterfall.md). The stop is the collision model's inelastic limit (restitution 0) applied to the displacement
// d_i against fixed particles only (a wall particle has infinite mass, so the particle takes the whole reversal):
// for each wall or dummy particle j whose distance from the displaced position would fall below alpha l0
// (numerics.collision_distance) while d_i approaches it,
//   d_i <- d_i - (d_i . e_ij) e_ij,   e_ij = (r_j - r_i) / |r_j - r_i|,
// in the order of the neighbour list. The displacement along the wall is kept, and so is any displacement between
// fluid particles the caller does not name. numerics.respacing_stop (forty-ninth session) names the water as
// well for a bubble gas's re-spacing: the water around a bubble is its gas's other wall, and a re-spacing traced at
// 5 mm brought a gas particle to 0.14 l0 from the water, which the next liquid correction threw at 18 m/s. (Stopping
// the re-spacing against the water was tried in the twenty-fifth session, on the paper scheme: it lost 15 and 2
// particles on waterfall_small.)
#pragma once

#include <cstddef>
#include <vector>

#include "mps/neighbour_search.hpp"

namespace mistfall {

// Removes from `displacement` of particle i its approach to every particle j of its list with fixed(j) that it would
// bring within `distance` (see above). The list must reach distance + |displacement|. Returns whether it changed it.
template <int D, class Fixed>
bool stopDisplacementAtWalls(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl,
                             double distance, Fixed&& fixed, Vec<D>& displacement) {
  bool stopped = false;
  const double d2 = distance * distance;
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    if (!fixed(j)) continue;
    const Vec<D> rij = position[j] - position[i];
    const double r2 = rij.squaredNorm();
    const double approach = displacement.dot(rij);
    if (r2 <= 0.0 || approach <= 0.0 || (rij - displacement).squaredNorm() >= d2) continue;
    displacement -= (approach / r2) * rij;
    stopped = true;
  }
  return stopped;
}

}  // namespace mistfall
