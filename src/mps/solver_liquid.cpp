// The liquid's pressure system and correction, eqs. (5), (7), (9) (the step's stages `computeLiquidNumberDensity`,
// `solveLiquidPressure`, `extrapolateDummyPressure`, `correctLiquid` of MpsSolver, solver.hpp): liquid and walls
// carry unknowns, each bubble one merged unknown (bubble_pressure.hpp); open gas is invisible to the liquid.
// numerics.scheme = "stabilised" changes the walls, the gradient and the known terms of the rows
// (solver_liquid_stabilised.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "mps/bubble_cavity.hpp"
#include "mps/bubble_pressure.hpp"
#include "mps/gradient.hpp"
#include "mps/inflow_pressure.hpp"
#include "mps/interface_curvature.hpp"
#include "mps/number_density.hpp"
#include "mps/solver.hpp"
#include "mps/wall_mirror.hpp"

namespace mistfall {

// n* of the liquid system: open gas does not count (the liquid next to it is a free surface).
template <int D>
void MpsSolver<D>::computeLiquidNumberDensity() {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  p.number_density.resize(n);
  const auto& in_system = roles_.in_liquid_system;
  auto counts = [&](std::int32_t j) { return in_system[j] != 0; };
  const double re = constants_.re_number_density;
  // by volume, the bubbles' gas rows first: the other rows read their n* (countBubbleGasByVolume)
  const bool by_volume = config_.numerics.bubble_gas_counts_by_volume;
  const auto& bubble_gas = roles_.enclosed_gas;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    p.number_density[i] = in_system[i] && (!by_volume || bubble_gas[i])
                              ? numberDensityAt<D>(i, p.position, near_neighbours_, re, counts)
                              : 0.0;
  if (by_volume) countBubbleGasByVolume();
}

// numerics.bubble_gas_in_water_density = "volume": the rows outside the bubbles count each bubble gas particle j by
// the volume it stands for, V_j / l0^D = n0 / n_j (n_j its own n* above), as the volume-weighted number density
// sum_j w_ij V_j / l0^D does, instead of as one particle. A bubble squeezed below its spacing packs more particles
// round the water beside it than the water's share of the space holds; counted whole, they raised the water's n*
// to 1.35-4.2 n0 and its pressure to 37-179 kPa above the bubble's (docs/waterfall.md, fifty-first session). The
// bubbles' own rows (their merged unknown's volume, eq. (17)) keep the particle count: computed before, they are read
// here and not written, so the loop reads them in place.
template <int D>
void MpsSolver<D>::countBubbleGasByVolume() {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const auto& in_system = roles_.in_liquid_system;
  const auto& bubble_gas = roles_.enclosed_gas;
  const std::vector<double>& own = p.number_density;
  const double n0 = constants_.n0;
  auto counts = [&](std::int32_t j) { return in_system[j] != 0; };
  auto volume = [&](std::int32_t j) { return bubble_gas[j] && own[j] > 0.0 ? n0 / own[j] : 1.0; };
  const double re = constants_.re_number_density;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (in_system[i] && !bubble_gas[i])
      p.number_density[i] = volumeWeightedNumberDensityAt<D>(i, p.position, near_neighbours_, re, counts, volume);
}

// The liquid system: eq. (9) for liquid and walls (one density), with one unknown per bubble (bubble_pressure.hpp):
// enclosed gas holds its bubble's pressure P_B and pushes on the liquid with it (the force of eq. (7)).
template <int D>
void MpsSolver<D>::solveLiquidPressure(double dt) {
  auto& p = state_.particles;
  const std::size_t n = p.size();
  const double beta_n0 = config_.numerics.surface_threshold * constants_.n0;
  const PhaseProperties& liquid = phases_[static_cast<int>(Phase::Liquid)];
  const PhaseProperties& gas = phases_[static_cast<int>(Phase::Gas)];
  problem_.takes_part.assign(n, 0);
  problem_.unknown.assign(n, 0);
  problem_.carries_velocity = roles_.in_liquid_system;
  problem_.density = liquid.density;
  problem_.sound_speed.assign(n, liquid.sound_speed);
  const bool stabilised = config_.numerics.scheme == Scheme::Stabilised;
  problem_.extra_rhs.clear();
  // One group (merged unknown) per bubble, numbered in region order; its initial guess is the bubble's pressure
  // from the last step (its particles all hold it).
  std::vector<std::int32_t> group_of(n, -1), group_of_region(regions_.regionCount(), -1);
  std::vector<double> group_shift, group_guess, group_reference;
  // eq. (17)'s shift on a bubble's row; none on a fresh run's first step with the memory term
  // (numerics.bubble_start_at_water_pressure): the bubble starts at the water's pressure, which the memory keeps
  const bool bubble_memory = config_.numerics.gas_pressure_memory_bubbles;
  const bool start_at_water_pressure =
      state_.step == 0 && bubble_memory && config_.numerics.bubble_start_at_water_pressure;
  auto& references = state_.gas_reference_pressure;
  const double bubble_shift = std::isfinite(gas.sound_speed) && !start_at_water_pressure
                                  ? liquid.density / (gas.density * dt * dt * gas.sound_speed * gas.sound_speed)
                                  : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = p.kind[i];
    problem_.takes_part[i] = roles_.in_liquid_system[i] && hasPressureUnknown(k) && !(stabilised && isMirroredWall(k));
    if (roles_.enclosed_gas[i]) {
      problem_.unknown[i] = 1;
      problem_.sound_speed[i] = std::numeric_limits<double>::infinity();
      auto& group = group_of_region[regions_.region_of[i]];
      if (group < 0) {
        group = static_cast<std::int32_t>(group_shift.size());
        group_shift.push_back(0.0);
        group_guess.push_back(p.pressure[i]);
        group_reference.push_back(0.0);
      }
      group_of[i] = group;
      group_shift[group] += bubble_shift;
      if (const auto r = references.find(p.id[i]); r != references.end())
        group_reference[group] += bubble_shift * r->second;
    } else {
      const bool dense = problem_.takes_part[i] && p.number_density[i] >= beta_n0;
      problem_.unknown[i] = dense && hasFullNeighbourhood(i, roles_.in_liquid_system);
      if (dense && !problem_.unknown[i]) ++report_.neighbour_surfaces;
      // out of its bubble, the gas is at its spacing at the ambient pressure
      if (!references.empty() && p.phase[i] == Phase::Gas) references.erase(p.id[i]);
    }
  }
  problem_.sourceless = harmonicInflowRows<D>(p, config_);  // [[inflow]] pressure = "harmonic"
  // numerics.bubble_cavity = "joined" (bubble_cavity.hpp): the water bordering a bubble's cavity joins its unknown
  // (incompressible, as its gas's rows), keeping its divergence; the cavity's area counts in the density term below
  std::vector<double> cavity_area(group_shift.size(), 0.0);
  std::vector<std::int32_t> cavity_edge;
  if (config_.numerics.bubble_cavity_joined)
    for (std::size_t g = 0; g < group_shift.size(); ++g) {
      auto inBubble = [&](std::size_t i) { return group_of[i] == static_cast<std::int32_t>(g) && p.phase[i] == Phase::Gas; };
      const BubbleCavity cavity = findBubbleCavity<D>(p, inBubble, constants_.l0);
      if (cavity.open) continue;
      cavity_area[g] = cavity.area;
      for (const auto k : cavity.edge) {
        if (!problem_.takes_part[k]) continue;
        problem_.unknown[k] = 1;
        problem_.sound_speed[k] = std::numeric_limits<double>::infinity();
        group_of[k] = static_cast<std::int32_t>(g);
        cavity_edge.push_back(k);
      }
    }
  // numerics.bubble_divergence = "whole_bubble": a bubble's rows count its gas's velocity too (pressure_poisson.hpp)
  if (config_.numerics.bubble_divergence_whole)
    problem_.velocity_group = group_of;
  else
    problem_.velocity_group.clear();
  if (stabilised) stabilisedPressureTerms(dt);
  const PressureSourceTerm source = sourceTermFor(config_.numerics, dt);  // pressure_poisson.hpp
  // the cavity's edge water: its number density is short by the cavity, which its bubble's row counts as area
  if (!cavity_edge.empty()) {
    if (problem_.extra_rhs.empty()) problem_.extra_rhs.assign(n, 0.0);
    for (const auto k : cavity_edge)
      problem_.extra_rhs[k] -= source.relaxation * liquid.density / (dt * dt) *
                               (p.number_density[k] - constants_.n0) / constants_.n0;
  }
  assemblePressureSystem<D>(p, p.number_density, neighbours_, constants_, problem_, source, dt, system_,
                            &near_neighbours_);
  applyLaplaceJump(group_of);
  lumpPressureGroups(system_, group_of, group_shift, lumped_);
  for (std::size_t g = 0; g < cavity_area.size(); ++g)  // the cavity as gas expanded by A_c / l0^2 cells
    lumped_.rhs[lumped_.first_group_row + static_cast<std::int64_t>(g)] -=
        source.relaxation * liquid.density / (dt * dt) * cavity_area[g] / (constants_.l0 * constants_.l0);
  // eq. (17)'s memory on each bubble's row (pressure_poisson.hpp): its shift times its pressure of the last step;
  // the density-drift term's share gamma of the shift times the gas's reference pressure, so that the row settles at
  // P_0 + rho_g c^2 delta, not at rho_g c^2 delta, for gas whose spacing is that of P_0 (bubble_initial_pressure)
  if (bubble_memory && std::isfinite(gas.sound_speed) && source.kind == PressureSource::Mixed)
    for (std::size_t g = 0; g < group_shift.size(); ++g)
      lumped_.rhs[lumped_.first_group_row + static_cast<std::int64_t>(g)] +=
          (1.0 - source.relaxation) * group_shift[g] * group_guess[g] + source.relaxation * group_reference[g];
  Eigen::VectorXd x = Eigen::VectorXd::Zero(lumped_.matrix.rows());
  for (std::size_t r = 0; r < system_.particle_of.size(); ++r) {
    const auto i = system_.particle_of[r];
    x[lumped_.column_of_row[r]] = group_of[i] >= 0 ? group_guess[group_of[i]] : p.pressure[i];
  }
  solveLinear(lumped_.matrix, lumped_.rhs, x, "liquid", report_.ppe_iterations);
  report_.ppe_unknowns = lumped_.matrix.rows();
  // Negative liquid pressures are set to zero (standard MPS: the liquid does not sustain tension); a bubble keeps
  // its pressure (below zero it is larger than at rest and pulls the liquid in).
  for (std::size_t i = 0; i < n; ++i)
    if (roles_.in_liquid_system[i]) p.pressure[i] = 0.0;
  for (std::size_t r = 0; r < system_.particle_of.size(); ++r) {
    const auto i = system_.particle_of[r];
    const double value = x[lumped_.column_of_row[r]];
    p.pressure[i] = group_of[i] >= 0 ? value : std::max(0.0, value);
  }
  if (start_at_water_pressure)  // the first step's bubbles are their gas at its spacing at the pressure found
    for (std::size_t i = 0; i < n; ++i)
      if (group_of[i] >= 0) references[p.id[i]] = p.pressure[i];
  if (!surface_pressure_.empty())
    for (std::size_t i = 0; i < n; ++i)
      if (surface_pressure_[i] != 0.0) p.pressure[i] = surface_pressure_[i];
}

