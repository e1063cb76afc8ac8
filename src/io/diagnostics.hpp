// Per-output-time run diagnostics written to DIR/diagnostics.csv (one row per output time), resumable.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

struct DiagnosticsRow {
  double time = 0;
  std::int64_t step = 0;
  double dt = 0;
  std::size_t liquid = 0, gas = 0, wall = 0, dummy = 0, escaped = 0;  // counts
  double max_speed = 0, kinetic_energy = 0;  // kinetic energy per unit width in 2D [J/m], J in 3D
  int ppe_iterations = 0;
  double ppe_residual = 0;  // of the last step
  double wall_seconds = 0;  // wall-clock since run start (cumulative, survives resume)
  int gas_ppe_iterations = 0;  // the gas system's solve in the last step (0 without open gas)
  // Enclosed gas (bubbles, delta_gl = 1): how many, and the largest one (by particle count; all in bubbles.csv).
  std::size_t bubbles = 0;
  std::size_t bubble_particles = 0;
  double bubble_pressure = 0;                         // its mean pressure [Pa]
  double bubble_x = 0, bubble_y = 0, bubble_z = 0;    // its centroid [m]
  double bubble_size = 0;                             // its area [m^2] (2D) or volume [m^3] (3D)
  // Open boundaries (open_boundaries.hpp): driven inflow particles now; particles created by the inflows and
  // removed by the outflows since the start (cumulative); their rates since the previous row [particles/s].
  std::size_t inflow = 0;
  std::int64_t created = 0, removed = 0;
  double inflow_rate = 0, outflow_rate = 0;
  // Gas pressure corrections cut by numerics.gas_correction_limit or gas_speed_limit since the previous row
  // (particle-steps).
  std::int64_t gas_capped = 0;
  // Numerical guards of the liquid since the previous row (solver.hpp StepReport): collision reversals, corrected
  // gradients that fell back to the standard form, rows made free surface by numerics.liquid_support_fraction.
  std::int64_t collisions = 0, gradient_fallbacks = 0, thin_support = 0;
  // Volume of each phase (measurePhaseVolumes) [m^2 in 2D, m^3 in 3D], and the gas's mean compression
  // (n - n0)/n0 and mean pressure [Pa] over its particles of full neighbourhood: with eq. (17) at rest,
  // gas_pressure = rho_g c^2 gas_compression plus its hydrostatic mean (the gas's bulk modulus, read off two rows).
  double liquid_volume = 0, gas_volume = 0, gas_compression = 0, gas_pressure = 0;
  // The gas's other guards since the previous row (particle-steps): gas moved with the water by
  // numerics.dispersed_gas_fraction, entrained gas that rose by a phase swap (entrained_gas_rise_speed), bubble
  // rows given numerics.bubble_regularisation's sound speed.
  std::int64_t dispersed_gas = 0, entrained_swaps = 0, regularised_rows = 0;
  // What set the time step since the previous row (issue 17): the steps whose dt the fastest gas particle's
  // Courant limit made shorter than the liquid's own, and the steps the row's interval would take at the liquid's
  // dt (the sum of dt / liquid dt over its steps; compare with the step count).
  std::int64_t gas_set_dt = 0;
  double liquid_dt_steps = 0;
  // Gas below a bubble's resolution since the previous row (particle-steps): gas of enclosed regions smaller than
  // numerics.bubble_min_particles, dispersed gas included, which moves with the water (issue 16: no buoyancy of
  // its own but entrained_gas_rise_speed's swaps).
  std::int64_t entrained_gas = 0;
  // gas_capped split by guard (particle-steps): cut by numerics.gas_correction_limit, by gas_speed_limit (a
  // correction cut by both counts in both).
  std::int64_t gas_correction_capped = 0, gas_speed_capped = 0;
  // The largest particle shift of a step since the previous row, in l0 (numerics.particle_shifting, stabilised
  // scheme; 0 at rest: it scales with the particle's speed).
  double largest_shift = 0;
  // Particle shifts shortened to numerics.shift_limit since the previous row (particle-steps; a guard).
  std::int64_t shift_cuts = 0;
  // Water pressures raised to the air's beside them by numerics.gap_water_floor since the previous row
  // (particle-steps; a guard of the one equation, mps/gap_water_floor.hpp).
  std::int64_t gap_water_floors = 0;
  // Gas that entered a vent's box within l0/2 of its column's gas and was let out through the vent since the previous
  // row (particles; counted in vented_out too; mps/gas_vent.cpp, placeEnteringGas).
  std::int64_t vent_crowded_out = 0;
  // Position-only displacements stopped at a wall by numerics.shift_wall_stop since the previous row (particle-steps;
  // a guard, mps/wall_stop.hpp): the liquid's shifts, and the gas system's re-spacings of a bubble's gas (these also
  // by numerics.bubble_gas_wall_stop, and slid along a wall by numerics.respacing_walls = "slip", mps/wall_slip.hpp).
  std::int64_t shift_wall_stops = 0, respacing_wall_stops = 0;
  // A bubble gas's moves with the water (the velocity extended into the bubble) stopped at a wall by
  // numerics.bubble_gas_wall_stop since the previous row (particle-steps; a guard, mps/bubble_gas_motion.hpp); its
  // re-spacings stopped by the same key are counted in respacing_wall_stops.
  std::int64_t bubble_gas_wall_stops = 0;
  // The gas system's re-spacings of a bubble's gas shortened to numerics.respacing_limit since the previous row
  // (particle-steps; a guard).
  std::int64_t respacing_cuts = 0;
  // A bubble's interface particles whose curvature had too few points to fit since the previous row
  // (numerics.bubble_surface_tension; particle-steps; they carry no jump, mps/interface_curvature.hpp).
  std::int64_t curvature_unfitted = 0;
  // The gas system's re-spacings of a bubble's gas longer than one spacing as solved, before numerics.respacing_limit
  // and any slide along the walls or the water (mps/wall_slip.hpp), since the previous row (particle-steps).
  std::int64_t long_respacings = 0;
  // Since the previous row, the re-spacings of a bubble's gas whose approach to a particle within collision_distance
  // numerics.respacing_stop took off (the water's, or every fluid particle's; mps/wall_stop.hpp; particle-steps)
  std::int64_t respacing_fluid_stops = 0;
  // The particle of largest_shift: its id (-1: no shift in the row, or a row written before the column existed) and
  // the start of its step [s], for `mistfall simulate --trace ID --trace-from T` from the checkpoint before it.
  std::int64_t largest_shift_id = -1;
  double largest_shift_time = 0;
  // Particle shifts whose coefficient numerics.shift_stability cut to its explicit step's stability bound since the
  // previous row (particle-steps; mps/shift_stability.hpp), the liquid's and the open gas's.
  std::int64_t shift_bounded = 0;
  // Velocities the collision model kept from approaching a wall by numerics.collision_wall_limit since the previous
  // row (particle-steps; a guard, mps/collision.hpp).
  std::int64_t collision_wall_limits = 0;
  // Vent columns held at liquid in their mouth by numerics.vent_liquid_stop since the previous row (column-steps; a
  // guard, mps/gas_vent.hpp).
  std::int64_t vent_liquid_stops = 0;
  // Fluid particles dense enough to carry a pressure unknown (n >= beta n0) that numerics.surface_neighbour_fraction or
  // surface_asymmetry made free surface (p = 0) since the previous row (particle-solves, every pressure system;
  // thresholds, not physics).
  std::int64_t neighbour_surfaces = 0;
  // Water-wall pairs reversed by numerics.liquid_collision_after_correction since the previous row (pair-steps; a
  // guard, apart from `collisions`).
  std::int64_t liquid_wall_collisions = 0;
  // Points of entrained bubbles that coalesced (came within l0/2 of another and gave their gas back to the lattice;
  // mps/entrained_bubbles.hpp) since the previous row.
  std::int64_t points_coalesced = 0;
  // The vents' gas (mps/gas_vent.hpp) since the start (cumulative, particles): created at their outer faces (air
  // drawn in from the ambient) and removed past them (air pushed out).
  std::int64_t vented_in = 0, vented_out = 0;
  // Entrained gas moved as points (numerics.entrained_bubble_diameter, mps/entrained_bubbles.hpp): points now (gas
  // particles off the lattice; their volume is in gas_volume), and since the previous row the gas particles that
  // became points, the points that rejoined the gas at the surface, point steps shortened next to a wall, and
  // released points that found no water particle to give back the volume the water kept for them (the liquid count
  // is then one above the water's mass; liquid - bubble_points is the water's particles otherwise).
  std::size_t bubble_points = 0;
  std::int64_t points_made = 0, points_released = 0, point_wall_stops = 0, points_unpaired = 0;
};

