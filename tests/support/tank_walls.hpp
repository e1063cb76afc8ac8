// The walls of an open tank as case-file text: for water and air in the box [0, width] x [0, height], a floor
// [-t, -t]..[width + t, 0] and side walls [-t, -t]..[0, height] and [width, -t]..[width + t, height], t the
// thickness (regions named floor, left, right).
#pragma once

#include <sstream>
#include <string>

namespace mistfall::test_support {

// A TOML float at the stream's default precision (0.1 + 0.02 is written 0.12, 0 is written 0.0).
inline std::string tomlFloat(double value) {
  std::ostringstream s;
  s << value;
  std::string text = s.str();
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

inline std::string tankWalls(double width, double height, double thickness) {
  std::string s;
  auto wall = [&](const char* name, double x0, double y0, double x1, double y1) {
    s += "[[region]]\nname = \"" + std::string(name) + "\"\nmaterial = \"wall\"\nmin = [" + tomlFloat(x0) + ", " +
         tomlFloat(y0) + "]\nmax = [" + tomlFloat(x1) + ", " + tomlFloat(y1) + "]\n";
  };
  const double t = thickness;
  wall("floor", -t, -t, width + t, 0.0);
  wall("left", -t, -t, 0.0, height);
  wall("right", width, -t, width + t, height);
  return s;
}

}  // namespace mistfall::test_support
