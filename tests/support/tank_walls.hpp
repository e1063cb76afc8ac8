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

// One 2D wall box [x0, y0]..[x1, y1] as a [[region]] table.
inline std::string wallRegion(const std::string& name, double x0, double y0, double x1, double y1) {
  return "[[region]]\nname = \"" + name + "\"\nmaterial = \"wall\"\nmin = [" + tomlFloat(x0) + ", " + tomlFloat(y0) +
         "]\nmax = [" + tomlFloat(x1) + ", " + tomlFloat(y1) + "]\n";
}

inline std::string tankWalls(double width, double height, double thickness) {
  const double t = thickness;
  return wallRegion("floor", -t, -t, width + t, 0.0) + wallRegion("left", -t, -t, 0.0, height) +
         wallRegion("right", width, -t, width + t, height);
}

}  // namespace mistfall::test_support
