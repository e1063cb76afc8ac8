// The tank of tank_case.hpp (water 0.06 m deep under air to 0.09 m, l0 = 5 mm) with ten single gas particles in two
// rows (1.25 and 2.75 cm above the floor), 1.5 cm apart and at least 1.75 cm from the side walls (gas within re of a
// wall is not enclosed: enclosed_gas.hpp): entrained gas below a bubble's resolution, for the swaps
// (test_entrained_gas.cpp) and the points (test_entrained_bubbles.cpp).
#pragma once

#include <string>

#include "tank_case.hpp"

namespace mistfall::test_support {

inline constexpr int kPocketColumns = 5, kPockets = 2 * kPocketColumns;
inline constexpr double kPocketLowRow = 0.0125, kPocketHighRow = 0.0275;

// `numerics`: lines appended to [numerics] (the entrained gas's model).
inline std::string pocketTankCase(const std::string& name, const std::string& numerics) {
  std::string text = tankCase(name, true, false, "", numerics);
  for (int k = 0; k < kPockets; ++k)
    text += "[[region]]\nname = \"pocket" + std::to_string(k) + "\"\nmaterial = \"gas\"\nshape = \"circle\"\n" +
            "center = [" + std::to_string(0.0175 + 0.015 * (k % kPocketColumns)) + ", " +
            std::to_string(k < kPocketColumns ? kPocketLowRow : kPocketHighRow) + "]\nradius = 0.003\n";
  return text;
}

}  // namespace mistfall::test_support
