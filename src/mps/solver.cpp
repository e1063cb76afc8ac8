#include "mps/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>
#include <string_view>

#include "mps/bubble_gas_motion.hpp"
#include "mps/bubble_pressure.hpp"
#include "mps/collision.hpp"
#include "mps/entrained_gas_rise.hpp"
#include "mps/gas_vent.hpp"
#include "mps/gradient.hpp"
#include "mps/laplacian.hpp"
#include "mps/number_density.hpp"
#include "mps/open_boundaries.hpp"
#include "mps/pair_loop.hpp"
#include "mps/time_step.hpp"
#include "mps/wall_mirror.hpp"

namespace mistfall {

namespace {
// The neighbour list's skin, in particle spacings (neighbor_search.hpp): the list is rebuilt when a particle has
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

template <int D>
double MpsSolver<D>::particleMass(std::size_t i) const {
  return phases_[static_cast<int>(state_.particles.phase[i])].density * std::pow(constants_.l0, D);
}

template <int D>
double MpsSolver<D>::maxFluidSpeed() const {
  const auto [liquid, gas] = maxPhaseSpeeds();
  return std::max(liquid, gas);
}

template <int D>
const char* MpsSolver<D>::roleOf(std::size_t i) const {
  const auto& p = state_.particles;
  return p.phase[i] != Phase::Gas ? "liquid" : (p.enclosed[i] ? "bubble gas" : "open gas");
}

// Which particle is the fastest, for a divergence's message: its id, role and place.
template <int D>
std::string MpsSolver<D>::fastestParticle() const {
  const auto& p = state_.particles;
  const std::size_t fastest = fluidSpeeds().fastest;
  if (fastest == p.size()) return "no fluid particle";
  std::ostringstream out;
  out << "particle id " << p.id[fastest] << ", " << roleOf(fastest) << ", at (";
  for (int d = 0; d < D; ++d) out << (d ? ", " : "") << p.position[fastest][d];
  out << ") m, pressure " << p.pressure[fastest] << " Pa";
  return out.str();
}

// The step about to be taken, for recentStepsCsv: its dt and the fastest fluid particle now.
template <int D>
void MpsSolver<D>::recordStep(double dt, std::size_t fastest) {
  const auto& p = state_.particles;
  RecentStep r;
  r.time = state_.time;
  r.step = state_.step;
  r.dt = dt;
  if (const std::size_t i = fastest; i < p.size()) {
    r.id = p.id[i];
    r.role = roleOf(i);
    r.position = p.position[i];
    r.speed = p.velocity[i].norm();
    r.pressure = p.pressure[i];
  }
  if (recent_steps_.size() == kRecentSteps) recent_steps_.pop_front();
  recent_steps_.push_back(r);
}

template <int D>
std::string MpsSolver<D>::recentStepsCsv() const {
  std::ostringstream out;
  out << std::setprecision(9) << "time,step,dt,id,role";
  for (int d = 0; d < D; ++d) out << "," << "xyz"[d];
  out << ",speed,pressure\n";
  for (const RecentStep& r : recent_steps_) {
    out << r.time << "," << r.step << "," << r.dt << "," << r.id << "," << r.role;
    for (int d = 0; d < D; ++d) out << "," << r.position[d];
    out << "," << r.speed << "," << r.pressure << "\n";
  }
  return out.str();
}

template <int D>
std::pair<double, double> MpsSolver<D>::maxPhaseSpeeds() const {
  const FluidSpeeds s = fluidSpeeds();
  return {s.liquid, s.gas};
}

// Each thread keeps its own fastest of each phase and its fastest particle; they are merged in thread order, and the
// first index wins a tie, so the answer does not depend on the number of threads.
template <int D>
typename MpsSolver<D>::FluidSpeeds MpsSolver<D>::fluidSpeeds() const {
  const auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  FluidSpeeds all;
  all.fastest = p.size();
  double top = -1.0;
#pragma omp parallel
  {
    FluidSpeeds mine;
    mine.fastest = p.size();
    double my_top = -1.0;
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < n; ++i) {
      if (p.kind[i] != ParticleKind::Fluid) continue;
      const double speed = p.velocity[i].norm();
      double& phase_top = p.phase[i] == Phase::Gas ? mine.gas : mine.liquid;
      phase_top = std::max(phase_top, speed);
      if (speed > my_top) my_top = speed, mine.fastest = static_cast<std::size_t>(i);
    }
#pragma omp critical(mistfall_fluid_speeds)
    {
      all.liquid = std::max(all.liquid, mine.liquid);
      all.gas = std::max(all.gas, mine.gas);
      if (my_top > top || (my_top == top && mine.fastest < all.fastest)) top = my_top, all.fastest = mine.fastest;
    }
  }
  return all;
}

template <int D>
const StepReport& MpsSolver<D>::step(double until) {
  const double t0 = omp_get_wtime();
  report_ = StepReport{};
  if (reorder_pending_ || state_.step % kSortInterval == 0) sortParticlesBySpace();
  if (!config_.vents.empty()) {  // the vents' particles now (gas_vent.hpp)
    vent_at_start_ = ventOf<D>(state_.particles, config_);
    vent_start_position_ = state_.particles.position;
  }
  buildNeighbours();
  {
    auto t = timer_.scope(Stage::GasRegions);
    findBubbles();
  }
  double dt = 0.0;
  {
    auto t = timer_.scope(Stage::TimeStep);
    dt = chooseTimeStepFor(until);
  }
  if (entrainedPoints()) start_velocity_ = state_.particles.velocity;
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
    report_.created = advanceInflows<D>(state_.particles, config_, dt);  // open_boundaries.hpp
    state_.created += report_.created;
    if (report_.created > 0) {  // the new water belongs to the liquid system and to no gas region
      const std::size_t n = state_.particles.size();
      roles_.extendForLiquid(n);
      regions_.region_of.resize(n, -1);
      regions_.enclosed_particle.resize(n, 0);
    }
  }
  buildNeighbours();
  // The liquid system, eqs. (5), (7): liquid, walls and one pressure per bubble.
  {
    auto t = timer_.scope(Stage::NumberDensity);
    computeLiquidNumberDensity();
  }
  double tp = omp_get_wtime();
  solve_seconds_ = 0.0;
  if (oneEquation())
    solveOneEquationPressure(dt);
  else
    solveLiquidPressure(dt);  // assembly, then the solve (timed in solveLinear)
  timer_.add(Stage::LiquidAssembly, omp_get_wtime() - tp - solve_seconds_);
  {
    auto t = timer_.scope(Stage::LiquidCorrection);
    setLiquidWallPressure();
    report_.seconds_pressure = omp_get_wtime() - tp;
    if (oneEquation())
      correctOneEquation(dt);
    else
      correctLiquid(dt);
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
  // The gas system, eqs. (6), (8): all gas, the moved liquid as its walls.
  if (roles_.gas_count > 0 && !oneEquation()) {
    buildNeighbours();
    tp = omp_get_wtime();
    solve_seconds_ = 0.0;
    solveGasPressure(dt);
    const double gas_seconds = omp_get_wtime() - tp;
    timer_.add(Stage::GasAssembly, gas_seconds - solve_seconds_);
    report_.seconds_pressure += gas_seconds;
    auto t = timer_.scope(Stage::GasCorrection);
    correctGas(dt);
    trace("gas correction");
    collideCorrectedGas(dt);
    trace("gas collision");
    riseEntrainedGas(dt);
    trace("entrained gas rise");
  }
  if (entrainedPoints()) {
    auto t = timer_.scope(Stage::GasCorrection);
    moveEntrainedBubbles(dt);
    trace("entrained bubbles");
  }
  {
    auto t = timer_.scope(Stage::OpenBoundaries);
    if (!config_.vents.empty()) {
      const VentExchange vented =
          exchangeVentGas<D>(state_.particles, config_, vent_at_start_, vent_start_position_, dt,
                             phases_[static_cast<int>(Phase::Gas)].density, gravity_);
      report_.vented_in = vented.gas_in;
      report_.vented_out = vented.gas_out;
      report_.vent_crowded_out = vented.gas_crowded_out;
      report_.vent_liquid_stops = static_cast<std::size_t>(vented.liquid_stops);
      report_.vented_in_by_vent = vented.gas_in_by_vent;
      report_.vented_out_by_vent = vented.gas_out_by_vent;
      report_.vented_liquid_by_vent = vented.liquid_out_by_vent;
      state_.vented_in += vented.gas_in;
      state_.vented_out += vented.gas_out;
      state_.removed += vented.liquid_out;
      report_.removed += vented.liquid_out;
    }
    markEscaped();
    const std::int64_t outflow = removeOutflow<D>(state_.particles, config_);
    report_.removed += outflow;
    state_.removed += outflow;
    removeReleasedPoints();
  }
  trace("open boundaries");
  const bool reached = until - state_.time <= dt;
  state_.time = reached ? until : state_.time + dt;
  // An output time, where a checkpoint may be written: a run resumed from it starts without what the solver keeps
  // from step to step beyond the state, so the unbroken run drops it here too (bit-identical resume).
  if (reached) forgetReusedState();
  state_.step += 1;
  state_.dt = dt;
  report_.dt = dt;
  {
    auto t = timer_.scope(Stage::Health);
    checkHealth(dt);
  }
  report_.seconds_total = omp_get_wtime() - t0;
  return report_;
}

// delta_gl of eq. (7): which gas regions are enclosed by liquid (enclosed_gas.hpp), then the roles of the
// particles in the two pressure systems. Without gas every active particle belongs to the liquid system.
template <int D>
void MpsSolver<D>::findBubbles() {
  if (oneEquation()) {  // every active particle in the one equation, each gas particle with its own momentum
    // Which gas is enclosed by water: in an open gas domain the rest of the gas may border empty space; with
    // entrained points, the pockets below a bubble's resolution that may become points (entrained_bubbles.hpp).
    regions_ = GasRegions{};
    auto& p = state_.particles;
    if (phase_present_[static_cast<int>(Phase::Gas)] &&
        (config_.numerics.gas_domain == GasDomain::Open || entrainedPoints())) {
      findGasRegions<D>(p, near_neighbours_, constants_.re_number_density, constants_.l0, regions_,
                        gasRegionOptions(&p.enclosed));
      p.enclosed = regions_.enclosed_particle;
      for (char e : regions_.enclosed) report_.bubbles += (e != 0);
    }
    assignCouplingRoles<D>(state_.particles, GasRegions{}, roles_);
    for (std::size_t i = 0; i < state_.particles.size(); ++i) {
      roles_.in_liquid_system[i] = isActive(state_.particles.kind[i]);
      roles_.open_gas[i] = 0;
    }
    return;
  }
  if (phase_present_[static_cast<int>(Phase::Gas)]) {
    auto& p = state_.particles;
    findGasRegions<D>(p, near_neighbours_, constants_.re_number_density, constants_.l0, regions_,
                      gasRegionOptions(&p.enclosed));
    // Gas that was open and is enclosed now joins the water's system and is carried by the water.
    std::vector<char> joined(p.size(), 0);
    bool any_joined = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool was_enclosed = i < p.enclosed.size() && p.enclosed[i];
      joined[i] = regions_.enclosed_particle[i] && !was_enclosed;
      any_joined = any_joined || joined[i];
    }
    if (any_joined) adoptLiquidVelocity<D>(p, near_neighbours_, joined, constants_.re_number_density);
    p.enclosed = regions_.enclosed_particle;
    for (char e : regions_.enclosed) report_.bubbles += (e != 0);
    report_.dispersed_gas = regions_.dispersed;
  } else {
    regions_ = GasRegions{};
  }
  assignCouplingRoles<D>(state_.particles, regions_, roles_,
                         static_cast<std::size_t>(config_.numerics.bubble_min_particles));
  report_.entrained_gas = roles_.entrained_count;
}

