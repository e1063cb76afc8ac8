// The MPS time step (semi-implicit two-step method of Koshizuka & Oka, MODEL.md section 1), with the gas-liquid
// coupling of eqs. (5)-(8) (docs/two-phase.md):
//   buildNeighbours -> findBubbles (delta_gl) -> chooseTimeStep -> predict (viscosity + gravity, explicit)
//   -> collide -> advanceInflows (open_boundaries.hpp) -> buildNeighbours at r*
//   -> liquid system: numberDensity n* -> solveLiquidPressure (eq. (9), one unknown per bubble with eq. (17)'s
//      shift; numerics.scheme = "stabilised": stabilisedPressureTerms, solver_liquid_stabilised.cpp)
//      -> setLiquidWallPressure (paper: dummies extrapolated; stabilised: mirrored walls averaged)
//      -> correctLiquid (-dt/rho grad p; stabilised: the corrected gradient)
//   -> moveBubbleGas (the bubbles' gas takes the liquid's velocity, extended into the bubble)
//   -> gas system (when gas exists): buildNeighbours -> solveGasPressure (eq. (17), liquid as moving walls)
//      -> correctGas (open gas: velocity and position; bubble gas: position only)
//      -> riseEntrainedGas (gas below a bubble's resolution climbs through the water by exchange)
//   -> exchangeVentGas (gas_vent.hpp) -> markEscaped -> removeOutflow -> checkHealth
// numerics.coupling = "one_equation" replaces the liquid system, the bubbles and the gas system by one
// variable-density projection of both phases (solveOneEquationPressure -> correctOneEquation).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <stdexcept>
#include <deque>
#include <string>

#include "case/case_config.hpp"
#include "mps/bubble_pressure.hpp"
#include "mps/collision.hpp"
#include "mps/corrected_gradient.hpp"
#include "mps/enclosed_gas.hpp"
#include "mps/gas_vent.hpp"
#include "mps/linear_solver.hpp"
#include "mps/particle_trace.hpp"
#include "mps/phase_coupling.hpp"
#include "mps/entrained_bubbles.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/pressure_poisson.hpp"
#include "mps/reference_density.hpp"
#include "mps/simulation_state.hpp"
#include "mps/stage_timer.hpp"
#include "mps/pressure_repulsion.hpp"
#include "mps/surface_tangent.hpp"

namespace mistfall {

// A run that cannot go on: NaN, particles leaving the domain en masse, the pressure solve failing, dt collapse.
class DivergenceError : public std::runtime_error {
 public:
  DivergenceError(const std::string& what, double time, std::int64_t step)
      : std::runtime_error(what), time_(time), step_(step) {}
  double time() const { return time_; }
  std::int64_t step() const { return step_; }

