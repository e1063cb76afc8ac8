// The step of MpsSolver (solver.hpp): its stages in order, with a timer round each, and the stages of prediction,
// time step, neighbours, number density and the particles' order. The other stages are in solver_*.cpp.
#include "mps/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "mps/bubble_pressure.hpp"
#include "mps/collision.hpp"
#include "mps/entrained_gas_rise.hpp"
#include "mps/gradient.hpp"
#include "mps/laplacian.hpp"
#include "mps/number_density.hpp"
#include "mps/pair_loop.hpp"
#include "mps/time_step.hpp"
#include "mps/wall_mirror.hpp"

namespace mistfall {

namespace {
// The neighbour list's skin, in particle spacings (neighbour_search.hpp): the list is rebuilt when a particle has
// moved more than half of it since the last build. A larger skin means fewer builds but longer lists for every
// operator to filter.
constexpr double kNeighbourSkin = 0.5;
// Steps between two sorts of the particle arrays by place (spatial_order.hpp), besides the sort after each output
// time. waterfall.toml at 5.4-5.5 s, 1 thread: 159 ms a step unsorted, 126 sorted once at 5.4 s, 115 every 100 steps,
// 113 every 25 (a Morton order of the cells instead of rows: 126).
constexpr std::int64_t kSortInterval = 100;
// The AMG hierarchy of a pressure system preconditions the next steps' systems (linear_solver.hpp): at most this
// many, while they take at most one CG iteration more, and while at least 90 % of their unknowns are particles
// that were unknowns of the set-up system (the gas system's rows change every step: the liquid next to the gas).
constexpr PreconditionerReuse kPreconditionerReuse{8, 1, 0.9};

// Runs a pressure system's assembly and solve, `assemble_and_solve`, whose linear solves add their seconds to
// `solve_seconds` (solveLinear books them to their own stages); books the rest to `assembly` and returns the whole.
template <class AssembleAndSolve>
double timeAssembly(StageTimer& timer, Stage assembly, double& solve_seconds, AssembleAndSolve&& assemble_and_solve) {
  const double start = omp_get_wtime();
  solve_seconds = 0.0;
  assemble_and_solve();
  const double seconds = omp_get_wtime() - start;
  timer.add(assembly, seconds - solve_seconds);
  return seconds;
}

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
      search_(domain_lower_, domain_upper_, std::max(constants_.re_number_density, constants_.re_laplacian),
              kNeighbourSkin * constants_.l0),
      liquid_solver_(makeLinearSolver(config.numerics.pressure_solver, config.numerics.solver_tolerance,
                                      config.numerics.solver_max_iterations, kPreconditionerReuse)),
      gas_solver_(makeLinearSolver(config.numerics.pressure_solver, config.numerics.solver_tolerance,
                                   config.numerics.solver_max_iterations, kPreconditionerReuse)),
      full_neighbour_count_(latticeNeighbourCount(D, constants_.re_number_density, constants_.l0)) {
  // The reach of the near list: every radius its operators use (number density, gas-region links and touches,
  // collision distance, the entrained gas's 1.5 l0), at most the full list's.
  const NumericsConfig& n = config.numerics;
  near_reach_ = std::min(search_.radius(), constants_.l0 * std::max({constants_.re_number_density / constants_.l0,
                                                                     n.gas_region_link, n.dispersed_gas_touch,
                                                                     n.collision_distance, 1.5}));
  for (std::size_t i = 0; i < state_.particles.size(); ++i) {
    const auto k = state_.particles.kind[i];
    if (k == ParticleKind::Fluid) phase_present_[static_cast<int>(state_.particles.phase[i])] = true;
    if (k == ParticleKind::Point) phase_present_[static_cast<int>(Phase::Gas)] = true;
  }
  if (entrainedPoints()) {
    EntrainedBubbleModel model;
    model.diameter = n.entrained_bubble_diameter;
    model.liquid_density = config.physics.liquid.density;
    model.gas_density = config.physics.gas.density;
    model.liquid_viscosity = config.physics.liquid.kinematic_viscosity;
    model.surface_tension = config.physics.surface_tension;
    model.gravity = gravity_.norm();
    entrained_bubbles_ = std::make_unique<EntrainedBubbles<D>>(model, constants_.l0, constants_.re_number_density,
                                                               constants_.n0, gravity_);
  }
}

// Its phase's density times l0^D; with numerics.entrained_gas_inertia = "liquid" the water's for gas below a bubble's
// resolution, which the step moves as liquid (phase_coupling.hpp), so that it meets the water with the water's inertia;
// with `bubble_gas_as_liquid` (numerics.bubble_gas_inertia = "liquid") the water's for a bubble's gas too.
template <int D>
double MpsSolver<D>::particleMass(std::size_t i, bool bubble_gas_as_liquid) const {
  const bool moves_as_liquid = (config_.numerics.entrained_gas_liquid_inertia && isEntrainedBelowResolution(i)) ||
                               (bubble_gas_as_liquid && roles_.enclosed_gas[i]);
  const Phase phase = moves_as_liquid ? Phase::Liquid : state_.particles.phase[i];
  return phases_[static_cast<int>(phase)].density * std::pow(constants_.l0, D);
}

template <int D>
const StepReport& MpsSolver<D>::step(double until) {
  const double t0 = omp_get_wtime();
  report_ = StepReport{};
  if (reorder_pending_ || state_.step % kSortInterval == 0) sortParticlesBySpace();
  holdVentStart();  // the vents' particles at the step's start (gas_vent.hpp)
  buildNeighbours();
  // Gas regions and bubbles (the flag delta_gl of eq. (7)), and which particle belongs to which pressure system.
  {
    auto t = timer_.scope(Stage::GasRegions);
    findBubbles();
  }
  double dt = 0.0;
  {
    auto t = timer_.scope(Stage::TimeStep);
    dt = chooseTimeStepFor(until);
  }
  // The explicit step of eqs. (1)-(4): viscosity and gravity give u*, r*.
  {
    auto t = timer_.scope(Stage::Predict);
    predict(dt);
  }
  trace("predict");
  {
    auto t = timer_.scope(Stage::Collision);
    collide(dt);
  }
  trace("collision");
  {
    auto t = timer_.scope(Stage::OpenBoundaries);
    admitInflow(dt);
  }
  buildNeighbours();
  // The liquid system, eqs. (5), (7): liquid, walls and one pressure per bubble.
  {
    auto t = timer_.scope(Stage::NumberDensity);
    computeLiquidNumberDensity();
  }
  solveLiquidSystem(dt);  // its assembly and solve, each timed
  {
    auto t = timer_.scope(Stage::LiquidCorrection);
    correctLiquidSystem(dt);
  }
  trace("liquid correction");
  {
    auto t = timer_.scope(Stage::Collision);
    collideCorrectedLiquid(dt);
  }
  trace("liquid collision");
  if (config_.numerics.scheme == Scheme::Stabilised) {  // particle_shifting.hpp
    auto t = timer_.scope(Stage::Shifting);
    shiftParticles(dt);
    trace("shifting");
  }
  if (roles_.enclosed_count > 0) {
    auto t = timer_.scope(Stage::BubbleGas);
    moveBubbleGas(dt);
    trace("bubble gas motion");
  }
  // The gas system, eqs. (6), (8), (17): all gas, the moved liquid as its walls.
  if (roles_.gas_count > 0 && !oneEquation()) solveGasSystem(dt);  // its stages, each timed and traced
  if (entrainedPoints()) {  // eq. (18) for the sub-particle bubbles, their reaction on the water (eq. (7))
    auto t = timer_.scope(Stage::GasCorrection);
    moveEntrainedBubbles(dt);
    trace("entrained bubbles");
  }
  {
    auto t = timer_.scope(Stage::OpenBoundaries);
    ventAndRemove(dt);
  }
  trace("open boundaries");
  advanceClock(until, dt);
  {
    auto t = timer_.scope(Stage::Health);
    checkHealth(dt);
  }
  report_.seconds_total = omp_get_wtime() - t0;
  return report_;
}

// The liquid system's assembly and solve: the pressure of the liquid and the bubbles (or, one_equation, of both
// phases), with the wall and dummy pressures left to the correction.
template <int D>
void MpsSolver<D>::solveLiquidSystem(double dt) {
  report_.seconds_pressure = timeAssembly(timer_, Stage::LiquidAssembly, solve_seconds_, [&] {
    if (oneEquation())
      solveOneEquationPressure(dt);
    else
      solveLiquidPressure(dt);
  });
}

// The wall and dummy pressures, then -dt/rho grad p (eq. (7)).
template <int D>
void MpsSolver<D>::correctLiquidSystem(double dt) {
  setLiquidWallPressure();
  if (oneEquation())
    correctOneEquation(dt);
  else
    correctLiquid(dt);
}

// The gas system, eqs. (6), (8), (17): its n*, rows and solve, the gas's correction and the guards after it, and the
// entrained gas's rise.
template <int D>
void MpsSolver<D>::solveGasSystem(double dt) {
  buildNeighbours();
  report_.seconds_pressure += timeAssembly(timer_, Stage::GasAssembly, solve_seconds_, [&] { solveGasPressure(dt); });
  auto t = timer_.scope(Stage::GasCorrection);
  correctGas(dt);
  trace("gas correction");
  collideCorrectedGas(dt);
  trace("gas collision");
  riseEntrainedGas(dt);
  trace("entrained gas rise");
}

// The step's end: the clock moves on by dt, or to `until` when dt reaches it.
template <int D>
void MpsSolver<D>::advanceClock(double until, double dt) {
  const bool reached = until - state_.time <= dt;
  state_.time = reached ? until : state_.time + dt;
  // An output time, where a checkpoint may be written: a run resumed from it starts without what the solver keeps
  // from step to step beyond the state, so the unbroken run drops it here too (bit-identical resume).
  if (reached) forgetReusedState();
  state_.step += 1;
  state_.dt = dt;
  report_.dt = dt;
}

template <int D>
const NeighbourList& MpsSolver<D>::currentNeighbours() {
  buildNeighbours();
  return neighbours_;
}

template <int D>
void MpsSolver<D>::traceParticle(std::uint64_t id, double from, const std::string& path) {
  trace_ = std::make_unique<ParticleTrace<D>>(id, from, constants_.l0, path);
  if (!trace_->open()) throw std::runtime_error("cannot write the trace file " + path);
}

template <int D>
void MpsSolver<D>::traceStage(const char* stage) {
  const auto& roles = roles_;
  trace_->record(state_.time, state_.step, stage, state_.particles, gas_pressure_, constants_.l0,
                 [&](std::size_t i) { return i < roles.open_gas.size() && roles.inGasSystem(i); });
}

// The neighbourhood tests of a fluid particle (walls always pass), on the neighbours within re with counts[j]:
// numerics.surface_neighbour_fraction, at least that fraction of a full lattice's neighbours; and
// numerics.surface_asymmetry, |sum_j w_ij r_ij / |r_ij|| at most that fraction of n0 (a particle inside the fluid
// has its neighbours on all sides, one missing neighbour at 2 l0 moves the sum by 0.008 n0; the top row of a flat
// surface reads 0.28 n0).
template <int D>
bool MpsSolver<D>::hasFullNeighbourhood(std::size_t i, const std::vector<char>& counts) const {
  const double fraction = config_.numerics.surface_neighbour_fraction;
  const double asymmetry = config_.numerics.surface_asymmetry;
  const auto& p = state_.particles;
  if ((fraction <= 0.0 && asymmetry <= 0.0) || p.kind[i] != ParticleKind::Fluid) return true;
  auto counted = [&](std::int32_t j) { return counts[j] != 0; };
  const double re = constants_.re_number_density;
  if (fraction > 0.0 &&
      neighbourCountAt<D>(i, p.position, near_neighbours_, re, counted) < fraction * full_neighbour_count_)
    return false;
  if (asymmetry <= 0.0) return true;
  Vec<D> lopsided = Vec<D>::Zero();
  forEachPairWithin<D>(i, p.position, near_neighbours_, re, counted, [&](std::int32_t, const Vec<D>& rij, double r2,
                                                                         double w) { lopsided += (w / std::sqrt(r2)) * rij; });
  return lopsided.norm() <= asymmetry * constants_.n0;
}

// The neighbour list for the current positions: the last one while it still covers them (neighbour_search.hpp:
// the results are the same, bit for bit, as with a fresh list), else a new one.
template <int D>
void MpsSolver<D>::buildNeighbours() {
  auto t = timer_.scope(Stage::Neighbours);
  const auto& p = state_.particles;
  // A list is made anew only when the last one no longer covers the particles and cannot be carried over the
  // particles an open boundary removed or made since (neighbour_search.hpp).
  if (!search_.covers(p.position, p.kind) && !search_.carryOver(p.position, p.kind, p.id, neighbours_))
    search_.build(p.position, p.kind, p.id, neighbours_);
  if (near_built_ != search_.builds()) {
    filterNeighbours<D>(search_.builtPositions(), neighbours_, near_reach_ + search_.skin(), near_neighbours_);
    near_built_ = search_.builds();
  }
}

template <int D>
double MpsSolver<D>::chooseTimeStepFor(double until) {
  // Viscous limit of the phases present (a case without gas is not slowed by the gas viscosity).
  double nu = 0.0;
  for (int ph = 0; ph < 2; ++ph)
    if (phase_present_[ph]) nu = std::max(nu, phases_[ph].kinematic_viscosity);
  const FluidSpeeds speeds = fluidSpeeds();
  const double liquid_speed = speeds.liquid, gas_speed = speeds.gas;
  double dt = chooseTimeStep(std::max(liquid_speed, gas_speed), constants_.l0, config_.numerics.courant, nu,
                             config_.numerics.dt_max);
  // What set it (issue 17, item 4): the step the liquid alone would allow, and whether a gas particle's Courant
  // limit was the binding one.
  report_.liquid_dt = chooseTimeStep(liquid_speed, constants_.l0, config_.numerics.courant, nu, config_.numerics.dt_max);
  report_.dt_set_by_gas = dt < report_.liquid_dt;
  const double remaining = until - state_.time;
  if (remaining < dt) {
    dt = remaining;
  } else if (remaining < 2.0 * dt) {
    dt = 0.5 * remaining;  // avoid a sliver step just before an output time
  }
  recordStep(dt, speeds.fastest);
  if (dt < config_.numerics.dt_min && remaining > config_.numerics.dt_min) {
    std::ostringstream msg;
    msg << "time step " << dt << " s fell below numerics.dt_min = " << config_.numerics.dt_min
        << " s (max speed " << maxFluidSpeed() << " m/s: " << fastestParticle() << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
  return dt;
}

// Explicit stage: u* = u + dt (nu lap u + g), r* = r + dt u*  (viscosity by eq. (13)).
template <int D>
void MpsSolver<D>::predict(double dt) {
  auto& p = state_.particles;
  if (entrainedPoints()) start_velocity_ = p.velocity;  // the water's material acceleration over the step
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> acceleration(n, Vec<D>::Zero());
  // The liquid's viscous term ignores the gas; the gas sees liquid and walls as walls moving with their velocity.
  auto active = [&](std::int32_t j) { return isActive(p.kind[j]); };
  auto notGas = [&](std::int32_t j) { return isActive(p.kind[j]) && !isGas(p.kind[j], p.phase[j]); };
  // A bubble's gas that follows the liquid (bubble_gas_motion not "own_pressure") takes its velocity from the
  // extension (bubble_gas_motion.hpp) and feels no pressure of its own, so it must feel no gravity either: the
  // extension's sweeps start from the gas's own velocity, and an interior that kept g dt each step sank the bubble.
  const bool gas_follows = bubbleGasFollowsLiquid();
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid || (gas_follows && roles_.enclosed_gas[i])) continue;
    const double nu = phases_[static_cast<int>(p.phase[i])].kinematic_viscosity;
    acceleration[i] = gravity_;
    if (nu <= 0.0) continue;
    if (p.phase[i] == Phase::Gas)
      acceleration[i] += nu * laplacianAt<D>(i, p.position, p.velocity, neighbours_, constants_, active);
    else
      acceleration[i] += nu * laplacianAt<D>(i, p.position, p.velocity, neighbours_, constants_, notGas);
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    p.velocity[i] += dt * acceleration[i];
    p.position[i] += dt * p.velocity[i];
  }
}

// The walls' and dummies' pressure in the liquid system: paper scheme, extrapolated from the nearest wall particle
// (they take part in the next correction); stabilised scheme, the mirrored wall pressure averaged over the fluid
// around each (wall_mirror.hpp; output and wall loads only: the correction mirrors the fluid's own pressure).
template <int D>
void MpsSolver<D>::setLiquidWallPressure() {
  auto& p = state_.particles;
  const double rho = phases_[static_cast<int>(Phase::Liquid)].density;
  if (config_.numerics.scheme == Scheme::Paper) {
    extrapolateDummyPressure(p.pressure, rho);
    return;
  }
  const auto& in_system = roles_.in_liquid_system;
  auto liquid = [&](std::int32_t j) {
    return in_system[j] && (p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Inflow);
  };
  // Each fluid neighbour continues its own pressure with its own density (one density without one_equation).
  auto density = [&](std::int32_t j) { return oneEquation() ? problem_.density_of[j] : rho; };
  averageMirroredWallPressure<D>(p.position, p.kind, p.pressure, near_neighbours_, constants_.re_number_density,
                                 density, gravity_, liquid);
}

// The particle arrays in the order of their cells (spatial_order.hpp), at the first step after construction and
// after each output time, and every kSortInterval steps: a function of the state (its step count) only, so a resumed
// run sorts as the unbroken one did. The neighbour list is made anew for the new indices; the kept AMG hierarchies
// follow their rows by particle id.
template <int D>
void MpsSolver<D>::sortParticlesBySpace() {
  auto t = timer_.scope(Stage::Neighbours);
  auto& p = state_.particles;
  std::vector<std::int64_t> key(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) key[i] = search_.cellKey(p.position[i]);
  p.reorder(orderByKey(key));
  search_.build(p.position, p.kind, p.id, neighbours_);
  reorder_pending_ = false;
}

template class MpsSolver<2>;
template class MpsSolver<3>;

}  // namespace mistfall
