// Where the time of a run goes: wall seconds accumulated per named stage of the step (MpsSolver::step, solver.hpp)
// and of the run around it (output, texture: cli/simulate.cpp). Reported by `make bench` (bench/stage_table.hpp).
// A scope guard times a block: { auto t = timer.scope(Stage::Collision); ... }. The timer costs two clock reads
// per stage and step, and never changes the results.
#pragma once

#include <omp.h>

#include <array>
#include <cstdint>

namespace mistfall {

enum class Stage : int {
  Neighbours,       // neighbour list builds (all of a step's)
  GasRegions,       // gas regions, bubbles (delta_gl) and the coupling roles
  TimeStep,         // choosing dt (max speed)
  Predict,          // viscosity and gravity, u* and r*
  Collision,        // collision reversals
  OpenBoundaries,   // inflows, escaped particles, outflows
  NumberDensity,    // n* of the liquid system
  LiquidAssembly,   // the liquid system's rows (unknowns, stabilised terms, matrix, bubbles lumped)
  LiquidSetup,      // the liquid solve's preconditioner setup (AMG hierarchy, incomplete Cholesky)
  LiquidSolve,      // the liquid solve's iterations
  LiquidCorrection, // wall and dummy pressures, -dt/rho grad p
  Shifting,         // particle shifting (stabilised scheme, particle_shifting.hpp)
  BubbleGas,        // the bubbles' gas carried by the liquid
  GasAssembly,      // the gas system's n*, rows and matrix
  GasSetup,         // the gas solve's preconditioner setup
  GasSolve,         // the gas solve's iterations
  GasCorrection,    // the gas correction, entrained gas rising
  Health,           // finite values, escaped fraction
  Output,           // frames, fields, diagnostics, checkpoints (cli/simulate.cpp)
  Texture,          // the inline texture stage (cli/simulate.cpp)
  Count
};

inline const char* stageName(Stage s) {
  static constexpr const char* names[] = {
      "neighbour search",   "gas regions/bubbles", "time step",         "predict (visc+grav)", "collision",
      "open boundaries",    "number density",      "liquid: assembly",  "liquid: AMG setup",   "liquid: AMG solve",
      "liquid: correction", "shifting",            "bubble gas motion", "gas: assembly",       "gas: AMG setup",
      "gas: AMG solve",     "gas: correction",     "health check",      "output",              "texture"};
  static_assert(sizeof(names) / sizeof(names[0]) == static_cast<int>(Stage::Count));
  return names[static_cast<int>(s)];
}

class StageTimer {
 public:
  static constexpr int kCount = static_cast<int>(Stage::Count);

  void add(Stage s, double seconds) {
    seconds_[static_cast<int>(s)] += seconds;
    calls_[static_cast<int>(s)] += 1;
  }
  double seconds(Stage s) const { return seconds_[static_cast<int>(s)]; }
  std::int64_t calls(Stage s) const { return calls_[static_cast<int>(s)]; }
  double total() const {
    double t = 0.0;
    for (double s : seconds_) t += s;
    return t;
  }
  void reset() {
    seconds_.fill(0.0);
    calls_.fill(0);
  }
  StageTimer& operator+=(const StageTimer& o) {
    for (int k = 0; k < kCount; ++k) seconds_[k] += o.seconds_[k], calls_[k] += o.calls_[k];
    return *this;
  }

  // Times from construction to destruction (or stop()).
  class Scope {
   public:
    Scope(StageTimer& timer, Stage stage) : timer_(&timer), stage_(stage), start_(omp_get_wtime()) {}
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    ~Scope() { stop(); }
    void stop() {
      if (timer_) timer_->add(stage_, omp_get_wtime() - start_);
      timer_ = nullptr;
    }

   private:
    StageTimer* timer_;
    Stage stage_;
    double start_;
  };
  Scope scope(Stage s) { return Scope(*this, s); }

 private:
  std::array<double, kCount> seconds_{};
  std::array<std::int64_t, kCount> calls_{};
};

}  // namespace mistfall
