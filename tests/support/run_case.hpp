// Test helpers: run a case in-process to given times and hand back the state at each.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "mps/solver.hpp"

namespace mistfall::test_support {

inline CaseConfig loadShippedCase(const std::string& name) {
  return loadCaseFile(std::string(MISTFALL_SOURCE_DIR) + "/cases/" + name);
}

// The shipped still tank (cases/hydrostatic.toml) at spacing l0 with water of `width` x `depth` [m]: its
// construction kept (walls 4 layers thick, 6 layers of air gap above the water).
inline CaseConfig stillTankCase(double l0, double width, double depth) {
  CaseConfig c = loadShippedCase("hydrostatic.toml");
  const double wall = 4 * l0, top = depth + 6 * l0;
  c.numerics.particle_spacing = l0;
  c.domain.min = {-wall, -wall, 0.0};
  c.domain.max = {width + wall, top + 4 * l0, 0.0};
  for (auto& r : c.regions) {
    if (r.name == "water") r.box.max = {width, depth, 0.0};
    if (r.name == "wall_bottom") r.box = {{-wall, -wall, 0.0}, {width + wall, 0.0, 0.0}};
    if (r.name == "wall_left") r.box = {{-wall, -wall, 0.0}, {0.0, top, 0.0}};
    if (r.name == "wall_right") r.box = {{width, -wall, 0.0}, {width + wall, top, 0.0}};
  }
  return c;
}

// A case parsed from text, its particles built and a solver over them, ready to step (solver->step(until)).
template <int D>
struct SolverRun {
  CaseConfig config;
  SimulationState<D> state;
  std::unique_ptr<MpsSolver<D>> solver;
  SolverRun(const std::string& text, const std::string& source_name) : config(parseCase(text, source_name)) {
    state.particles = buildParticles<D>(config);
    solver = std::make_unique<MpsSolver<D>>(config, state);
  }
};

// Advances a fresh run of `config` through each time in `times` (ascending), calling visit(time, state, solver).
template <int D>
void runThrough(const CaseConfig& config, const std::vector<double>& times,
                const std::function<void(double, const SimulationState<D>&, const MpsSolver<D>&)>& visit) {
  SimulationState<D> state;
  state.particles = buildParticles<D>(config);
  MpsSolver<D> solver(config, state);
  for (double t : times) {
    while (state.time < t - 1e-12) solver.step(t);
    visit(t, state, solver);
  }
}

}  // namespace mistfall::test_support
