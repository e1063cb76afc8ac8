#include "case/case_config.hpp"

#include <stdexcept>
#include <string>

namespace mistfall {

const PhaseProperties& phaseProperties(const PhysicsConfig& physics, int phase_index) {
  switch (phase_index) {
    case 0: return physics.liquid;
    case 1: return physics.gas;
  }
  throw std::out_of_range("phaseProperties: phase index " + std::to_string(phase_index) +
                          " is not 0 (liquid) or 1 (gas)");
}

const char* toString(PressureSolverKind k) {
  switch (k) {
    case PressureSolverKind::EigenIccg: return "iccg";
    case PressureSolverKind::HypreAmg: return "amg";
  }
  return "?";
}

const char* toString(RenderStyle s) { return s == RenderStyle::Natural ? "natural" : "lab"; }

}  // namespace mistfall
