// vents.csv: what each vent ([[vent]], src/mps/gas_vent.hpp) let in and out since the previous output time, one line
// a vent at every output time (a case without vents writes no file):
//   time, vent (its name), gas_in, gas_out (particles), air_out [m^2/s per unit width in 2D, m^3/s in 3D: the net
//   volume of air leaving through it, (gas_out - gas_in) l0^D / the interval; negative where air enters],
//   liquid_out (liquid particles removed through it: past its outer face, or in its box with liquid_exit =
//   "inner_face"; empty on the lines a run wrote before the column existed)
// The cavity vent's air_in against the water's discharge is the nappe's air demand (docs/waterfall.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace mistfall {

class VentLog {
 public:
  // Creates the file with its header; on resume keeps the lines with time <= resume_time (+1e-12).
  VentLog(const std::filesystem::path& file, std::vector<std::string> vents, double particle_volume,
          std::optional<double> resume_time = std::nullopt);
  // One line per vent; `interval` is the time since the previous output (0 at the first: air_out 0).
  void append(double time, double interval, const std::vector<std::int64_t>& gas_in,
              const std::vector<std::int64_t>& gas_out, const std::vector<std::int64_t>& liquid_out = {});

  static const char* header();

 private:
  std::filesystem::path file_;
  std::vector<std::string> vents_;
  double particle_volume_;
  std::ofstream out_;
};

}  // namespace mistfall
