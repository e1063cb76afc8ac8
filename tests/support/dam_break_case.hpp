// Test helper: the tiny 2D dam break used by the simulate and inline-texture tests (a few seconds per run).
#pragma once

#include <sstream>
#include <string>

#include "tank_walls.hpp"

namespace mistfall::test_support {

// 2D dam break, l0 = 0.01: a 0.1 x 0.2 column (10 x 20 = 200 fluid particles) in a 0.3 m long tank with
// 4-layer walls (tankWalls: floor, left, right). `numerics_extra` / `output_extra` are appended to those tables.
inline std::string damBreakCase(double end_time = 0.1, double interval = 0.02, const std::string& numerics_extra = "",
                                const std::string& output_extra = "") {
  std::ostringstream s;
  s << R"([case]
name = "small_dam_break"
dimension = 2

[domain]
min = [-0.04, -0.04]
max = [0.34, 0.30]

[physics]
gravity = [0.0, -9.81]

[numerics]
particle_spacing = 0.01
dt_max = 1.0e-3
max_escaped_fraction = 0.05
)" << numerics_extra
    << "\n[output]\nend_time = " << end_time << "\ninterval = " << interval << "\n" << output_extra << R"(
[[region]]
name = "column"
material = "water"
min = [0.0, 0.0]
max = [0.1, 0.2]

)" << tankWalls(0.3, 0.26, 0.04);
  return s.str();
}

}  // namespace mistfall::test_support
