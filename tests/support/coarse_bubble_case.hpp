// A coarse cases/bubble_rise.toml as case-file text: l0 = 5 mm (62 gas particles in the bubble, 9 across), a gas disc
// of radius 2.25 cm whose centre lies 5.75 cm under the surface of a tank 0.2 m wide, compressible gas (c = 340 m/s),
// mixed source. `extra_numerics`: lines appended to [numerics]; `end_time`: [output] end_time, and `spacing`:
// numerics.particle_spacing, as TOML text.
#pragma once

#include <string>

namespace mistfall::test_support {

inline std::string coarseBubbleCase(const std::string& extra_numerics = "", const std::string& end_time = "0.15",
                                    const std::string& spacing = "0.005") {
  return R"(
[case]
name = "coarse_bubble"
dimension = 2
[domain]
min = [-0.02, -0.02]
max = [0.22, 0.25]
[physics.gas]
sound_speed = 340.0
[numerics]
particle_spacing = )" + spacing + R"(
dt_max = 5e-4
pressure_source = "mixed"
source_relaxation = 0.01
)" + extra_numerics + "[output]\nend_time = " + end_time + "\n" + R"([[region]]
name = "air"
material = "gas"
min = [0.0, 0.0]
max = [0.2, 0.2]
[[region]]
name = "water"
material = "water"
min = [0.0, 0.0]
max = [0.2, 0.15]
[[region]]
name = "bubble"
material = "gas"
shape = "circle"
center = [0.1, 0.0925]
radius = 0.0225
[[region]]
name = "floor"
material = "wall"
min = [-0.02, -0.02]
max = [0.22, 0.0]
[[region]]
name = "left"
material = "wall"
min = [-0.02, 0.0]
max = [0.0, 0.2]
[[region]]
name = "right"
material = "wall"
min = [0.2, 0.0]
max = [0.22, 0.2]
)";
}

}  // namespace mistfall::test_support
