// Test helper: a 5 cm channel fed at q = 0.016 m^2/s through an inflow under a gate, over a brink at x = 0.40 m into
// a pit whose floor is an outflow, all in a closed box of air (l0 = 1 cm, the stabilised scheme, collision at 0.8 l0),
// under either coupling (tests/test_stabilised_air.cpp, tests/test_one_equation.cpp).
#pragma once

#include <string>

namespace mistfall::test_support {

inline std::string closedChannelCase(const std::string& coupling) {
  return R"(
[case]
name = "closed_channel"
dimension = 2
[domain]
min = [-0.04, -0.16]
max = [0.56, 0.14]
[physics.gas]
sound_speed = 340.0
[numerics]
particle_spacing = 0.01
dt_max = 5e-4
scheme = "stabilised"
coupling = ")" + coupling + R"("
collision_distance = 0.8
pressure_source = "mixed"
source_relaxation = 0.01
gas_domain = "closed"
[output]
end_time = 0.3
[[region]]
name = "air"
material = "gas"
min = [0.0, -0.12]
max = [0.52, 0.10]
[[region]]
name = "water"
material = "water"
min = [0.04, 0.0]
max = [0.4, 0.05]
velocity = [0.32, 0.0]
[[region]]
name = "bed"
material = "wall"
min = [-0.04, -0.04]
max = [0.4, 0.0]
[[region]]
name = "back"
material = "wall"
min = [-0.04, -0.16]
max = [0.0, 0.14]
[[region]]
name = "gate"
material = "wall"
min = [0.0, 0.05]
max = [0.05, 0.10]
[[region]]
name = "lid"
material = "wall"
min = [0.0, 0.10]
max = [0.56, 0.14]
[[region]]
name = "floor"
material = "wall"
min = [0.0, -0.16]
max = [0.56, -0.12]
[[region]]
name = "right"
material = "wall"
min = [0.52, -0.12]
max = [0.56, 0.10]
[[inflow]]
name = "upstream"
min = [0.0, 0.0]
max = [0.04, 0.05]
direction = [1, 0]
discharge = 0.016
[[outflow]]
name = "pit"
min = [0.0, -0.12]
max = [0.52, -0.06]
)";
}

}  // namespace mistfall::test_support