 private:
  double time_;
  std::int64_t step_;
};

struct StepReport {
  double dt = 0.0;
  int ppe_iterations = 0;
  double ppe_residual = 0.0;
  std::size_t ppe_unknowns = 0;
  double seconds_total = 0.0;     // wall time of the step
  double seconds_pressure = 0.0;  // of which assembling and solving the PPE
  int gas_ppe_iterations = 0;      // the gas system (0 when there is no open gas)
  std::size_t gas_ppe_unknowns = 0;
  std::size_t bubbles = 0;         // enclosed gas regions at the start of the step
  std::int64_t created = 0;        // particles created by inflows in the step
  std::int64_t removed = 0;        // particles removed by outflows in the step (and liquid past a vent's face)
  std::int64_t vented_in = 0;      // gas created at the vents' outer faces in the step (gas_vent.hpp)
  std::int64_t vented_out = 0;     // gas removed past the vents' outer faces in the step
  std::vector<std::int64_t> vented_in_by_vent, vented_out_by_vent;  // the same per vent (the case's order)
  std::vector<std::int64_t> vented_liquid_by_vent;  // liquid removed through each vent in the step (in `removed`)
  std::size_t entrained_gas_swaps = 0;  // entrained gas particles that rose by exchange in the step
  // numerics.entrained_bubble_diameter (entrained_bubbles.hpp): gas particles that left the lattice as points, points
  // that returned to it at the surface, point steps shortened next to a wall
  std::size_t bubble_points_made = 0, bubble_points_released = 0, bubble_point_wall_stops = 0;
  std::size_t bubble_points_unpaired = 0;  // released points with no water particle to take the volume from
  std::size_t bubble_points_coalesced = 0;  // points within l0/2 of another that gave their gas back to the lattice
  std::size_t gas_corrections_capped = 0;  // gas corrections cut by gas_correction_limit or gas_speed_limit
  std::size_t gas_correction_cuts = 0;     // ... by gas_correction_limit
  std::size_t gas_speed_cuts = 0;          // ... by gas_speed_limit (a correction may be cut by both)
  std::size_t dispersed_gas = 0;     // gas particles moved with the water by numerics.dispersed_gas_fraction
  std::size_t entrained_gas = 0;     // gas particles below a bubble's resolution (moved as water; dispersed included)
  std::size_t regularised_rows = 0;  // bubble rows given numerics.bubble_regularisation's sound speed
  // What set dt: the step the liquid's particles alone allow (Courant, viscosity, dt_max; before the output-time
  // cut), and whether the fastest gas particle made dt shorter than that.
  double liquid_dt = 0.0;
  bool dt_set_by_gas = false;
  // Numerical guards of the liquid (counted, reported per output row in diagnostics.csv):
  std::size_t collisions = 0;          // approaching pairs closer than numerics.collision_distance, reversed
  std::size_t collision_wall_limits = 0;  // velocities kept from approaching a wall by numerics.collision_wall_limit
  std::size_t liquid_wall_collisions = 0;  // water-wall pairs reversed by numerics.liquid_collision_after_correction
  // fluid particles dense enough (n >= beta n0) made free surface (p = 0) by numerics.surface_neighbour_fraction or
  // surface_asymmetry alone, in every system of the step
  std::size_t neighbour_surfaces = 0;
  std::size_t gradient_fallbacks = 0;  // corrected gradients that fell back to the standard form (stabilised)
  std::size_t thin_support = 0;        // rows made free surface by numerics.liquid_support_fraction (stabilised)
  double largest_shift = 0.0;          // the largest particle shift of the step / l0 (particle_shifting.hpp)
  std::int64_t largest_shift_id = -1;  // its particle's id (-1: none shifted)
  double largest_shift_time = 0.0;     // the start of the step [s]
  std::size_t shift_cuts = 0;          // shifts shortened to numerics.shift_limit
  std::size_t shift_bounded = 0;       // shifts cut to numerics.shift_stability's bound (shift_stability.hpp)
  std::size_t shift_wall_stops = 0;     // shifts stopped at a wall by numerics.shift_wall_stop (wall_stop.hpp)
  std::size_t respacing_wall_stops = 0; // a bubble gas's re-spacings stopped at a wall by it, bubble_gas_wall_stop or respacing_walls
  std::size_t bubble_gas_wall_stops = 0; // a bubble gas's moves with the water stopped at a wall (bubble_gas_wall_stop)
  std::size_t respacing_cuts = 0;       // a bubble gas's re-spacings shortened to numerics.respacing_limit
  std::size_t respacing_fluid_stops = 0;  // a bubble gas's re-spacings stopped at a fluid particle (respacing_stop)
  std::size_t long_respacings = 0;      // a bubble gas's re-spacings longer than l0 as solved (before a cut or a slide)
  std::size_t curvature_unfitted = 0;   // bubble interface particles with no curvature fit (bubble_surface_tension)
  std::size_t vent_crowded_out = 0;    // gas that entered a vent within l0/2 of its column's gas, let out (gas_vent.cpp)
  std::size_t vent_liquid_stops = 0;   // vent columns held at liquid by numerics.vent_liquid_stop (gas_vent.hpp)
  std::size_t gap_water_floors = 0;    // water pressures raised to the air's by numerics.gap_water_floor
};

template <int D>
class MpsSolver {
 public:
  // The solver advances `state` in place; it must outlive the solver.
  MpsSolver(const CaseConfig& config, SimulationState<D>& state);

