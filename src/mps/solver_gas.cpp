// The gas's pressure system and correction, eqs. (6), (8), (17) (the step's stages `solveGasPressure`,
// `correctGas`, `riseEntrainedGas`, and `moveBubbleGas` of MpsSolver, solver.hpp): every gas particle carries an
// unknown, with the moved liquid and the walls next to gas as its walls (phase_coupling.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mps/bubble_gas_motion.hpp"
#include "mps/entrained_gas_rise.hpp"
#include "mps/gas_vent.hpp"
#include "mps/gradient.hpp"
#include "mps/number_density.hpp"
#include "mps/pair_loop.hpp"
#include "mps/particle_shifting.hpp"
#include "mps/shift_stability.hpp"
#include "mps/wall_mirror.hpp"
#include "mps/wall_slip.hpp"
#include "mps/wall_stop.hpp"
#include "mps/solver.hpp"

namespace mistfall {

// numerics.gas_operators = "stabilised": the liquid that is a wall of the gas system (not gas of any kind), mirrored
// like the walls: seen from gas particle i it holds p_i + rho_g g . r_ij, and its velocity enters the divergence.
template <int D>
bool MpsSolver<D>::mirroredLiquid(std::size_t j) const {
  const auto& p = state_.particles;
  return p.phase[j] == Phase::Liquid && !isMirroredWall(p.kind[j]) && isActive(p.kind[j]);
}

// The gas system, eq. (17) with the gas's sound speed: every gas particle, and as its walls every wall or liquid
// particle within re of gas (at the liquid's corrected positions). n* counts every particle. With
// numerics.gas_domain = "open" the gas has free-surface particles (p = 0) and open gas pressures are clamped at 0;
// with "closed" every particle of the system is an unknown and may be below the ambient. In both, a bubble's
// pressures are kept as solved, since only their gradient is used (to re-space its gas; the bubble's own pressure
// P_B comes from the liquid system).
template <int D>
void MpsSolver<D>::solveGasPressure(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  markGasSideWalls<D>(p, near_neighbours_, constants_.re_number_density, roles_);
  const double re = constants_.re_number_density;
  gas_number_density_.assign(n, 0.0);
  auto active = [&](std::int32_t j) { return isActive(p.kind[j]); };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (roles_.inGasSystem(i) || roles_.gas_side_wall[i])
      gas_number_density_[i] = numberDensityAt<D>(i, p.position, near_neighbours_, re, active);
  const double beta_n0 = config_.numerics.surface_threshold * constants_.n0;
  const PhaseProperties& gas = phases_[static_cast<int>(Phase::Gas)];
  std::vector<char> active_flags(n);
  for (std::int64_t i = 0; i < n; ++i) active_flags[i] = isActive(p.kind[i]);
  problem_.takes_part.assign(n, 0);
  problem_.unknown.assign(n, 0);
  problem_.carries_velocity.assign(n, 0);
  problem_.density = gas.density;
  problem_.sound_speed.assign(n, gas.sound_speed);
  const bool closed = config_.numerics.gas_domain == GasDomain::Closed;
  const bool mirrored = config_.numerics.gas_stabilised;  // walls and liquid mirrored (wall_mirror.hpp)
  for (std::int64_t i = 0; i < n; ++i) {
    problem_.takes_part[i] = roles_.inGasSystem(i) || roles_.gas_side_wall[i];
    if (mirrored && (isMirroredWall(p.kind[i]) || mirroredLiquid(i))) problem_.takes_part[i] = 0;  // known part below
    const bool dense = gas_number_density_[i] >= beta_n0;
    // numerics.bubble_cavity = "joined": a bubble's gas is never a free surface (at a cavity's edge it would be held
    // at p = 0 while its neighbours are drawn to it, instead of spreading into the cavity)
    const bool joined_bubble = config_.numerics.bubble_cavity_joined && roles_.enclosed_gas[i];
    problem_.unknown[i] = problem_.takes_part[i] &&
                          (closed || joined_bubble || (dense && hasFullNeighbourhood(i, active_flags)));
    if (problem_.takes_part[i] && !closed && dense && !problem_.unknown[i]) ++report_.neighbour_surfaces;
    // (mirrored walls' rest enters through mirroredWallTerm below; the liquid's velocity stays in the divergence)
    problem_.carries_velocity[i] = isActive(p.kind[i]) && !(mirrored && isMirroredWall(p.kind[i]));
    // A bubble and the liquid ring around it form a block with no free surface: with c = infinity its pressure
    // level is undetermined. Only its gradient re-spaces the gas (the bubble's pressure is the liquid system's
    // P_B), so a (nearly) incompressible gas gets a regularising sound speed of numerics.bubble_regularisation
    // l0 / dt on the bubble's rows (10: a shift of about 1e-3 of the diagonal, which keeps the solve well
    // conditioned; 0: none, the paper's incompressible gas).
    if (roles_.enclosed_gas[i] && config_.numerics.bubble_regularisation > 0.0 && problem_.unknown[i] &&
        config_.numerics.bubble_regularisation * constants_.l0 / dt < gas.sound_speed) {
      problem_.sound_speed[i] = config_.numerics.bubble_regularisation * constants_.l0 / dt;
      ++report_.regularised_rows;
    }
  }
  // The vents' gas holds the ambient pressure (ventGasPressure, solver.hpp): a Dirichlet boundary of the system; with
  // numerics.vent_outlet = "zero_gradient" it has no part in its neighbours' divergence.
  problem_.boundary_value.clear();
  auto vented = [&](std::int64_t i) { return isVentGas(static_cast<std::size_t>(i)) && roles_.open_gas[i]; };
  if (!vent_at_start_.empty()) {
    problem_.boundary_value.assign(n, 0.0);
    for (std::int64_t i = 0; i < n; ++i)
      if (vented(i) && problem_.takes_part[i]) {
        problem_.unknown[i] = 0;
        if (config_.numerics.vent_zero_gradient) problem_.carries_velocity[i] = 0;
        problem_.boundary_value[i] = ventGasPressure(static_cast<std::size_t>(i), gas.density);
      }
  }
  const PressureSourceTerm source = sourceTermFor(config_.numerics, dt);  // pressure_poisson.hpp
  // eq. (17)'s memory (pressure_poisson.hpp) on the open gas's rows: its pressure of the last step (with
  // numerics.gas_pressure_memory `true` or "open_gas"; "bubbles" leaves the open gas's rows soft)
  problem_.extra_rhs.clear();
  problem_.velocity_group.clear();  // the liquid system's bubble groups are not this system's
  problem_.sourceless.clear();  // the inflows' rows are the liquid's (inflow_pressure.hpp)
  if (config_.numerics.gas_pressure_memory_open) {
    problem_.extra_rhs.assign(n, 0.0);
    for (std::int64_t i = 0; i < n; ++i)
      if (roles_.open_gas[i] && problem_.unknown[i])
        problem_.extra_rhs[i] = compressibleMemoryTerm(source, p.pressure[i], dt, problem_.sound_speed[i]);
  }
  // numerics.bubble_cavity = "joined": a bubble's rows take the whole density term (gamma = 1), so the re-spacing
  // spreads its gas through the bubble's void, cavity included, each step (its pressure is P_B's, not these rows')
  if (config_.numerics.bubble_cavity_joined) {
    if (problem_.extra_rhs.empty()) problem_.extra_rhs.assign(n, 0.0);
    for (std::int64_t i = 0; i < n; ++i)
      if (roles_.enclosed_gas[i] && problem_.unknown[i])
        problem_.extra_rhs[i] += (1.0 - source.relaxation) * gas.density / (dt * dt) *
                                 (gas_number_density_[i] - constants_.n0) / constants_.n0;
  }
  // numerics.gas_operators = "stabilised": the known part of each row from the walls (wall_mirror.hpp: hydrostatic
  // and the walls' rest in the divergence) and from the liquid (hydrostatic only: its velocity is in the divergence).
  if (mirrored) {
    if (problem_.extra_rhs.empty()) problem_.extra_rhs.assign(n, 0.0);
    auto liquid = [&](std::int32_t j) { return mirroredLiquid(static_cast<std::size_t>(j)); };
    const double factor = constants_.laplacianFactor();
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      if (!problem_.unknown[i]) continue;
      double hydrostatic = 0.0;
      forEachPairWithin<D>(i, p.position, neighbours_, constants_.re_laplacian, liquid,
                           [&](std::int32_t, const Vec<D>& rib, double, double w) { hydrostatic += w * gravity_.dot(rib); });
      problem_.extra_rhs[i] +=
          mirroredWallTerm<D>(i, p.position, p.velocity, p.kind, neighbours_, constants_, gas.density, gravity_, dt) +
          factor * gas.density * hydrostatic;
    }
  }
  assemblePressureSystem<D>(p, gas_number_density_, neighbours_, constants_, problem_, source, dt, system_,
                            &near_neighbours_);
  solveSystem(p.pressure, "gas", report_.gas_ppe_iterations);
  report_.gas_ppe_unknowns = system_.particle_of.size();
  gas_pressure_.assign(n, 0.0);
  if (!problem_.boundary_value.empty())
    for (std::int64_t i = 0; i < n; ++i)
      if (vented(i)) gas_pressure_[i] = problem_.boundary_value[i];
  for (std::size_t r = 0; r < system_.particle_of.size(); ++r) {
    const auto i = system_.particle_of[r];
    const double solved = pressure_unknowns_[r];
    gas_pressure_[i] = (roles_.enclosed_gas[i] || closed) ? solved : std::max(0.0, solved);
  }
  extrapolateDummyPressure(gas_pressure_, gas.density, !closed);
  for (std::int64_t i = 0; i < n; ++i) {
    if (!roles_.open_gas[i]) continue;
    p.pressure[i] = gas_pressure_[i];
    p.number_density[i] = gas_number_density_[i];
  }
}

