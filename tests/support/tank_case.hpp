// The two-phase test tank as case-file text: 2D, 0.1 m wide, water 0.06 m deep, optionally air up to 0.09 m
// above it (open top) and a gas disc (bubble) of radius 1.25 cm at (0.05, 0.03) in the water; l0 = 5 mm, mixed
// source term, walls at the floor and the sides.
#pragma once

#include <string>

#include "tank_walls.hpp"

namespace mistfall::test_support {

// `gas_sound_speed`: the [physics.gas] sound_speed, or empty for no [physics.gas] table (the defaults);
// `extra_numerics`: lines appended to [numerics].
inline std::string tankCase(const std::string& name, bool air, bool bubble, const std::string& gas_sound_speed,
                            const std::string& extra_numerics = "") {
  std::string text = "[case]\nname = \"" + name + "\"\ndimension = 2\n[domain]\nmin = [-0.02, -0.02]\n"
                     "max = [0.12, 0.12]\n";
  if (!gas_sound_speed.empty()) text += "[physics.gas]\nsound_speed = " + gas_sound_speed + "\n";
  text += "[numerics]\nparticle_spacing = 0.005\ndt_max = 5e-4\npressure_source = \"mixed\"\n"
          "source_relaxation = 0.01\n" + extra_numerics + "[output]\nend_time = 1.0\n";
  if (air) text += "[[region]]\nname = \"air\"\nmaterial = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.09]\n";
  text += "[[region]]\nname = \"water\"\nmaterial = \"water\"\nmin = [0.0, 0.0]\nmax = [0.1, 0.06]\n";
  if (bubble)
    text += "[[region]]\nname = \"bubble\"\nmaterial = \"gas\"\nshape = \"circle\"\ncenter = [0.05, 0.03]\n"
            "radius = 0.0125\n";
  return text + tankWalls(0.1, 0.09, 0.02);
}

}  // namespace mistfall::test_support