// Fills the particle counts (liquid/gas = non-escaped Fluid particles by phase), max_speed and
// kinetic_energy (over Fluid particles; a particle's mass is density * l0^D, per unit width in 2D).
template <int D>
void measureParticles(DiagnosticsRow& row, const Particles<D>& p, double liquid_particle_mass,
                      double gas_particle_mass);

// Fills liquid_volume, gas_volume, gas_compression and gas_pressure. A fluid particle's volume is l0^D n0 / n_i
// (its MPS density is rho n_i / n0 and its mass rho l0^D) where its number density is at least
// `interior_fraction` n0; a particle of a thinner neighbourhood (a free surface: n_i says nothing of its volume)
// counts l0^D. The compression and pressure average the gas particles of the first kind.
template <int D>
void measurePhaseVolumes(DiagnosticsRow& row, const Particles<D>& p, double l0, double n0, double interior_fraction);

class DiagnosticsWriter {
 public:
  // Creates (truncates) the file and writes the header; if resume_time is given, keeps the existing rows
  // with time <= resume_time (+1e-12) and drops the later ones (rewritten atomically), then appends.
  DiagnosticsWriter(const std::filesystem::path& file, std::optional<double> resume_time = std::nullopt);
  void append(const DiagnosticsRow& row);  // appends one line and flushes

  // Reads a diagnostics file. Columns are matched by header name (missing ones stay default, unknown ones
  // are ignored); an incomplete last line (a crash mid-append) is skipped. Throws on a missing file.
  static std::vector<DiagnosticsRow> read(const std::filesystem::path& file);

  static std::string header();                         // the CSV header line, no newline
  static std::string formatRow(const DiagnosticsRow& row);  // one CSV line, no newline

 private:
  std::filesystem::path file_;
  std::ofstream out_;
};

}  // namespace mistfall
