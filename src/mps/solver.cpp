#include "mps/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "mps/collision.hpp"
#include "mps/gradient.hpp"
#include "mps/laplacian.hpp"
#include "mps/number_density.hpp"
#include "mps/time_step.hpp"

namespace mistfall {

namespace {
template <int D>
Vec<D> firstComponents(const std::array<double, 3>& a) {
  Vec<D> v;
  for (int k = 0; k < D; ++k) v[k] = a[k];
  return v;
}
}  // namespace

template <int D>
MpsSolver<D>::MpsSolver(const CaseConfig& config, SimulationState<D>& state)
    : config_(config),
      state_(state),
      constants_(referenceConstants(D, config.numerics.particle_spacing, config.numerics.radius_number_density,
                                    config.numerics.radius_laplacian)),
      phases_{config.physics.liquid, config.physics.gas},
      gravity_(firstComponents<D>(config.physics.gravity)),
      domain_lower_(firstComponents<D>(config.domain.min)),
      domain_upper_(firstComponents<D>(config.domain.max)),
      search_(domain_lower_, domain_upper_, std::max(constants_.re_number_density, constants_.re_laplacian)),
      linear_solver_(makeLinearSolver(config.numerics.pressure_solver, config.numerics.solver_tolerance,
                                      config.numerics.solver_max_iterations)) {
  for (std::size_t i = 0; i < state_.particles.size(); ++i) {
    const auto k = state_.particles.kind[i];
    initial_fluid_ += (k == ParticleKind::Fluid || k == ParticleKind::Escaped);
    if (k == ParticleKind::Fluid) phase_present_[static_cast<int>(state_.particles.phase[i])] = true;
  }
}

template <int D>
double MpsSolver<D>::particleMass(std::size_t i) const {
  return phases_[static_cast<int>(state_.particles.phase[i])].density * std::pow(constants_.l0, D);
}

template <int D>
double MpsSolver<D>::maxFluidSpeed() const {
  const auto& p = state_.particles;
  double vmax = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
#pragma omp parallel for reduction(max : vmax) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (p.kind[i] == ParticleKind::Fluid) vmax = std::max(vmax, p.velocity[i].norm());
  return vmax;
}

template <int D>
const StepReport& MpsSolver<D>::step(double until) {
  const double t0 = omp_get_wtime();
  report_ = StepReport{};
  buildNeighbours();
  const double dt = chooseTimeStepFor(until);
  predict(dt);
  collide(dt);
  buildNeighbours();
  computeNumberDensity();
  const double tp = omp_get_wtime();
  solvePressure(dt);
  extrapolateDummyPressure();
  report_.seconds_pressure = omp_get_wtime() - tp;
  correct(dt);
  markEscaped();
  state_.time = (until - state_.time <= dt) ? until : state_.time + dt;
  state_.step += 1;
  state_.dt = dt;
  report_.dt = dt;
  checkHealth(dt);
  report_.seconds_total = omp_get_wtime() - t0;
  return report_;
}

template <int D>
void MpsSolver<D>::buildNeighbours() {
  search_.build(state_.particles.position, state_.particles.kind, neighbours_);
}

template <int D>
double MpsSolver<D>::chooseTimeStepFor(double until) const {
  // Viscous limit of the phases present (a case without gas is not slowed by the gas viscosity).
  double nu = 0.0;
  for (int ph = 0; ph < 2; ++ph)
    if (phase_present_[ph]) nu = std::max(nu, phases_[ph].kinematic_viscosity);
  double dt = chooseTimeStep(maxFluidSpeed(), constants_.l0, config_.numerics.courant, nu, config_.numerics.dt_max);
  const double remaining = until - state_.time;
  if (remaining < dt) {
    dt = remaining;
  } else if (remaining < 2.0 * dt) {
    dt = 0.5 * remaining;  // avoid a sliver step just before an output time
  }
  if (dt < config_.numerics.dt_min && remaining > config_.numerics.dt_min) {
    std::ostringstream msg;
    msg << "time step " << dt << " s fell below numerics.dt_min = " << config_.numerics.dt_min
        << " s (max speed " << maxFluidSpeed() << " m/s)";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
  return dt;
}

// Explicit stage: u* = u + dt (nu lap u + g), r* = r + dt u*  (viscosity by eq. (13)).
template <int D>
void MpsSolver<D>::predict(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> acceleration(n, Vec<D>::Zero());
  auto active = [&](std::int32_t j) { return isActive(p.kind[j]); };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const double nu = phases_[static_cast<int>(p.phase[i])].kinematic_viscosity;
    acceleration[i] = gravity_;
    if (nu > 0.0) acceleration[i] += nu * laplacianAt<D>(i, p.position, p.velocity, neighbours_, constants_, active);
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    p.velocity[i] += dt * acceleration[i];
    p.position[i] += dt * p.velocity[i];
  }
}

template <int D>
void MpsSolver<D>::collide(double dt) {
  if (config_.numerics.collision_distance <= 0.0) return;
  auto& p = state_.particles;
  std::vector<double> mass(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) mass[i] = particleMass(i);
  resolveCollisions<D>(p.position, p.velocity, p.kind, mass, neighbours_,
                       config_.numerics.collision_distance * constants_.l0, config_.numerics.collision_restitution, dt);
}

template <int D>
void MpsSolver<D>::computeNumberDensity() {
  auto& p = state_.particles;
  mistfall::computeNumberDensity<D>(p.position, p.kind, neighbours_, constants_.re_number_density, p.number_density);
}

// Implicit stage: assemble and solve eq. (9) (eq. (17) for a phase with finite sound speed).
template <int D>
void MpsSolver<D>::solvePressure(double dt) {
  auto& p = state_.particles;
  const auto surface = freeSurfaceFlags(p, config_.numerics.surface_threshold, constants_.n0);
  const PressureSourceTerm source{config_.numerics.pressure_source, config_.numerics.source_relaxation};
  assemblePressureSystem<D>(p, neighbours_, constants_, phases_, surface, source, dt, system_);
  const auto rows = system_.particle_of.size();
  pressure_unknowns_.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) pressure_unknowns_[r] = p.pressure[system_.particle_of[r]];
  const auto result = linear_solver_->solve(system_.matrix, system_.rhs, pressure_unknowns_);
  report_.ppe_iterations = result.iterations;
  report_.ppe_residual = result.relative_residual;
  report_.ppe_unknowns = rows;
  if (!result.converged && !(result.relative_residual <= 1e3 * config_.numerics.solver_tolerance)) {
    std::ostringstream msg;
    msg << "pressure solve (" << linear_solver_->name() << ") did not converge: relative residual "
        << result.relative_residual << " after " << result.iterations << " iterations ("
        << "numerics.solver_tolerance = " << config_.numerics.solver_tolerance << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
  std::fill(p.pressure.begin(), p.pressure.end(), 0.0);
  // Negative pressures are set to zero (standard MPS: the liquid does not sustain tension).
  for (std::size_t r = 0; r < rows; ++r) p.pressure[system_.particle_of[r]] = std::max(0.0, pressure_unknowns_[r]);
}

// Dummy particles carry no unknown, but they complete the neighbourhood of fluid next to a wall in the pressure
// gradient (without them the min-pressure term pushes that fluid into the wall). Each takes the pressure of its
// nearest wall particle, extrapolated hydrostatically: p_d = p_w + rho g . (r_d - r_w), clamped at 0.
template <int D>
void MpsSolver<D>::extrapolateDummyPressure() {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double rho = phases_[static_cast<int>(Phase::Liquid)].density;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Dummy) continue;
    double best = std::numeric_limits<double>::infinity();
    std::int32_t nearest = -1;
    for (auto s = neighbours_.begin(i); s < neighbours_.end(i); ++s) {
      const auto j = neighbours_.indices[s];
      if (p.kind[j] != ParticleKind::Wall) continue;
      const double r2 = (p.position[j] - p.position[i]).squaredNorm();
      if (r2 < best) best = r2, nearest = j;
    }
    p.pressure[i] =
        nearest < 0 ? 0.0
                    : std::max(0.0, p.pressure[nearest] + rho * gravity_.dot(p.position[i] - p.position[nearest]));
  }
}

