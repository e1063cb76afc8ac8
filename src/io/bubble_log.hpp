// bubbles.csv: every enclosed gas region (bubble) at every output time, one line each:
//   time, bubble (region id at that time), particles, mean_pressure [Pa], centroid_x/y/z [m], size [m^2 or m^3]
// Region ids are renumbered at every output time (enclosed_gas.hpp); follow a bubble by its centroid.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "mps/enclosed_gas.hpp"

namespace mistfall {

class BubbleLog {
 public:
  // Creates the file with its header; on resume keeps the lines with time <= resume_time (+1e-12).
  BubbleLog(const std::filesystem::path& file, std::optional<double> resume_time = std::nullopt);
  void append(double time, const std::vector<BubbleStats>& bubbles);

  static const char* header();

 private:
  std::filesystem::path file_;
  std::ofstream out_;
};

}  // namespace mistfall