  // Advances one time step, never past `until` (so output times are hit exactly). Throws DivergenceError.
  const StepReport& step(double until);
  // What the last step did (the same report step() returned).
  const StepReport& lastReport() const { return report_; }

  const MpsConstants& constants() const { return constants_; }
  // Drops what the solver keeps from step to step beyond the state (the pressure solves' AMG hierarchies): the
  // next step starts as a fresh solver would. step() calls it whenever it reaches `until` (an output time, where
  // checkpoints are written), so that a resumed run is bit-identical to the unbroken one. (The neighbour list is
  // kept: it gives the same results as a fresh one.)
  void forgetReusedState();
  // Wall seconds per stage of every step since construction (or since the caller reset it).
  StageTimer& stageTimer() { return timer_; }
  const StageTimer& stageTimer() const { return timer_; }
  const NeighbourList& neighbours() const { return neighbours_; }
  double maxFluidSpeed() const;
  std::pair<double, double> maxPhaseSpeeds() const;  // fastest liquid and gas particle [m/s]
  std::string fastestParticle() const;               // its id, phase, role and place, in words
  std::string describeParticle(std::size_t i) const;  // the same for particle i
  // The last kRecentSteps steps' time, dt and fastest fluid particle, as CSV with a header line, oldest first (for
  // diverged.txt: which particle shortened the step before a divergence).
  std::string recentStepsCsv() const;
  static constexpr std::size_t kRecentSteps = 200;
  double particleMass(std::size_t i, bool bubble_gas_as_liquid = false) const;  // the collision model's (solver.cpp)
  // The neighbour list rebuilt at the current particle positions (for operators run between steps).
  const NeighbourList& currentNeighbours();
  // Gas regions and enclosed bubbles of the current particle positions (rebuilds the neighbour list).
  std::vector<BubbleStats> currentBubbles();
  // Writes particle `id` and its neighbours within l0 after every stage of each step from `from` on to the CSV file
  // `path` (particle_trace.hpp; `mistfall simulate --trace`). Throws std::runtime_error when it cannot be written.
  void traceParticle(std::uint64_t id, double from, const std::string& path);

