// Gas vents: openings of the air to the ambient atmosphere (the case file's [[vent]], case_config.hpp; issue 16,
// item 3: a laboratory weir's nappe is ventilated). A vent is a box cut through a wall, filled with gas at set-up,
// with an outward axis n (case/scene.cpp fills the box's lattice points that no region's fluid holds). Its gas is a buffer in the manner of the SPH open boundaries of Lastiwka, Basa & Quinlan
// (2009, "Permeable and non-reflecting boundary conditions in SPH", IJNMF 61) and Tafuni, Dominguez, Vacondio &
// Crespo (2018, "A versatile algorithm for the treatment of open boundary conditions in SPH GPU models", CMAME 342):
//  * the pressure is imposed: the ambient air at rest, p_a(x) = rho_g g.x (zero at the case's origin), is a
//    Dirichlet boundary of the gas system (solver_gas.cpp) on the vent's gas particles, less the entering air's
//    dynamic pressure where a column enters (ventPressure, below);
//  * the velocity is extrapolated with zero normal gradient: each lattice column of the vent (its particles nearest
//    one lattice line along n) moves as one, along n, at the mean normal velocity u_n of the domain's gas within
//    2 l0 in front of the vent's inner face (0 where there is none); in its neighbours' divergence the vent's gas
//    counts with that velocity (numerics.vent_outlet = "buffer", Tafuni's buffer), or not at all ("zero_gradient":
//    each neighbour sees it moving as itself, so a column cannot draw the air it follows; with the columns'
//    velocities in that divergence, a column and the air in front of it fed on each other at a vent's edges on the
//    stabilised gas operators: tests/test_gas_vent.cpp, docs/waterfall.md);
//  * gas that enters the box from the domain joins its column: it is put on the column's line across the vent,
//    keeping its place along it, with the column's velocity, or leaves through the vent where it would lie within
//    l0/2 of the column's gas (gas_vent.cpp, placeEnteringGas), so the columns give back no close pairs;
//  * gas that passes the outer face leaves the domain (removed, counted); where a column has moved inward so far
//    that one more lattice layer fits between its outermost particle and the outer face, that layer is created
//    with the column's velocity (as an inflow buffer creates its layers, open_boundaries.hpp).
// The air then leaves where the domain pushes it out and enters where the domain draws it in, at the ambient
// pressure. Liquid in a vent is not driven; liquid that passes the outer face is removed like an outflow's, or, with
// the vent's liquid_exit = "inner_face", liquid that is in the box at a step's end (spray reaching the opening): a
// droplet inside a column stands among gas the column moves only along its axis, which does not make way for it
// (traced at 5 mm, docs/waterfall.md: a droplet falling back through the roof vent's column, n = 31-33, was shifted
// to 0.096 l0 from an air particle, which the next gas correction threw out at 1,550 m/s).
// Nothing about a vent is stored between steps but its particles, so a checkpoint restarts it exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "case/case_config.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// The ambient air's pressure at x: rho_g g.x [Pa].
template <int D>
double ambientPressure(const Vec<D>& x, double gas_density, const Vec<D>& gravity) {
  return gas_density * gravity.dot(x);
}

// The pressure a vent's gas holds (a Dirichlet value of the pressure equation), from its column's velocity u: where
// the column leaves the domain (u.n >= 0), the ambient's p_a(x); where it enters, with `inflow = "total_pressure"`,
// the ambient air's total pressure less the dynamic pressure of the entering air,
//   p = p_a(x) - rho_g (u.n)^2 / 2      (u.n < 0),
// the air drawn in from rest outside without loss (Bernoulli along a streamline from the still ambient): the
// entrainment condition of an opening to the atmosphere (in OpenFOAM, totalPressure with
// pressureInletOutletVelocity). With the static pressure p_a on entry (`inflow = "static"`, the first version) a
// suction of a few pascals draws air in with nothing to bound its speed: at l0 = 5 mm a column at the edge of
// waterfall.toml's roof vent fed on the air it drew and reached 7.8 m/s within 0.2 s (docs/two-phase.md).
template <int D>
double ventPressure(const Vec<D>& x, const Vec<D>& u, const Vent& vent, double gas_density, const Vec<D>& gravity) {
  const double un = vent.sign * u[vent.axis];
  const bool total = vent.inflow == Vent::Inflow::TotalPressure;
  return ambientPressure<D>(x, gas_density, gravity) - (total && un < 0.0 ? 0.5 * gas_density * un * un : 0.0);
}

// Which vent each particle is in (-1: none), by position.
template <int D>
std::vector<int> ventOf(const Particles<D>& p, const CaseConfig& c);

// What the vents exchanged with the ambient in one step (particles).
struct VentExchange {
  std::int64_t gas_in = 0;      // gas created at outer faces
  std::int64_t gas_out = 0;     // gas removed past outer faces
  std::int64_t liquid_out = 0;  // liquid removed past outer faces
  std::int64_t gas_crowded_out = 0;  // of gas_out: gas that entered a box within l0/2 of its column's gas
  std::int64_t liquid_stops = 0;     // columns held by numerics.vent_liquid_stop (liquid at their mouth)
  std::vector<std::int64_t> gas_in_by_vent, gas_out_by_vent, liquid_out_by_vent;  // per vent, in the case's order
};

// numerics.vent_liquid_stop (a guard, counted in liquid_stops): a column drawn inward whose drive would bring one of
// its particles within collision_distance of a liquid particle, approaching it, does not move inward in the step.
// A column is driven, not moved by the pressure, and nothing else stops it: traced on waterfall_small (docs/
// waterfall.md), a spray droplet at the roof vent's mouth with the column drawn in at 4.4 m/s onto it; its first
// particle, 0.15 l0 from the droplet (n = 18.9 against 6.5), left the box and the next gas solve threw the air beside
// it out of the domain at 700 m/s.
// Drives the vents' gas over the step: `start` holds, for each particle with start_vent[i] >= 0 (its vent at the
// step's start), its position then. Each such gas particle is set to start + dt u_n n with its column's u_n; then
// what passed an outer face is removed and the layers that fit are created (the arrays are compacted, order
// kept; new particles come last). `gravity` and `gas_density` give the new particles' ambient pressure.
template <int D>
VentExchange exchangeVentGas(Particles<D>& p, const CaseConfig& c, const std::vector<int>& start_vent,
                             const std::vector<Vec<D>>& start, double dt, double gas_density, const Vec<D>& gravity);

}  // namespace mistfall
