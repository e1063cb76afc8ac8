// Initial particle arrangement of a case: water and wall regions filled on one cubic lattice.
// Lattice rule: points are domain.min[k] + (i_k + 0.5) * l0 for integers i_k >= 0; a point belongs to a
// box when min[k] <= x[k] < max[k] on every axis (with a 1e-9 * l0 tolerance, see docs/case-file.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "case/case_config.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// Lattice indices per axis must stay below this (they are packed into 21 bits each).
inline constexpr std::int64_t kMaxLatticeIndex = (std::int64_t{1} << 21) - 2;

// Number of lattice points along axis `axis` inside the domain.
std::int64_t domainLatticeCount(const CaseConfig& c, int axis);

// Number of lattice points inside box `b` (first c.dimension axes), clipped to the domain.
std::size_t countLatticePoints(const CaseConfig& c, const Box& b);

// Particles for the case: water regions first (region order, lexicographic lattice order with axis 0
// slowest), then the union of wall regions in lexicographic order. A solid point is Wall if one of its
// 3^D - 1 lattice neighbours inside the domain is not solid, otherwise Dummy.
// Requires c.dimension == D (throws std::invalid_argument otherwise).
template <int D>
Particles<D> buildParticles(const CaseConfig& c);

extern template Particles<2> buildParticles<2>(const CaseConfig& c);
extern template Particles<3> buildParticles<3>(const CaseConfig& c);

}  // namespace mistfall
