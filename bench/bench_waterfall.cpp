// The paper's waterfall, cases/waterfall.toml (l0 = 5 mm: water, air around it, walls, the inflow buffer) and
// waterfall_small.toml (l0 = 1 cm), on 1 and 2 threads: particle-steps per second and the wall time per simulated
// second. Each repetition starts the case afresh, takes 2 warm-up steps and times the next 10. These are the
// first milliseconds (the sheet leaving the brink, dt at numerics.dt_max), not the splash, where the time step
// falls several-fold (docs/waterfall.md): the figure is a lower bound on the wall time of a whole run.
#include "case_timing.hpp"

namespace {

void waterfall(benchmark::State& bench) { mistfall::timeCaseSteps(bench, "cases/waterfall.toml", 2, 10); }
void waterfallSmall(benchmark::State& bench) {
  mistfall::timeCaseSteps(bench, "cases/waterfall_small.toml", 2, 10);
}

}  // namespace

BENCHMARK(waterfall)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(waterfallSmall)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
