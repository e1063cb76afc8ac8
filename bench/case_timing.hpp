// Times the first steps of a shipped 2D case for the benchmark table: each repetition builds the case afresh,
// takes `warmup` steps untimed and times the next `timed` steps. Counters: particles, threads, particle-steps per
// second, the pressure solves' share of the time, CG iterations per step of the liquid and gas systems, the mean
// time step and the wall time per simulated second (wall_s_per_sim_s = timed wall time / simulated time).
#pragma once

#include <benchmark/benchmark.h>
#include <omp.h>

#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/solver.hpp"
#include "stage_table.hpp"

namespace mistfall {

inline void timeCaseSteps(benchmark::State& bench, const std::string& case_file, int warmup, int timed) {
  const int threads = static_cast<int>(bench.range(0));
  omp_set_num_threads(threads);
  const CaseConfig config = loadCaseFile(std::string(MISTFALL_SOURCE_DIR) + "/" + case_file);
  double total_seconds = 0.0, pressure_seconds = 0.0, simulated = 0.0;
  std::int64_t steps = 0, iterations = 0, gas_iterations = 0;
  double particles = 0.0;
  for (auto _ : bench) {
    bench.PauseTiming();
    SimulationState<2> state;
    state.particles = buildParticles<2>(config);
    MpsSolver<2> mps(config, state);
    for (int i = 0; i < warmup; ++i) mps.step(1e9);
    particles = static_cast<double>(state.particles.size());
    mps.stageTimer().reset();
    bench.ResumeTiming();
    for (int i = 0; i < timed; ++i) {
      const auto& r = mps.step(1e9);
      total_seconds += r.seconds_total;
      pressure_seconds += r.seconds_pressure;
      iterations += r.ppe_iterations;
      gas_iterations += r.gas_ppe_iterations;
      simulated += r.dt;
      ++steps;
    }
    recordStages(case_file + " threads:" + std::to_string(threads), mps.stageTimer(), timed, particles);
  }
  bench.counters["particles"] = particles;
  bench.counters["threads"] = threads;
  bench.counters["particle_steps_per_s"] = benchmark::Counter(particles * steps / total_seconds);
  bench.counters["pressure_share"] = pressure_seconds / total_seconds;
  bench.counters["ppe_iters"] = static_cast<double>(iterations) / steps;
  bench.counters["gas_ppe_iters"] = static_cast<double>(gas_iterations) / steps;
  bench.counters["dt_ms"] = 1e3 * simulated / steps;
  bench.counters["wall_s_per_sim_s"] = total_seconds / simulated;
}

}  // namespace mistfall
