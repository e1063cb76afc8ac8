// Initial particle arrangement of a case: water, gas and wall regions filled on one cubic lattice.
// Lattice rule: points are domain.min[k] + (i_k + 0.5) * l0 for integers i_k >= 0; a point belongs to a
// box when min[k] <= x[k] < max[k] on every axis, to a circle (disc / sphere) when |x - center| <= radius
// (both with a 1e-9 * l0 tolerance, see docs/case-file.md).
// Overlaps: a point in any wall region is solid; otherwise it takes the material (and velocity) of the
// last-declared water or gas region that contains it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "case/case_config.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// Lattice indices per axis must stay below this (they are packed into 21 bits each).
inline constexpr std::int64_t kMaxLatticeIndex = (std::int64_t{1} << 21) - 2;

// Number of lattice points along axis `axis` inside the domain.
std::int64_t domainLatticeCount(const CaseConfig& c, int axis);

// Number of lattice points inside box `b` (first c.dimension axes), clipped to the domain.
std::size_t countLatticePoints(const CaseConfig& c, const Box& b);

// Number of lattice points inside region `r` (box or circle), clipped to the domain, before overlaps are
// resolved.
std::size_t countLatticePoints(const CaseConfig& c, const Region& r);

// Per region (same order as c.regions), the number of particles it contributes after overlaps are resolved:
// for a water or gas region its points that lie in no wall region and in no later water or gas region; for a
// wall region all its points (points shared by several wall regions count in each).
std::vector<std::size_t> regionParticleCounts(const CaseConfig& c);

// Coordinates along `axis` of the lattice points inside box `b` (clipped to the domain), ascending.
std::vector<double> latticeCoordinates(const CaseConfig& c, const Box& b, int axis);

// Particles for the case: water first (regions in file order, each in lexicographic lattice order with
// axis 0 slowest, points lost to overlaps or inside an inflow box skipped), then gas (same rule), then the
// lattice points of each inflow box (kind Inflow, water, at the inflow velocity), then the union of wall regions in
// lexicographic order. A solid point is Wall if one of its 3^D - 1 lattice neighbours inside the domain is
// not solid (water, gas or empty), otherwise Dummy.
// Requires c.dimension == D (throws std::invalid_argument otherwise).
template <int D>
Particles<D> buildParticles(const CaseConfig& c);

extern template Particles<2> buildParticles<2>(const CaseConfig& c);
extern template Particles<3> buildParticles<3>(const CaseConfig& c);

}  // namespace mistfall