// numerics.bubble_surface_tension = "jump": the water sees a bubble's interface gas at P_B + s_i, s_i = -sigma kappa_i
// (Young-Laplace, kappa from interface_curvature.hpp). With p = T P + s, s known, the system A p = b becomes
//   T^T A T P = T^T (b - A s),
// so the jump enters the right-hand side before the merge (bubble_pressure.hpp), and the bubble's row still sums its
// particles' rows. Built on the paper scheme (the case reader refuses the stabilised one, whose gradient does not read
// interface_jump_). A uniform s would only shift P_B; the jump moves the water where kappa varies along the interface.
template <int D>
void MpsSolver<D>::applyLaplaceJump(const std::vector<std::int32_t>& group_of) {
  interface_jump_.clear();
  if (!config_.numerics.bubble_surface_tension) return;
  auto& p = state_.particles;
  const std::size_t n = p.size();
  auto bubbleOf = [&](std::int32_t j) { return p.phase[j] == Phase::Gas ? group_of[j] : -1; };
  auto liquid = [&](std::int32_t j) { return p.kind[j] == ParticleKind::Fluid && p.phase[j] == Phase::Liquid; };
  const InterfaceCurvature curvature = interfaceCurvature<D>(
      p.position, near_neighbours_, constants_.l0, constants_.re_number_density,
      config_.numerics.surface_tension_fit_radius * constants_.l0, bubbleOf, liquid);
  report_.curvature_unfitted = curvature.unfitted;
  interface_jump_.assign(n, 0.0);
  Eigen::VectorXd jump = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(system_.particle_of.size()));
  // Gas deeper than the interface's particles meets the water too (within the Laplacian's radius): it takes the
  // curvature of its nearest interface particle, so that every pair of gas and water carries the jump (with the
  // interface particles alone, a weightless bubble held 0.54 sigma / R).
  const double reach2 = constants_.re_laplacian * constants_.re_laplacian;
  for (std::size_t r = 0; r < system_.particle_of.size(); ++r) {
    const auto i = system_.particle_of[r];
    const std::int32_t bubble = bubbleOf(static_cast<std::int32_t>(i));
    if (bubble < 0) continue;
    double kappa = curvature.kappa[i];
    if (!curvature.on_interface[i]) {
      double nearest = reach2;
      for (auto s = neighbours_.begin(i); s < neighbours_.end(i); ++s) {
        const auto j = neighbours_.indices[s];
        if (!curvature.on_interface[j] || bubbleOf(j) != bubble) continue;
        const double d2 = (p.position[j] - p.position[i]).squaredNorm();
        if (d2 < nearest) nearest = d2, kappa = curvature.kappa[j];
      }
    }
    interface_jump_[i] = -config_.physics.surface_tension * kappa;
    jump[static_cast<Eigen::Index>(r)] = interface_jump_[i];
  }
  system_.rhs -= system_.matrix * jump;
}

