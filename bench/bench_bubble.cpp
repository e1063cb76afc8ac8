// Two-phase throughput on cases/bubble_rise.toml (7,392 particles: water, the bubble, the air above, walls):
// particle-steps per second of the coupled step (liquid system with the bubble's pressure, bubble gas motion,
// then the gas system), on 1 and 2 threads. Each repetition starts the case afresh, takes 2 warm-up steps and
// times the next 10 (t = 0.5 ms to 3 ms: the rising bubble, not yet its burst at the surface).
#include "case_timing.hpp"

namespace {

void bubbleRise(benchmark::State& bench) { mistfall::timeCaseSteps(bench, "cases/bubble_rise.toml", 2, 10); }

}  // namespace

BENCHMARK(bubbleRise)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