 private:
  // The step's stages beyond the named operators below (solver.cpp, solver_open_boundaries.cpp).
  void holdVentStart();
  void admitInflow(double dt);
  void solveLiquidSystem(double dt);
  void correctLiquidSystem(double dt);
  void solveGasSystem(double dt);
  void ventAndRemove(double dt);
  void advanceClock(double until, double dt);
  void buildNeighbours();
  void sortParticlesBySpace();
  bool hasFullNeighbourhood(std::size_t i, const std::vector<char>& counts) const;
  double chooseTimeStepFor(double until);  // also fills report_.liquid_dt, dt_set_by_gas
  void predict(double dt);
  void collide(double dt);
  void collideCorrectedGas(double dt);
  void collideCorrectedLiquid(double dt);
  template <class Affects>
  CollisionCount collideWhere(double dt, Affects&& affects, bool bubble_gas_as_liquid = false);
  void findBubbles();
  GasRegionOptions gasRegionOptions(const std::vector<char>* was_enclosed) const;
  void computeLiquidNumberDensity();
  void countBubbleGasByVolume();
  void solveLiquidPressure(double dt);
  void setLiquidWallPressure();
  void extrapolateDummyPressure(std::vector<double>& pressure, double density, bool clamp = true) const;
  void correctLiquid(double dt);
  // numerics.scheme = "stabilised" (solver_liquid_stabilised.cpp)
  void stabilisedPressureTerms(double dt);
  void makeThinRowsFreeSurface();
  std::optional<double> thinRowLiquidPressure(std::size_t i, double rho) const;
  std::optional<double> bubbleSidePressure(std::size_t i) const;
  void findSurfaceTangents(const std::vector<Vec<D>>& last_gradient);
  void shiftParticles(double dt);
  // with `repulsive`, plus numerics.pressure_repulsion's term (pressure_repulsion.hpp): the correction's gradient
  CorrectedGradient<D> stabilisedGradient(std::size_t i, bool repulsive = false) const;
  // The corrected gradient of `difference` over `include` at i, plus the repulsion with `repulsive` on a row with an
  // unknown (the surface tangents are this step's once the unknowns are chosen: only the correction reads them).
  template <class Include, class Difference>
  CorrectedGradient<D> gradientWithRepulsion(std::size_t i, bool repulsive, Include&& include,
                                             Difference&& difference) const {
    const bool repel = repulsive && problem_.unknown[i] && !surface_tangents_.empty();
    return repulsiveCorrectedGradient<D>(i, state_.particles.position, neighbours_, constants_,
                                         config_.numerics.gradient_correction_min_determinant, repel,
                                         config_.numerics.pressure_repulsion,
                                         repel ? surface_tangents_.normal[i] : Vec<D>::Zero(), include, difference);
  }
  // numerics.coupling = "one_equation" (solver_one_equation.cpp): both phases in one variable-density projection
  bool oneEquation() const { return config_.numerics.coupling == NumericsConfig::Coupling::OneEquation; }
  // A bubble's gas moved with the liquid's velocity (bubble_gas_motion.hpp), not by a pressure of its own.
  bool bubbleGasFollowsLiquid() const {
    return config_.numerics.bubble_gas_motion != NumericsConfig::BubbleGasMotion::OwnPressure;
  }
  void solveOneEquationPressure(double dt);
  void correctOneEquation(double dt);
  CorrectedGradient<D> oneEquationGradient(std::size_t i, bool repulsive = false) const;
  void solveGasPressure(double dt);
  void correctGas(double dt);
  Vec<D> stabilisedGasGradient(std::size_t i) const;
  void applyLaplaceJump(const std::vector<std::int32_t>& group_of);
  bool mirroredLiquid(std::size_t j) const;
  // Gas of a vent at the step's start (gas_vent.hpp): a Dirichlet particle at the ambient pressure.
  bool isVentGas(std::size_t i) const {
    const auto& p = state_.particles;
    return i < vent_at_start_.size() && vent_at_start_[i] >= 0 && p.kind[i] == ParticleKind::Fluid &&
           p.phase[i] == Phase::Gas;
  }
  // Gas of an enclosed region below a bubble's resolution: it takes part in the liquid system as liquid (two
  // systems; on the one equation every gas particle has a row of its own, with its own density).
  bool isEntrainedBelowResolution(std::size_t i) const {
    const auto& p = state_.particles;
    return !oneEquation() && i < roles_.in_liquid_system.size() && p.kind[i] == ParticleKind::Fluid &&
           p.phase[i] == Phase::Gas && roles_.in_liquid_system[i] && !roles_.enclosed_gas[i];
  }
  // The Dirichlet value such a particle holds (gas_vent.hpp's ventPressure: the ambient's, less the entering air's
  // dynamic pressure where its column enters), for gas of density `density`.
  double ventGasPressure(std::size_t i, double density) const {
    const auto& p = state_.particles;
    return ventPressure<D>(p.position[i], p.velocity[i], config_.vents[vent_at_start_[i]], density, gravity_);
  }
  void moveBubbleGas(double dt);
  void riseEntrainedGas(double dt);
  bool entrainedPoints() const { return config_.numerics.entrained_bubble_diameter > 0.0; }
  void moveEntrainedBubbles(double dt);
  void removeReleasedPoints();
  // Solves system_ with initial guess from `guess`; throws DivergenceError naming `which` when it fails.
  void solveSystem(const std::vector<double>& guess, const char* which, int& iterations);
  // Throws DivergenceError naming the particle of the first row of `a` whose diagonal is zero or not finite.
  void checkDiagonal(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const char* which) const;
  void solveLinear(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   const char* which, int& iterations);
  void markEscaped();
  void checkHealth(double dt) const;
  void trace(const char* stage) {
    if (trace_ && trace_->active(state_.time)) traceStage(stage);
  }
  void traceStage(const char* stage);

