// The open-boundary tests' channel (test_open_boundaries.cpp, test_inflow_pressure.cpp): water 5 cm deep on a floor
// that ends at x = 0.4 m, fed by an inflow buffer 4 cm long under a gate at its upstream end (q = 0.016 m^2/s by
// default: U = 0.32 m/s, the water starting at q / 0.05 m); l0 = 1 cm, water only. By default the water falls off the
// end into an outflow box (x >= 0.42 m); with `end_wall` a wall closes the channel at x = 0.4 m instead.
#pragma once

#include <cstdio>
#include <string>

namespace mistfall::test_support {

struct ChannelCase {
  std::string direction = "[1, 0]";  // the inflow's
  std::string discharge = "0.016";   // [m^2/s]
  std::string inflow_keys;           // more lines of the [[inflow]] table
  std::string scheme;                // numerics.scheme (empty: the default)
  bool end_wall = false;
};

inline std::string channelCaseText(const ChannelCase& o = {}) {
  char speed[32];
  std::snprintf(speed, sizeof speed, "%.9g", std::stod(o.discharge) / 0.05);
  std::string text = R"(
[case]
name = "channel"
dimension = 2
[domain]
min = [-0.04, -0.3]
max = [0.64, 0.3]
[numerics]
)" + (o.scheme.empty() ? std::string() : "scheme = \"" + o.scheme + "\"\n") + R"(particle_spacing = 0.01
dt_max = 5e-4
pressure_source = "mixed"
source_relaxation = 0.01
[output]
end_time = 2.0
[[region]]
name = "water"
material = "water"
min = [0.04, 0.0]
max = [0.4, 0.05]
velocity = [)" + std::string(speed) + R"(, 0.0]
[[region]]
name = "floor"
material = "wall"
min = [-0.04, -0.04]
max = [)" + (o.end_wall ? "0.44" : "0.4") + R"(, 0.0]
[[region]]
name = "back"
material = "wall"
min = [-0.04, 0.0]
max = [0.0, 0.1]
[[region]]
name = "gate"
material = "wall"
min = [0.0, 0.05]
max = [0.05, 0.09]
[[inflow]]
name = "upstream"
min = [0.0, 0.0]
max = [0.04, 0.05]
direction = )" + o.direction + R"(
discharge = )" + o.discharge + "\n" + o.inflow_keys + "\n";
  if (o.end_wall)
    text += "[[region]]\nname = \"end\"\nmaterial = \"wall\"\nmin = [0.4, 0.0]\nmax = [0.44, 0.1]\n";
  else
    text += "[[outflow]]\nname = \"end\"\nmin = [0.42, -0.3]\nmax = [0.64, 0.3]\n";
  return text;
}

}  // namespace mistfall::test_support
