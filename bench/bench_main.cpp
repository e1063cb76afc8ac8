// The benchmark executable's entry point (each bench_*.cpp registers its own benchmarks). After Google Benchmark's
// table it prints where the time of each timed step went (bench/stage_table.hpp): one row per stage of the step,
// one column per benchmark that recorded its stages, in milliseconds per step (and the share of the step).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

#include "stage_table.hpp"

namespace {

void printStageTables() {
  using namespace mistfall;
  const auto& records = stageRecords();
  if (records.empty()) return;
  // Columns of at most 4 benchmarks per table, so that the lines stay readable.
  std::vector<const std::pair<const std::string, StageRecord>*> all;
  for (const auto& r : records) all.push_back(&r);
  for (std::size_t first = 0; first < all.size(); first += 4) {
    const std::size_t last = std::min(all.size(), first + 4);
    std::printf("\nWall time per step by stage (ms/step, share of the step), src/mps/stage_timer.hpp\n");
    std::printf("%-22s", "stage");
    for (std::size_t c = first; c < last; ++c) std::printf(" | %30s", all[c]->first.c_str());
    std::printf("\n%-22s", "");
    for (std::size_t c = first; c < last; ++c)
      std::printf(" | %30s", ("particles " + std::to_string(static_cast<long>(all[c]->second.particles))).c_str());
    std::printf("\n");
    for (int k = 0; k < StageTimer::kCount; ++k) {
      const Stage s = static_cast<Stage>(k);
      bool any = false;
      for (std::size_t c = first; c < last; ++c) any = any || all[c]->second.timer.seconds(s) > 0.0;
      if (!any) continue;
      std::printf("%-22s", stageName(s));
      for (std::size_t c = first; c < last; ++c) {
        const auto& r = all[c]->second;
        const double ms = 1e3 * r.timer.seconds(s) / static_cast<double>(r.steps);
        std::printf(" | %21.2f (%4.1f %%)", ms, 100.0 * r.timer.seconds(s) / r.timer.total());
      }
      std::printf("\n");
    }
    std::printf("%-22s", "total");
    for (std::size_t c = first; c < last; ++c) {
      const auto& r = all[c]->second;
      const double ms = 1e3 * r.timer.total() / static_cast<double>(r.steps);
      std::printf(" | %21.2f %8s", ms, (std::to_string(static_cast<long>(r.particles * 1e3 / ms / 1e3)) + "k p-s/s").c_str());
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  printStageTables();
  return 0;
}