  const CaseConfig& config_;
  SimulationState<D>& state_;
  MpsConstants constants_;
  std::array<PhaseProperties, 2> phases_;
  Vec<D> gravity_;
  Vec<D> domain_lower_, domain_upper_;
  std::array<bool, 2> phase_present_{false, false};
  NeighbourSearch<D> search_;
  NeighbourList neighbours_;
  // The pairs of neighbours_ within near_reach_ (+ the skin): for the operators of the number-density radius
  // (number density, gradient, gas regions, collision), which then visit about half the pairs (2D).
  NeighbourList near_neighbours_;
  double near_reach_ = 0.0;
  std::int64_t near_built_ = -1;  // search_.builds() when near_neighbours_ was filtered
  GasRegions regions_;
  CouplingRoles roles_;
  PressureProblem problem_;
  std::vector<char> thin_row_;               // stabilised: rows makeThinRowsFreeSurface made free surface
  std::vector<double> surface_pressure_;     // stabilised: Dirichlet values of free-surface particles (empty: 0)
  SurfaceTangents<D> surface_tangents_;      // stabilised: near the free surface, its normal (surface_tangent.hpp)
  std::vector<double> gas_number_density_;  // n* of the gas system (all particles counted)
  std::vector<double> gas_pressure_;        // pressures of the gas system (open gas, its walls, dummies)
  // numerics.bubble_surface_tension: per particle, -sigma kappa on a bubble's interface gas (empty: none). The water
  // sees that gas at P_B - sigma kappa (the Laplace jump); the gas itself holds P_B.
  std::vector<double> interface_jump_;
  // The vents' particles at the step's start (gas_vent.hpp): which vent each is in (-1: none; empty without
  // vents) and where it was; they are driven from there, and their gas is the gas system's Dirichlet boundary.
  std::vector<int> vent_at_start_;
  std::vector<Vec<D>> vent_start_position_;
  // numerics.entrained_bubble_diameter: the points' model, and every particle's velocity at the step's start (the
  // water's material acceleration over the step).
  std::unique_ptr<EntrainedBubbles<D>> entrained_bubbles_;
  std::vector<Vec<D>> start_velocity_;
  std::vector<std::uint64_t> released_points_;  // ids of the points released in the step, removed at its end
  PressureSystem system_;
  LumpedPressureSystem lumped_;
  Eigen::VectorXd pressure_unknowns_;
  std::unique_ptr<LinearSolver> liquid_solver_, gas_solver_;
  std::vector<std::int32_t> row_ids_;    // what each row of the system being solved is (solveLinear)
  std::vector<std::int64_t> row_keys_;   // its rows' particle ids (solveLinear)
  StepReport report_;
  struct RecentStep {  // a step's time and dt, and its fastest fluid particle when dt was chosen
    double time = 0.0, dt = 0.0, speed = 0.0, pressure = 0.0;
    std::int64_t step = 0;
    std::uint64_t id = 0;
    const char* role = "";
    Vec<D> position = Vec<D>::Zero();
  };
  std::deque<RecentStep> recent_steps_;
  struct FluidSpeeds {  // the fastest liquid and gas speeds [m/s] and the fastest fluid particle's index
    double liquid = 0.0, gas = 0.0;
    std::size_t fastest = 0;  // particles.size() when there is no fluid particle
  };
  FluidSpeeds fluidSpeeds() const;  // one parallel pass over the particles
  const char* roleOf(std::size_t i) const;  // "liquid", "open gas" or "bubble gas" (docs/two-phase.md, section 1)
  void recordStep(double dt, std::size_t fastest);
  bool reorder_pending_ = true;  // sort the particles by place before the next step (spatial_order.hpp)
  int full_neighbour_count_ = 0;  // neighbours within re of a particle inside a full lattice
  StageTimer timer_;
  double solve_seconds_ = 0.0;  // setup + solve seconds of the linear solves since the stage began
  std::unique_ptr<ParticleTrace<D>> trace_;  // --trace (particle_trace.hpp); null when off
};

}  // namespace mistfall