// Dummy particles carry no unknown, but they complete the neighbourhood of fluid next to a wall in the pressure
// gradient (without them the min-pressure term pushes that fluid into the wall). Each takes the pressure of its
// nearest wall particle, extrapolated hydrostatically: p_d = p_w + rho g . (r_d - r_w), clamped at 0 when `clamp`
// (gas in a closed box may be below the ambient: numerics.gas_domain).
template <int D>
void MpsSolver<D>::extrapolateDummyPressure(std::vector<double>& pressure, double rho, bool clamp) const {
  const auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double reach2 = search_.radius() * search_.radius();
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Dummy) continue;
    double best = std::numeric_limits<double>::infinity();
    std::int32_t nearest = -1;
    for (auto s = neighbours_.begin(i); s < neighbours_.end(i); ++s) {
      const auto j = neighbours_.indices[s];
      if (p.kind[j] != ParticleKind::Wall) continue;
      const double r2 = (p.position[j] - p.position[i]).squaredNorm();
      if (r2 < best && r2 < reach2) best = r2, nearest = j;  // within the search radius (the list has a skin)
    }
    const double extrapolated =
        nearest < 0 ? 0.0 : pressure[nearest] + rho * gravity_.dot(p.position[i] - p.position[nearest]);
    pressure[i] = clamp ? std::max(0.0, extrapolated) : extrapolated;
  }
}

