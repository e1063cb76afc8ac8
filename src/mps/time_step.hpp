// Adaptive time step: the smallest of the Courant limit  courant * l0 / max|u|,  the viscous diffusion
// limit  0.2 * l0^2 / nu_max,  and the cap dt_max.
#pragma once

#include <algorithm>
#include <limits>

namespace mistfall {

inline double chooseTimeStep(double max_speed, double l0, double courant, double max_viscosity, double dt_max) {
  double dt = dt_max;
  if (max_speed > 0.0) dt = std::min(dt, courant * l0 / max_speed);
  if (max_viscosity > 0.0) dt = std::min(dt, 0.2 * l0 * l0 / max_viscosity);
  return dt;
}

}  // namespace mistfall