// The rules of findGasRegions from the case (enclosed_gas.hpp): in a closed gas domain a gas region below a
// bubble's resolution that touches liquid is entrained gas (0, off, when the gas borders open space); the join
// radius numerics.gas_region_link in metres (0: the number-density radius); numerics.dispersed_gas_fraction.
template <int D>
GasRegionOptions MpsSolver<D>::gasRegionOptions(const std::vector<char>* was_enclosed) const {
  GasRegionOptions options;
  options.was_enclosed = was_enclosed;
  if (config_.numerics.gas_domain == GasDomain::Closed)
    options.closed_small_region = static_cast<std::size_t>(config_.numerics.bubble_min_particles);
  // numerics.closed_pockets = "unvented": the vents' gas at the step's start is the atmosphere
  if (config_.numerics.closed_pockets == NumericsConfig::ClosedPockets::Unvented) options.vent_of = &vent_at_start_;
  options.join_radius = config_.numerics.gas_region_link * constants_.l0;
  options.dispersed_fraction = config_.numerics.dispersed_gas_fraction;
  options.dispersed_touch = config_.numerics.dispersed_gas_touch * constants_.l0;
  return options;
}

template <int D>
const NeighborList& MpsSolver<D>::currentNeighbours() {
  buildNeighbours();
  return neighbours_;
}

