// The MPS time step (semi-implicit two-step method of Koshizuka & Oka, MODEL.md section 1):
//   buildNeighbours -> chooseTimeStep -> predict (viscosity + gravity, explicit) -> collide
//   -> buildNeighbours at r* -> numberDensity n* -> solvePressure (eq. (9)/(17)) -> extrapolateDummyPressure
//   -> correct (-dt/rho grad p)
//   -> markEscaped -> checkHealth
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "case/case_config.hpp"
#include "mps/linear_solver.hpp"
#include "mps/neighbor_search.hpp"
#include "mps/pressure_poisson.hpp"
#include "mps/reference_density.hpp"
#include "mps/simulation_state.hpp"

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
};

template <int D>
class MpsSolver {
 public:
  // The solver advances `state` in place; it must outlive the solver.
  MpsSolver(const CaseConfig& config, SimulationState<D>& state);

  // Advances one time step, never past `until` (so output times are hit exactly). Throws DivergenceError.
  const StepReport& step(double until);

  const MpsConstants& constants() const { return constants_; }
  const NeighborList& neighbours() const { return neighbours_; }
  double maxFluidSpeed() const;
  double particleMass(std::size_t i) const;

 private:
  void buildNeighbours();
  double chooseTimeStepFor(double until) const;
  void predict(double dt);
  void collide(double dt);
  void computeNumberDensity();
  void solvePressure(double dt);
  void extrapolateDummyPressure();
  void correct(double dt);
  void markEscaped();
  void checkHealth(double dt) const;

  const CaseConfig& config_;
  SimulationState<D>& state_;
  MpsConstants constants_;
  std::array<PhaseProperties, 2> phases_;
  Vec<D> gravity_;
  Vec<D> domain_lower_, domain_upper_;
  std::size_t initial_fluid_ = 0;
  std::array<bool, 2> phase_present_{false, false};
  NeighborSearch<D> search_;
  NeighborList neighbours_;
  PressureSystem system_;
  Eigen::VectorXd pressure_unknowns_;
  std::unique_ptr<LinearSolver> linear_solver_;
  StepReport report_;
};

}  // namespace mistfall