// Correction of the liquid: u' = -dt (1/rho_l) <grad p> (gradient.hpp, minimum-pressure form), u = u* + u', r = r* + dt u'.
// Enclosed gas pushes with its bubble's pressure but is moved by the gas system.
template <int D>
void MpsSolver<D>::correctLiquid(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double rho = phases_[static_cast<int>(Phase::Liquid)].density;
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  const auto& in_system = roles_.in_liquid_system;
  auto solvedPressure = [&](std::int32_t j) {
    return in_system[j] && hasPressureUnknown(p.kind[j]);
  };
  auto carriesPressure = [&](std::int32_t j) { return in_system[j] != 0; };
  const bool stabilised = config_.numerics.scheme == Scheme::Stabilised;
  // the water sees a bubble's interface gas at P_B - sigma kappa (applyLaplaceJump)
  std::vector<double> jumped;
  if (!interface_jump_.empty()) {
    jumped = p.pressure;
    for (std::int64_t i = 0; i < n; ++i) jumped[i] += interface_jump_[i];
  }
  const std::vector<double>& seen = interface_jump_.empty() ? p.pressure : jumped;
  std::size_t fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid || !in_system[i] || roles_.enclosed_gas[i]) continue;
    if (stabilised) {
      const auto gradient = stabilisedGradient(i, true);
      fallbacks += gradient.fell_back;
      change[i] = -dt / rho * gradient.value;
      continue;
    }
    change[i] = -dt / rho * gradientAt<D>(i, p.position, seen, near_neighbours_, constants_,
                                          GradientForm::MinimumNeighbour, carriesPressure, solvedPressure);
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid || !in_system[i] || roles_.enclosed_gas[i]) continue;
    p.velocity[i] += change[i];
    p.position[i] += dt * change[i];
  }
  report_.gradient_fallbacks = fallbacks;
}

#define MISTFALL_INSTANTIATE(D)                                                                   \
  template void MpsSolver<D>::computeLiquidNumberDensity();                                      \
  template void MpsSolver<D>::solveLiquidPressure(double);                                       \
  template void MpsSolver<D>::extrapolateDummyPressure(std::vector<double>&, double, bool) const; \
  template void MpsSolver<D>::correctLiquid(double);                                             \
  template void MpsSolver<D>::applyLaplaceJump(const std::vector<std::int32_t>&);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall
