// Dam-break throughput: particle-steps per second and the share of time in the pressure solve, for the
// 2D Martin & Moyce column at about 10k, 40k and 160k particles, on 1 and 2 threads, for each PPE solver.
// The column (a x 2a) starts from rest and is advanced for a fixed number of steps after a short warm-up.
// l0 = 2 mm with dt_max = 2.5e-4 s (the dt_max / l0 ratio of cases/dam_break.toml).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <sstream>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/solver.hpp"
#include "stage_table.hpp"

using namespace mistfall;

namespace {

// Fluid particles = (a/l0) * (2a/l0); a chosen so that all particles (with walls) are about `target`.
CaseConfig damBreakCase(int target_particles, const char* solver) {
  const double l0 = 0.002;
  const int columns = static_cast<int>(std::lround(std::sqrt(target_particles * 0.88 / 2.0)));
  const double a = columns * l0;
  const double wall = 4 * l0;
  std::ostringstream toml;
  toml << "[case]\nname = \"bench\"\ndimension = 2\n"
       << "[domain]\nmin = [" << -wall << ", " << -wall << "]\nmax = [" << 4 * a + wall << ", " << 2.4 * a << "]\n"
       << "[numerics]\nparticle_spacing = " << l0 << "\ndt_max = 2.5e-4\npressure_solver = \"" << solver << "\"\n"
       << "[output]\nend_time = 1.0\ninterval = 0.1\n"
       << "[[region]]\nname = \"column\"\nmaterial = \"water\"\nmin = [0, 0]\nmax = [" << a << ", " << 2 * a << "]\n"
       << "[[region]]\nname = \"floor\"\nmaterial = \"wall\"\nmin = [" << -wall << ", " << -wall << "]\nmax = ["
       << 4 * a + wall << ", 0]\n"
       << "[[region]]\nname = \"left\"\nmaterial = \"wall\"\nmin = [" << -wall << ", 0]\nmax = [0, " << 2.4 * a << "]\n"
       << "[[region]]\nname = \"right\"\nmaterial = \"wall\"\nmin = [" << 4 * a << ", 0]\nmax = [" << 4 * a + wall
       << ", " << 2.4 * a << "]\n";
  return parseCase(toml.str(), "bench");
}

void damBreak(benchmark::State& bench, const char* solver) {
  const int target = static_cast<int>(bench.range(0));
  const int threads = static_cast<int>(bench.range(1));
  omp_set_num_threads(threads);
  const CaseConfig config = damBreakCase(target, solver);
  SimulationState<2> state;
  state.particles = buildParticles<2>(config);
  MpsSolver<2> mps(config, state);
  for (int i = 0; i < 5; ++i) mps.step(1.0);  // warm-up: first steps start from a perfect lattice
  mps.stageTimer().reset();
  double pressure_seconds = 0.0, total_seconds = 0.0;
  std::int64_t steps = 0, iterations = 0;
  for (auto _ : bench) {
    const auto& r = mps.step(1.0);
    pressure_seconds += r.seconds_pressure;
    total_seconds += r.seconds_total;
    iterations += r.ppe_iterations;
    ++steps;
  }
  const double n = static_cast<double>(state.particles.size());
  bench.counters["particles"] = n;
  bench.counters["threads"] = threads;
  bench.counters["particle_steps_per_s"] = benchmark::Counter(n * steps / total_seconds);
  bench.counters["pressure_share"] = pressure_seconds / total_seconds;
  bench.counters["ppe_iters"] = static_cast<double>(iterations) / steps;
  recordStages(std::string("dam break ") + solver + " " + std::to_string(target / 1000) + "k threads:" +
                   std::to_string(threads),
               mps.stageTimer(), steps, n);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10000, 40000, 160000})
    for (int t : {1, 2}) b->Args({n, t});
  b->ArgNames({"particles", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
}

}  // namespace

BENCHMARK_CAPTURE(damBreak, iccg, "iccg")->Apply(sizes);
BENCHMARK_CAPTURE(damBreak, amg, "amg")->Apply(sizes);
