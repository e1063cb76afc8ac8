#include "case/case_config.hpp"

namespace mistfall {

const char* toString(PressureSolverKind k) {
  switch (k) {
    case PressureSolverKind::EigenIccg: return "iccg";
    case PressureSolverKind::HypreAmg: return "amg";
  }
  return "?";
}

}  // namespace mistfall
