// Two-phase throughput on cases/bubble_rise.toml (7,392 particles: water, the bubble, the air above, walls):
// particle-steps per second of the coupled step (liquid system with the bubble's pressure, bubble gas motion,
// then the gas system), on 1 and 2 threads. Each repetition starts the case afresh, takes 2 warm-up steps and
// times the next 10 (t = 0.5 ms to 3 ms: the rising bubble, not yet its burst at the surface).
#include <benchmark/benchmark.h>
#include <omp.h>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/solver.hpp"

using namespace mistfall;

namespace {

void bubbleRise(benchmark::State& bench) {
  const int threads = static_cast<int>(bench.range(0));
  omp_set_num_threads(threads);
  const CaseConfig config = loadCaseFile(std::string(MISTFALL_SOURCE_DIR) + "/cases/bubble_rise.toml");
  double total_seconds = 0.0, pressure_seconds = 0.0;
  std::int64_t steps = 0, iterations = 0, gas_iterations = 0;
  double particles = 0.0;
  for (auto _ : bench) {
    bench.PauseTiming();
    SimulationState<2> state;
    state.particles = buildParticles<2>(config);
    MpsSolver<2> mps(config, state);
    for (int i = 0; i < 2; ++i) mps.step(1.0);
    particles = static_cast<double>(state.particles.size());
    bench.ResumeTiming();
    for (int i = 0; i < 10; ++i) {
      const auto& r = mps.step(1.0);
      total_seconds += r.seconds_total;
      pressure_seconds += r.seconds_pressure;
      iterations += r.ppe_iterations;
      gas_iterations += r.gas_ppe_iterations;
      ++steps;
    }
  }
  bench.counters["particles"] = particles;
  bench.counters["threads"] = threads;
  bench.counters["particle_steps_per_s"] = benchmark::Counter(particles * steps / total_seconds);
  bench.counters["pressure_share"] = pressure_seconds / total_seconds;
  bench.counters["ppe_iters"] = static_cast<double>(iterations) / steps;
  bench.counters["gas_ppe_iters"] = static_cast<double>(gas_iterations) / steps;
}

}  // namespace

BENCHMARK(bubbleRise)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
