// The per-stage breakdown that `make bench` prints after Google Benchmark's table: each timed benchmark records
// its solver's StageTimer (src/mps/stage_timer.hpp: wall seconds per named stage of the step) over its timed steps,
// and bench_main.cpp prints one table per benchmark, milliseconds per step and share of the step.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "mps/stage_timer.hpp"

namespace mistfall {

struct StageRecord {
  StageTimer timer;
  std::int64_t steps = 0;
  double particles = 0.0;
};

// Keyed by the benchmark's name (e.g. "damBreak/amg/particles:40000/threads:2"); inline: one registry per program.
inline std::map<std::string, StageRecord>& stageRecords() {
  static std::map<std::string, StageRecord> records;
  return records;
}

inline void recordStages(const std::string& name, const StageTimer& timer, std::int64_t steps, double particles) {
  auto& r = stageRecords()[name];
  r.timer += timer;
  r.steps += steps;
  r.particles = particles;
}

}  // namespace mistfall
