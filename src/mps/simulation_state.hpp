// The complete state of a run at one instant: what a checkpoint stores and a resume restores.
#pragma once

#include <cstdint>
#include <map>

#include "mps/particles.hpp"

namespace mistfall {

template <int D>
struct SimulationState {
  double time = 0.0;          // simulated time [s]
  std::int64_t step = 0;      // steps taken
  double dt = 0.0;            // last time step [s]
  int next_frame = 0;         // index of the next frame to write
  std::int64_t created = 0;   // particles created by inflows since the start
  std::int64_t removed = 0;   // particles removed by outflows since the start (liquid past a vent's face too)
  std::int64_t vented_in = 0;   // gas particles created by the vents since the start (gas_vent.hpp)
  std::int64_t vented_out = 0;  // gas particles removed by the vents since the start
  Particles<D> particles;
  // The force each entrained point (entrained_bubbles.hpp) put on the water over its last step, by particle id: the
  // next step takes its echo out of the water's acceleration the point reads.
  std::map<std::uint64_t, Vec<D>> point_forces;
  // The pressure at which a bubble's gas particle sits at its initial spacing, by particle id: set on a fresh run's
  // first step for the gas of the bubbles present at t = 0 (numerics.bubble_initial_pressure = "water"), whose
  // lattice is the gas at the pressure of the water around it, not at the ambient. eq. (17)'s row of a bubble then
  // settles at P_0 + rho_g c^2 delta (solver_liquid.cpp). Gas without an entry is at its spacing at 0 Pa.
  std::map<std::uint64_t, double> gas_reference_pressure;
};

}  // namespace mistfall
