// Open boundaries: inflow buffers and outflow boxes (the waterfall's weir inflow and pool outflow; the case file's
// [[inflow]] and [[outflow]], case_config.hpp).
//  * Inflow: the buffer's particles (kind Inflow) are driven at the inflow velocity U (r += dt U, u = U), their
//    pressure solved (inflow_pressure.hpp). One that crosses the buffer's downstream face becomes Fluid. When the
//    upstream-most layer has moved so far that one more lattice layer fits behind it inside the box, that layer
//    is created, at the box's lattice points across the flow: water enters one layer per l0 / U, so the discharge
//    is q = U * n * l0 with n the layer's particle count (2D; n = depth / l0 gives q = U * depth).
//  * Outflow: every liquid particle inside an outflow box is removed; the arrays are compacted (order kept). Gas
//    passes through (the air around a waterfall is not drained by the pool's outlet).
// Nothing about a buffer is stored between steps but its particles, so a checkpoint restarts it exactly.
#pragma once

#include <cstdint>

#include "case/case_config.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// Whether x lies in the box [min, max) on each of the first D axes.
template <int D>
bool insideBox(const Vec<D>& x, const Box& b) {
  for (int k = 0; k < D; ++k)
    if (x[k] < b.min[k] || x[k] >= b.max[k]) return false;
  return true;
}

// Moves every inflow buffer's particles by dt, releases those past the downstream face and creates the layers
// that fit. Returns the number of particles created.
template <int D>
std::int64_t advanceInflows(Particles<D>& p, const CaseConfig& c, double dt);

// Removes the liquid particles inside an outflow box. Returns how many.
template <int D>
std::int64_t removeOutflow(Particles<D>& p, const CaseConfig& c);

}  // namespace mistfall