template <int D>
std::vector<BubbleStats> MpsSolver<D>::currentBubbles() {
  if (!phase_present_[static_cast<int>(Phase::Gas)]) return {};
  buildNeighbours();
  GasRegions regions;
  findGasRegions<D>(state_.particles, near_neighbours_, constants_.re_number_density, constants_.l0, regions,
                    gasRegionOptions(&state_.particles.enclosed));
  return bubbleStatistics<D>(state_.particles, regions, constants_.l0);
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

// The neighbour list for the current positions: the last one while it still covers them (neighbor_search.hpp:
// the results are the same, bit for bit, as with a fresh list), else a new one.
template <int D>
void MpsSolver<D>::buildNeighbours() {
  auto t = timer_.scope(Stage::Neighbours);
  const auto& p = state_.particles;
  // A list is made anew only when the last one no longer covers the particles and cannot be carried over the
  // particles an open boundary removed or made since (neighbor_search.hpp).
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

template <int D>
void MpsSolver<D>::collide(double dt) {
  if (config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  // Momentum is shared by mass, so the liquid hardly feels the gas; it ignores open gas altogether.
  const auto& open_gas = roles_.open_gas;
  const CollisionCount count = collideWhere(
      dt, [&](std::int64_t i, std::int32_t j) { return !(open_gas[j] && p.phase[i] == Phase::Liquid); });
  report_.collisions = count.reversals;
  report_.collision_wall_limits = count.wall_limits;
}

// The collision model (collision.hpp) with numerics.collision_distance and collision_restitution, over the pairs
// (i, j) where j may change i's velocity, with numerics.collision_wall_limit; the reversals and wall limits it made.
template <int D>
template <class Affects>
CollisionCount MpsSolver<D>::collideWhere(double dt, Affects&& affects) {
  auto& p = state_.particles;
  std::vector<double> mass(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) mass[i] = particleMass(i);
  const CollisionModel model{config_.numerics.collision_distance * constants_.l0,
                             config_.numerics.collision_restitution, config_.numerics.collision_wall_limit};
  return resolveCollisionPasses<D>(config_.numerics.collision_passes, p.position, p.velocity, p.kind, mass,
                                   near_neighbours_, model, dt, affects);
}

// numerics.gas_collision_after_correction: the collision model once more, after the gas system's correction, for gas
// approaching liquid, walls or dummies (the gas takes the whole reversal: it shares momentum by mass). Measured on
// waterfall_small at 3.78 s: a lone spray droplet (n = 1.1 against n0 = 6.5) held a lower pressure in the gas system
// than the air around it, the minimum-neighbour gradient pushed the air particle beside it onto it (0.64 -> 0.155 l0
// in one step, 11.9 m/s approach), and the next step's gas rows, with a pair at 0.155 l0, kicked the air to 1,300
// m/s and two particles out of the domain (docs/two-phase.md).
template <int D>
void MpsSolver<D>::collideCorrectedGas(double dt) {
  if (!config_.numerics.gas_collision_after_correction || config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  const CollisionCount count = collideWhere(dt, [&](std::int64_t i, std::int32_t j) {
    return roles_.inGasSystem(i) && !isVentGas(static_cast<std::size_t>(i)) &&
           (p.phase[j] == Phase::Liquid || isFixed(p.kind[j]));
  });
  report_.collisions += count.reversals;
  report_.collision_wall_limits += count.wall_limits;
}

// numerics.liquid_collision_after_correction: the collision model once more, after the liquid correction, for water
// approaching a wall or dummy particle (the water takes the whole reversal). The mirrored walls hold each particle's
// own pressure (wall_mirror.hpp), so a particle the correction sends into a corner meets no pressure that sends it
// back: traced at 5 mm (runs/wf5_tr30, docs/waterfall.md), the collision after the prediction turned water particle
// 13312 away from the floor/weir corner every step and the correction turned it in again; over its last 20 ms the
// prediction carried it 0.3-0.4 l0 into the corner on the velocity the correction left, until it passed into the
// weir at 2.93 s and was lost.
template <int D>
void MpsSolver<D>::collideCorrectedLiquid(double dt) {
  if (!config_.numerics.liquid_collision_after_correction || config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  const CollisionCount count = collideWhere(dt, [&](std::int64_t i, std::int32_t j) {
    return p.phase[i] == Phase::Liquid && roles_.in_liquid_system[i] && isFixed(p.kind[j]);
  });
  report_.liquid_wall_collisions = count.reversals;
  report_.collision_wall_limits += count.wall_limits;
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

template <int D>
void MpsSolver<D>::solveSystem(const std::vector<double>& guess, const char* which, int& iterations) {
  const auto rows = system_.particle_of.size();
  pressure_unknowns_.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) pressure_unknowns_[r] = guess[system_.particle_of[r]];
  solveLinear(system_.matrix, system_.rhs, pressure_unknowns_, which, iterations);
}

template <int D>
void MpsSolver<D>::solveLinear(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                               Eigen::VectorXd& x, const char* which, int& iterations) {
  const bool gas = std::string_view(which) == "gas";
  // What each row is: the particle of the unknown (system_), or -1 - g for bubble g's merged unknown (lumped_).
  row_ids_.assign(static_cast<std::size_t>(a.rows()), -1);
  const auto& particle_of = system_.particle_of;
  if (!gas && static_cast<Eigen::Index>(lumped_.column_of_row.size()) == static_cast<Eigen::Index>(particle_of.size()) &&
      lumped_.matrix.rows() == a.rows()) {
    for (std::size_t r = 0; r < particle_of.size(); ++r) {
      const auto column = lumped_.column_of_row[r];
      row_ids_[column] = column < lumped_.first_group_row ? particle_of[r] : -1 - (column - lumped_.first_group_row);
    }
  } else if (static_cast<Eigen::Index>(particle_of.size()) == a.rows()) {
    row_ids_.assign(particle_of.begin(), particle_of.end());
  }
  // The amg solver's smoother blocks are cut from the rows in their own order: rows are numbered in particle order,
  // and the particle arrays are kept sorted by the neighbour search's cells (spatial_order.hpp), so consecutive
  // rows are neighbours in space (a bubble's merged unknown comes last).
  // The rows' keys for the reuse of the preconditioner: the particles' ids, which they keep for their life.
  row_keys_.resize(row_ids_.size());
  for (std::size_t r = 0; r < row_ids_.size(); ++r)
    row_keys_[r] = row_ids_[r] >= 0 ? static_cast<std::int64_t>(state_.particles.id[row_ids_[r]]) : row_ids_[r];
  LinearSolver& solver = gas ? *gas_solver_ : *liquid_solver_;
  const auto result = solver.solve(a, b, x, &row_keys_);
  timer_.add(gas ? Stage::GasSetup : Stage::LiquidSetup, result.setup_seconds);
  timer_.add(gas ? Stage::GasSolve : Stage::LiquidSolve, result.solve_seconds);
  solve_seconds_ += result.setup_seconds + result.solve_seconds;
  iterations = result.iterations;
  if (!result.converged && !(result.relative_residual <= 1e3 * config_.numerics.solver_tolerance)) {
    std::ostringstream msg;
    msg << which << " pressure solve (" << solver.name() << ") did not converge: relative residual "
        << result.relative_residual << " after " << result.iterations << " iterations ("
        << "numerics.solver_tolerance = " << config_.numerics.solver_tolerance << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
  report_.ppe_residual = std::max(report_.ppe_residual, result.relative_residual);
}

template <int D>
void MpsSolver<D>::forgetReusedState() {
  liquid_solver_->forget();
  gas_solver_->forget();
  reorder_pending_ = true;
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

template <int D>
void MpsSolver<D>::markEscaped() {
  auto& p = state_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid && p.kind[i] != ParticleKind::Point) continue;
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
  // Every fluid particle that has existed: in the domain, driven in an inflow, escaped, or removed by an outflow.
  const std::size_t escaped = p.count(ParticleKind::Escaped);
  const std::size_t total = p.count(ParticleKind::Fluid) + p.count(ParticleKind::Inflow) +
                            p.count(ParticleKind::Point) + escaped + static_cast<std::size_t>(state_.removed);
  if (total > 0 && static_cast<double>(escaped) > config_.numerics.max_escaped_fraction * static_cast<double>(total)) {
    std::ostringstream msg;
    msg << escaped << " of " << total << " fluid particles have left the domain (more than "
        << "numerics.max_escaped_fraction = " << config_.numerics.max_escaped_fraction << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
}

template class MpsSolver<2>;
template class MpsSolver<3>;

}  // namespace mistfall