// The gradient of the gas system's pressure at gas particle i with mirrored walls and liquid
// (numerics.gas_operators = "stabilised"): a wall, dummy or liquid neighbour b holds p_i + rho_g g . r_ib
// (wall_mirror.hpp). Away from the liquid the corrected gradient (exact for the hydrostatic field whatever the
// arrangement); with liquid within re the minimum-neighbour form (its repulsion keeps the gas off the water: over the
// paper scheme's drifting water the corrected form there let the air reach 2.8 m/s within 1 s, docs/two-phase.md).
template <int D>
Vec<D> MpsSolver<D>::stabilisedGasGradient(std::size_t i) const {
  const auto& p = state_.particles;
  const double rho = phases_[static_cast<int>(Phase::Gas)].density;
  auto value = [&](std::int32_t j) {
    const bool mirrored = isMirroredWall(p.kind[j]) || mirroredLiquid(j);
    return mirrored ? gas_pressure_[i] + rho * gravity_.dot(p.position[j] - p.position[i]) : gas_pressure_[j];
  };
  auto inMinimum = [&](std::int32_t j) {
    return roles_.inGasSystem(j) || roles_.gas_side_wall[j] || isMirroredWall(p.kind[j]);
  };
  auto difference = [&](std::int32_t j, const Vec<D>&) { return value(j) - gas_pressure_[i]; };
  const double re = constants_.re_number_density;
  bool liquid = false;
  forEachPairWithin<D>(i, p.position, near_neighbours_, re, inMinimum, [&](std::int32_t j, const Vec<D>&, double, double) {
    liquid = liquid || mirroredLiquid(j);
  });
  // Next to the liquid the standard form: the corrected gradient's own fallback (a determinant no moment reaches).
  const double min_determinant =
      liquid ? std::numeric_limits<double>::infinity() : config_.numerics.gradient_correction_min_determinant;
  return correctedGradientAt<D>(i, p.position, near_neighbours_, constants_, min_determinant, inMinimum, difference)
      .value;
}

