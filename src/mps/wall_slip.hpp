// A position-only displacement that slides along the walls (numerics.respacing_walls = "slip"): the gas system's
// re-spacing of a bubble's gas (correctGas: the bubble's gas takes the water's velocity, bubble_gas_motion.hpp, and
// the gas system's correction only moves it) loses the part of it that goes into the wall beside it,
//   d_i <- d_i - max(0, d_i . n_i) n_i,   n_i = m_i / |m_i|,   m_i = sum_{wall j, |r_ij| < re} r_ij w(|r_ij|) / |r_ij|^2
// (r_ij = r_j - r_i: n_i points from the particle into the walls within re; the first moment of the wall
// neighbourhood, as the shift's first moment of particle_shifting.hpp). It is the no-penetration condition u . n = 0
// of a solid wall applied to the displacement, the condition Lind, Xu, Stansby & Rogers (2012, J. Comput. Phys. 231,
// 1499) impose on their shift at a boundary by removing its normal component, here only towards the wall.
// Why: the re-spacing is a gradient of the gas system's pressure, and the walls' pressures need not push back: traced
// on waterfall_small, a bubble's gas flattened on the floor was re-spaced 1.9 l0 in one step along and into the floor
// and then 0.2-2 mm a step deeper, to 1 l0 inside it (docs/waterfall.md). The collision model acts on velocities and
// never sees such a move; the stop of wall_stop.hpp acts only within collision_distance of a listed wall particle.
// A move longer than `piece` (one spacing) is slid again along its path (slideAlongWallsOnPath): the walls within re
// of its start need not be the walls it reaches. Traced on the 5 mm waterfall, a bubble's gas 3.6 l0 above the floor
// was re-spaced 10.8 l0 in one step, 3.7 l0 into the floor, which was beyond re of its start (docs/waterfall.md).
#pragma once

#include <cstddef>
#include <vector>

#include "mps/particle_shifting.hpp"
#include "mps/wall_cells.hpp"

namespace mistfall {

// d <- d - max(0, d . n) n with n = moment / |moment| (the walls' first moment); whether it changed d.
template <int D>
bool removePartIntoWalls(const Vec<D>& moment, Vec<D>& displacement) {
  const double size = moment.norm();
  if (size <= 0.0) return false;
  const Vec<D> normal = moment / size;
  const double into = displacement.dot(normal);
  if (into <= 0.0) return false;
  displacement -= into * normal;
  return true;
}

// Removes from `displacement` of particle i its component into the walls (fixed(j)) within `re` (see above).
// Returns whether it changed it.
template <int D, class Fixed>
bool slideDisplacementAlongWalls(std::size_t i, const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                                 Fixed&& fixed, Vec<D>& displacement) {
  return removePartIntoWalls<D>(neighbourhoodFirstMoment<D>(i, position, nl, re, fixed), displacement);
}

// Removes from the component into the walls along `displacement`'s whole path from `start` (a move already slid at
// its start, slideDisplacementAlongWalls): it is taken in pieces of at most `piece` (< re); at the end of each the
// rest of it loses its component into the walls within re there (`walls`), d <- d - max(0, d . n) n as above.
// Returns whether it changed it. A move no longer than `piece` is left as it is, and so is one of more than
// `max_pieces` pieces (a diverged move, not read step by step).
template <int D>
bool slideAlongWallsOnPath(const Vec<D>& start, const WallCells<D>& walls, double piece, Vec<D>& displacement,
                           double max_pieces = 1e5) {
  if (!(displacement.norm() <= max_pieces * piece)) return false;
  Vec<D> at = start, rest = displacement;
  bool slid = false;
  while (rest.norm() > piece) {
    const Vec<D> step = rest * (piece / rest.norm());
    at += step, rest -= step;
    slid = removePartIntoWalls<D>(walls.firstMoment(at), rest) || slid;
  }
  if (slid) displacement = at + rest - start;
  return slid;
}

}  // namespace mistfall
