// Test helper: a vertical column of air 10 cm wide and 30 cm high between side walls at l0 = 1 cm, with a puddle in
// a cup beside it (a case needs water; it takes no part). The column's ends (walls or vents) and extra numerics keys
// are the caller's.
#pragma once

#include <string>

namespace mistfall::test_support {

// `numerics`: keys added to [numerics]; `speed`: the air's upward speed at the start [m/s]; `ends`: the tables that
// close (or open) the column at y < 0 and y > 0.3 m.
inline std::string airColumnCase(const std::string& numerics, double speed, const std::string& ends) {
  return R"(
[case]
name = "air_column"
dimension = 2
[domain]
min = [-0.04, -0.04]
max = [0.30, 0.34]
[physics.gas]
sound_speed = 340.0
[numerics]
particle_spacing = 0.01
dt_max = 5e-4
pressure_source = "mixed"
source_relaxation = 0.01
gas_domain = "closed"
)" + numerics + R"(
[output]
end_time = 1.0
[[region]]
name = "air"
material = "gas"
min = [0.0, 0.0]
max = [0.1, 0.3]
velocity = [0.0, )" + std::to_string(speed) + R"(]
[[region]]
name = "left"
material = "wall"
min = [-0.04, -0.04]
max = [0.0, 0.34]
[[region]]
name = "right"
material = "wall"
min = [0.1, -0.04]
max = [0.14, 0.34]
[[region]]
name = "cup"
material = "wall"
min = [0.14, -0.04]
max = [0.30, 0.0]
[[region]]
name = "cup_end"
material = "wall"
min = [0.26, 0.0]
max = [0.30, 0.1]
[[region]]
name = "puddle"
material = "water"
min = [0.14, 0.0]
max = [0.26, 0.03]
)" + ends;
}

// The column's ends sealed: a floor and a lid of wall.
inline std::string sealedEnds() {
  return R"(
[[region]]
name = "floor"
material = "wall"
min = [0.0, -0.04]
max = [0.1, 0.0]
[[region]]
name = "lid"
material = "wall"
min = [0.0, 0.3]
max = [0.1, 0.34]
)";
}

// The column's ends as a duct: a vent across its bottom (outward -y) and one across its top (outward +y).
inline std::string ductVents() {
  return R"(
[[vent]]
name = "bottom"
min = [0.0, -0.04]
max = [0.1, 0.0]
direction = [0, -1]
[[vent]]
name = "top"
min = [0.0, 0.3]
max = [0.1, 0.34]
direction = [0, 1]
)";
}

}  // namespace mistfall::test_support
