// Texture spread against the time step, and texture throughput. A cloud of 4000 fine particles (mist in air or
// micro-bubbles in water, no gravity) released at one point in a uniform field with U = 0 and
// k = 1e-3 m^2/s^2 (sigma_u = sqrt(2k/3) = 2.58 cm/s) is stepped to t = 0.5 s with dt = 0.25 .. 8 ms under each
// fluctuation model. Counters: the measured spread sigma_x (rms per axis) [mm], the model's [mm]
// (redrawn, tracer: sigma_u sqrt(dt t), the paper's model depends on dt; langevin, tracer:
// sqrt(2 sigma_u^2 T_L [t - T_L (1 - e^{-t/T_L})]) with T_L = 0.48 Ds / sqrt(k) = 75.9 ms at Ds = 5 mm,
// independent of dt), and texture particle-steps per second (threads: as OMP_NUM_THREADS).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cmath>

#include "texture/texture_cloud.hpp"

using namespace mistfall;

namespace {

constexpr double kK = 1e-3, kT = 0.5, kDs = 0.005;
constexpr int kParticles = 4000;

void textureSpread(benchmark::State& bench) {
  const bool langevin = bench.range(0) == 1;
  const bool bubbles = bench.range(1) == 1;
  const double dt = bench.range(2) * 0.25e-3;
  const int steps = static_cast<int>(std::lround(kT / dt));
  TextureParameters p;
  p.gravity = Vec3::Zero();
  p.fluctuation.model = langevin ? FluctuationModel::Langevin : FluctuationModel::Redrawn;
  p.fluctuation.ds = kDs;
  FlowSample gas, liquid;
  gas.k = liquid.k = kK;
  liquid.liquid_fraction = 1.0;
  const UniformFlow flow(gas, liquid);
  double variance = 0.0, seconds = 0.0;
  for (auto _ : bench) {
    TextureCloud cloud(p);
    for (int i = 0; i < kParticles; ++i)
      cloud.addParticle(bubbles ? TextureKind::MicroBubble : TextureKind::Mist, Vec3::Zero(), Vec3::Zero(), 7.5e-5,
                        0.0);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) cloud.step(flow, s * dt, dt);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    variance = 0.0;
    for (const auto& x : cloud.position) variance += x.squaredNorm();
    variance /= 3.0 * cloud.size();
  }
  const double sigma2 = 2.0 * kK / 3.0;
  const double t_l = lagrangianTimeScale(p.fluctuation, kK);
  const double model = langevin ? 2.0 * sigma2 * t_l * (kT - t_l * (1.0 - std::exp(-kT / t_l))) : sigma2 * dt * kT;
  bench.counters["dt_ms"] = dt * 1e3;
  bench.counters["sigma_mm"] = std::sqrt(variance) * 1e3;
  bench.counters["tracer_model_mm"] = std::sqrt(model) * 1e3;
  bench.counters["particle_steps_per_s"] =
      static_cast<double>(kParticles) * steps * static_cast<double>(bench.iterations()) / seconds;
}

}  // namespace

// Args: model (0 redrawn, 1 langevin), kind (0 mist, 1 micro-bubble), dt in units of 0.25 ms.
BENCHMARK(textureSpread)
    ->ArgsProduct({{0, 1}, {0, 1}, {1, 2, 4, 8, 16, 32}})
    ->ArgNames({"langevin", "bubble", "dt_x0.25ms"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

namespace {

// Throughput through a 2D flow grid (GridFlow: two frames, bilinear in space, linear in time): 20000 mist
// particles in a 1 m x 1 m grid of 1 cm spacing with a swirling gas field and k = 1e-3, 100 steps of 1 ms,
// on 1 and 2 threads.
std::shared_ptr<const ImageData> swirlGrid(double time) {
  auto g = std::make_shared<ImageData>();
  g->spacing = {0.01, 0.01, 1.0};
  g->dims = {101, 101, 1};
  g->time = time;
  const std::size_t n = g->nodeCount();
  std::vector<double> u(3 * n, 0.0), k(n, 1e-3), one(n, 1.0), zero(n, 0.0);
  for (std::size_t node = 0; node < n; ++node) {
    const double x = 0.01 * (node % 101) - 0.5, y = 0.01 * (node / 101) - 0.5;
    u[3 * node] = -y;
    u[3 * node + 1] = x;
  }
  g->arrays = {{"gas_velocity", 3, u}, {"liquid_velocity", 3, std::vector<double>(3 * n, 0.0)},
               {"gas_sps_k", 1, k},    {"liquid_sps_k", 1, zero},
               {"gas_coverage", 1, one}, {"liquid_coverage", 1, zero}};
  return g;
}

void textureThroughputGrid(benchmark::State& bench) {
  const int threads = static_cast<int>(bench.range(0));
  omp_set_num_threads(threads);
  const GridFlow flow(swirlGrid(0.0), swirlGrid(0.1), 2);
  TextureParameters p;
  p.fluctuation.ds = kDs;
  constexpr int kMany = 20000, kSteps = 100;
  double seconds = 0.0;
  for (auto _ : bench) {
    TextureCloud cloud(p);
    for (int i = 0; i < kMany; ++i)
      cloud.addParticle(TextureKind::Mist, Vec3(0.1 + 0.8 * (i % 200) / 200.0, 0.1 + 0.8 * (i / 200) / 100.0, 0.0),
                        Vec3::Zero(), 7.5e-5, 0.0);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < kSteps; ++s) cloud.step(flow, s * 1e-3, 1e-3);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  bench.counters["threads"] = threads;
  bench.counters["particle_steps_per_s"] =
      static_cast<double>(kMany) * kSteps * static_cast<double>(bench.iterations()) / seconds;
}

}  // namespace

BENCHMARK(textureThroughputGrid)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->Iterations(3);
