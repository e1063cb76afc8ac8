#include "io/vent_log.hpp"

#include <stdexcept>
#include <utility>

#include "io/resumable_log.hpp"
#include "io/text_format.hpp"

namespace mistfall {

const char* VentLog::header() { return "time,vent,gas_in,gas_out,air_out,liquid_out"; }

VentLog::VentLog(const std::filesystem::path& file, std::vector<std::string> vents, double particle_volume,
                 std::optional<double> resume_time)
    : file_(file),
      vents_(std::move(vents)),
      particle_volume_(particle_volume),
      out_(openResumableLog(file, header(), resume_time, "vent log")) {}

void VentLog::append(double time, double interval, const std::vector<std::int64_t>& gas_in,
                     const std::vector<std::int64_t>& gas_out, const std::vector<std::int64_t>& liquid_out) {
  for (std::size_t v = 0; v < vents_.size(); ++v) {
    const std::int64_t in = v < gas_in.size() ? gas_in[v] : 0, out = v < gas_out.size() ? gas_out[v] : 0;
    const double air_out = interval > 0.0 ? static_cast<double>(out - in) * particle_volume_ / interval : 0.0;
    out_ << text::formatDouble(time, 17) << ',' << vents_[v] << ',' << in << ',' << out << ','
         << text::formatDouble(air_out, 9) << ',' << (v < liquid_out.size() ? liquid_out[v] : 0) << '\n';
  }
  out_.flush();
  if (!out_) throw std::runtime_error("error writing vent log '" + file_.string() + "'");
}

}  // namespace mistfall