// Correction: u' = -dt/rho grad p (minimum-neighbour form), u = u* + u', r = r* + dt u'.
template <int D>
void MpsSolver<D>::correct(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  auto solvedPressure = [&](std::int32_t j) {
    return p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Wall;
  };
  auto carriesPressure = [&](std::int32_t j) { return isActive(p.kind[j]); };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const double rho = phases_[static_cast<int>(p.phase[i])].density;
    change[i] = -dt / rho *
                gradientAt<D>(i, p.position, p.pressure, neighbours_, constants_, GradientForm::MinimumNeighbour,
                              carriesPressure, solvedPressure);
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    p.velocity[i] += change[i];
    p.position[i] += dt * change[i];
  }
}

template <int D>
void MpsSolver<D>::markEscaped() {
  auto& p = state_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const auto& x = p.position[i];
    const bool inside = (x.array() >= domain_lower_.array()).all() && (x.array() <= domain_upper_.array()).all();
    if (!inside && x.allFinite()) {
      p.kind[i] = ParticleKind::Escaped;
      p.velocity[i].setZero();
      p.pressure[i] = 0.0;
    }
  }
}

template <int D>
void MpsSolver<D>::checkHealth(double) const {
  const auto& p = state_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !std::isfinite(p.pressure[i])) {
      std::ostringstream msg;
      msg << "particle " << i << " has a non-finite position, velocity or pressure";
      throw DivergenceError(msg.str(), state_.time, state_.step);
    }
  }
  const std::size_t escaped = p.count(ParticleKind::Escaped);
  if (initial_fluid_ > 0 &&
      static_cast<double>(escaped) > config_.numerics.max_escaped_fraction * static_cast<double>(initial_fluid_)) {
    std::ostringstream msg;
    msg << escaped << " of " << initial_fluid_ << " fluid particles have left the domain (more than "
        << "numerics.max_escaped_fraction = " << config_.numerics.max_escaped_fraction << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
}

template class MpsSolver<2>;
template class MpsSolver<3>;

}  // namespace mistfall