// Correction of the gas with the gas system's pressures (the liquid is not moved by it).
template <int D>
void MpsSolver<D>::correctGas(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double rho = phases_[static_cast<int>(Phase::Gas)].density;
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  auto solvedPressure = [&](std::int32_t j) { return roles_.inGasSystem(j) || roles_.gas_side_wall[j]; };
  auto carriesPressure = [&](std::int32_t j) { return isActive(p.kind[j]); };
  // numerics.gas_correction_limit: |u'| <= limit l0 / dt_max, a move of limit l0 in a step of dt_max (a correction
  // that would carry gas particles past their neighbours in one step comes from a pressure outlier, not from the
  // flow). The cap is a speed, not limit l0 / dt: a kick of l0 / dt lowers the Courant step, which would loosen a
  // cap of l0 / dt, and the next kick would be larger (on the waterfall at l0 = 5 mm, dt fell to 3e-5 s and the
  // air reached 17-30 m/s that way).
  const double limit = config_.numerics.gas_correction_limit * constants_.l0 / config_.numerics.dt_max;
  const double speed_limit = config_.numerics.gas_speed_limit;
  std::size_t capped = 0, correction_cuts = 0, speed_cuts = 0;
  // The vents' gas is moved by its vent at the end of the step (gas_vent.hpp: its column's velocity replaces
  // whatever a correction gave it), so it takes no correction here, and no guard counts it.
#pragma omp parallel for schedule(static) reduction(+ : capped, correction_cuts, speed_cuts)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!roles_.inGasSystem(i) || isVentGas(i)) continue;
    change[i] = -dt / rho * (config_.numerics.gas_stabilised
                                 ? stabilisedGasGradient(i)
                                 : gradientAt<D>(i, p.position, gas_pressure_, near_neighbours_, constants_,
                                                 GradientForm::MinimumNeighbour, carriesPressure, solvedPressure));
    const double size = change[i].norm();
    bool cut = false;
    if (limit > 0.0 && size > limit) change[i] *= limit / size, cut = true, ++correction_cuts;
    // numerics.gas_speed_limit: open gas leaves the correction at most this fast (the correction is shortened so
    // that |u* + u'| <= limit; the bubbles' gas moves with the water).
    if (speed_limit > 0.0 && !roles_.enclosed_gas[i]) {
      const Vec<D> corrected = p.velocity[i] + change[i];
      const double speed = corrected.norm();
      if (speed > speed_limit) change[i] = corrected * (speed_limit / speed) - p.velocity[i], cut = true, ++speed_cuts;
    }
    capped += cut;
  }
  report_.gas_corrections_capped = capped;
  report_.gas_correction_cuts = correction_cuts;
  report_.gas_speed_cuts = speed_cuts;
  const bool own_pressure = !bubbleGasFollowsLiquid();
  // numerics.shift_wall_stop or bubble_gas_wall_stop (guards, counted): a bubble gas's re-spacing, a move without a
  // velocity that the collision model cannot see, does not approach a wall particle it would bring within
  // collision_distance (wall_stop.hpp; only fixed particles are read, so the loop may move the gas as it goes).
  // numerics.respacing_limit (a guard, counted): a re-spacing longer than limit l0 is shortened to it. A re-spacing
  // changes no velocity, so the time step does not see it: traced on waterfall_small with the stiff bubbles, a bubble's
  // gas particle was re-spaced 4.3 l0 in one step to 0.12 l0 from another, and the next step's rows moved it 16 cm
  // through the floor (docs/waterfall.md).
  const bool wall_stop = config_.numerics.shift_wall_stop || config_.numerics.bubble_gas_wall_stop;
  const double stop_distance = config_.numerics.collision_distance * constants_.l0;
  const double respacing_limit = config_.numerics.respacing_limit * constants_.l0;
  auto fixed = [&](std::int32_t j) { return isFixed(p.kind[j]); };
  // A re-spacing longer than one spacing reads the walls along its path (wall_slip.hpp); they are binned only in a
  // step that has one.
  const double piece = constants_.l0;
  const bool slip = config_.numerics.respacing_slip && !own_pressure;
  bool long_move = false;
  for (std::int64_t i = 0; slip && !long_move && i < n; ++i)
    long_move = roles_.enclosed_gas[i] && dt * change[i].norm() > piece;
  std::optional<WallCells<D>> walls;
  if (long_move) walls.emplace(p.position, fixed, constants_.re_number_density);
  // numerics.respacing_stop (a guard, counted): the re-spacing does not approach a particle it would bring within
  // collision_distance (wall_stop.hpp), before the cut and the walls: "water", the water around a bubble, its gas's
  // other wall; "fluid", every fluid particle, the bubble's own gas too. Traced at 5 mm, a bubble's gas re-spaced
  // 1.4 l0 came to 0.14 l0 from a water particle, the next liquid correction gave that water 18 m/s, and the cascade
  // re-spaced gas 10.8 l0; in a stiff joined bubble at 1.25 mm two of its gas particles re-spaced onto each other
  // (n = 18.6 n0 / 6.6) were re-spaced 42 l0 into the walls the step after (docs/waterfall.md, docs/validation.md). A
  // slide along the water's first moment instead (as along the walls) kept the gas from following the water where it
  // opens the bubble's top: the coarse bubble of tests/test_waterfall_bubbles.cpp rose 0.39 cm in 0.12 s, 2.36 cm with
  // the stop. With "fluid" the loop runs in index order on one thread and the stop reads the gas already moved where it
  // is now (the same bits on any thread count): read at the loop's start instead, two gas particles re-spaced into the
  // same gap met there, and the 1.25 mm bubble diverged at 83 ms. The water does not move in the loop.
  using Stop = NumericsConfig::RespacingStop;
  const Stop stop_at = own_pressure ? Stop::None : config_.numerics.respacing_stop;
  auto stopsRespacing = [&](std::int32_t j) {
    return p.kind[j] == ParticleKind::Fluid && (stop_at == Stop::Fluid || p.phase[j] == Phase::Liquid);
  };
  std::size_t stops = 0, respacing_cuts = 0, long_respacings = 0, fluid_stops = 0;
#pragma omp parallel for schedule(static) reduction(+ : stops, respacing_cuts, long_respacings, fluid_stops) \
    if (stop_at != Stop::Fluid)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!roles_.inGasSystem(i)) continue;
    const bool respacing = roles_.enclosed_gas[i] && !own_pressure;
    if (!respacing) p.velocity[i] += change[i];
    Vec<D> move = dt * change[i];
    long_respacings += respacing && move.norm() > piece;  // as solved, before a cut or a slide
    if (respacing && stop_at != Stop::None)
      fluid_stops += stopDisplacementAtWalls<D>(static_cast<std::size_t>(i), p.position, near_neighbours_,
                                                stop_distance, stopsRespacing, move);
    if (respacing && respacing_limit > 0.0 && move.norm() > respacing_limit)
      move *= respacing_limit / move.norm(), ++respacing_cuts;
    // numerics.respacing_walls = "slip": the re-spacing slides along the walls within re of its start and, when it is
    // longer than one spacing, of each spacing of its path (wall_slip.hpp).
    bool stopped = false;
    if (respacing && slip) {
      stopped = slideDisplacementAlongWalls<D>(static_cast<std::size_t>(i), p.position, near_neighbours_,
                                               constants_.re_number_density, fixed, move);
      if (walls && move.norm() > piece)
        stopped = slideAlongWallsOnPath<D>(p.position[i], *walls, piece, move) || stopped;
    }
    if (respacing && wall_stop)
      stopped = stopDisplacementAtWalls<D>(static_cast<std::size_t>(i), p.position, near_neighbours_, stop_distance,
                                           fixed, move) || stopped;
    stops += stopped;
    p.position[i] += move;
  }
  report_.respacing_wall_stops = stops;
  report_.respacing_cuts = respacing_cuts;
  report_.long_respacings = long_respacings;
  report_.respacing_fluid_stops = fluid_stops;
  // numerics.gas_operators = "stabilised": the open gas is shifted as the stabilised liquid is (particle_shifting.hpp,
  // every active neighbour in the sum: the corrected gradient keeps nothing evenly spaced), but a vent's gas, which its
  // column moves (gas_vent.hpp).
  if (config_.numerics.gas_stabilised && config_.numerics.particle_shifting > 0.0) {
    std::vector<Vec<D>> shift(n, Vec<D>::Zero());
    auto all = [&](std::int32_t j) { return isActive(p.kind[j]); };
    const double a = config_.numerics.particle_shifting;
    const auto kernel = config_.numerics.shifting_kernel;
    std::size_t bounded = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounded)
    for (std::int64_t i = 0; i < n; ++i) {
      if (!roles_.open_gas[i] || isVentGas(static_cast<std::size_t>(i))) continue;
      shift[i] = shiftingDisplacement<D>(i, p.position, near_neighbours_, constants_, a, p.velocity[i], dt,
                                         Vec<D>::Zero(), all, kernel);
      const double factor = shiftStabilityFactor<D>(i, p.position, near_neighbours_, constants_, a,
                                                    p.velocity[i].norm(), dt, config_.numerics.shift_stability, all,
                                                    kernel);
      if (factor < 1.0) shift[i] *= factor, ++bounded;
    }
    report_.shift_bounded += bounded;
    for (std::int64_t i = 0; i < n; ++i) p.position[i] += shift[i];
  }
}

// Entrained gas below a bubble's resolution rises through the water by exchange (entrained_gas_rise.hpp).
template <int D>
void MpsSolver<D>::riseEntrainedGas(double dt) {
  const double speed = config_.numerics.entrained_gas_rise_speed;
  if (speed <= 0.0 || gravity_.norm() == 0.0) return;
  const Vec<D> up = -gravity_ / gravity_.norm();
  report_.entrained_gas_swaps = mistfall::riseEntrainedGas<D>(state_.particles, near_neighbours_, regions_, roles_, up,
                                                              constants_.l0, speed, dt, state_.step);
}

// Entrained gas below a bubble's resolution moves as points through the water (entrained_bubbles.hpp): the gas
// of enclosed regions too small to be bubbles, away from the vents, may leave the lattice at this step.
template <int D>
void MpsSolver<D>::moveEntrainedBubbles(double dt) {
  auto& p = state_.particles;
  std::vector<char> candidate(p.size(), 0);
  // Below a bubble's resolution: the gas of enclosed regions of fewer than bubble_min_particles. On the two systems
  // that is the enclosed gas that is not a bubble's (phase_coupling.hpp); the one equation has no bubbles of its own.
  const std::vector<std::size_t> region_size = regions_.regionSizes();
  const auto resolved = static_cast<std::size_t>(config_.numerics.bubble_min_particles);
  for (std::size_t i = 0; i < p.size() && i < regions_.enclosed_particle.size(); ++i)
    candidate[i] = regions_.enclosed_particle[i] &&
                   region_size[static_cast<std::size_t>(regions_.region_of[i])] < resolved && !isVentGas(i);
  const std::size_t before = p.size();
  EntrainedBubbleCounts counts = entrained_bubbles_->advance(p, start_velocity_, candidate, dt, state_.point_forces);
  if (p.size() > before) {  // the new points take no part in the rest of the step's operators
    roles_.extendForLiquid(p.size());
    for (std::size_t i = before; i < p.size(); ++i) roles_.in_liquid_system[i] = 0;
    regions_.region_of.resize(p.size(), -1);
    regions_.enclosed_particle.resize(p.size(), 0);
  }
  released_points_ = std::move(counts.released_ids);
  report_.bubble_points_made = counts.made;
  report_.bubble_points_released = counts.released;
  report_.bubble_point_wall_stops = counts.wall_stops;
  report_.bubble_points_unpaired = counts.unpaired;
  report_.bubble_points_coalesced = counts.coalesced;
}

// The points released at the surface this step leave the arrays (their gas is a surface particle's now), after the
// open boundaries' own removals (particle indices are not used again in the step).
template <int D>
void MpsSolver<D>::removeReleasedPoints() {
  if (released_points_.empty()) return;
  auto& p = state_.particles;
  std::sort(released_points_.begin(), released_points_.end());
  std::vector<char> remove(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    remove[i] = p.kind[i] == ParticleKind::Point &&
                std::binary_search(released_points_.begin(), released_points_.end(), p.id[i]);
  p.erase(remove);
  released_points_.clear();
}

// The gas of bubbles moves with the liquid around it (bubble_gas_motion.hpp; with numerics.bubble_gas_motion =
// "follow_void", on average with its void's translation), unless the key is "own_pressure" (then it keeps its
// predicted velocity and the gas system corrects it like open gas).
template <int D>
void MpsSolver<D>::moveBubbleGas(double dt) {
  using Motion = NumericsConfig::BubbleGasMotion;
  if (!bubbleGasFollowsLiquid()) return;
  const double re = constants_.re_number_density;
  // numerics.bubble_gas_wall_stop (a guard, counted): the gas does not follow the water into a wall.
  const double wall_stop =
      config_.numerics.bubble_gas_wall_stop ? config_.numerics.collision_distance * constants_.l0 : 0.0;
  const bool follow_void = config_.numerics.bubble_gas_motion == Motion::FollowVoid;
  std::vector<std::optional<Vec<D>>> translation;
  if (follow_void)
    translation = voidTranslation<D>(state_.particles, roles_, regions_.region_of, regions_.regionCount(), constants_.l0);
  report_.bubble_gas_wall_stops = extendVelocityIntoBubbles<D>(
      state_.particles, near_neighbours_, roles_, re, dt, follow_void ? &translation : nullptr,
      follow_void ? &regions_.region_of : nullptr, wall_stop);
}

#define MISTFALL_INSTANTIATE(D)                              \
  template void MpsSolver<D>::solveGasPressure(double);     \
  template void MpsSolver<D>::correctGas(double);           \
  template Vec<D> MpsSolver<D>::stabilisedGasGradient(std::size_t) const; \
  template bool MpsSolver<D>::mirroredLiquid(std::size_t) const;         \
  template void MpsSolver<D>::riseEntrainedGas(double);     \
  template void MpsSolver<D>::moveEntrainedBubbles(double); \
  template void MpsSolver<D>::removeReleasedPoints();       \
  template void MpsSolver<D>::moveBubbleGas(double);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall
