#include "io/bubble_log.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "io/resumable_log.hpp"
#include "io/text_format.hpp"

namespace mistfall {

const char* BubbleLog::header() {
  return "time,bubble,particles,mean_pressure,centroid_x,centroid_y,centroid_z,size";
}

BubbleLog::BubbleLog(const std::filesystem::path& file, std::optional<double> resume_time)
    : file_(file), out_(openResumableLog(file, header(), resume_time, "bubble log")) {}

void BubbleLog::append(double time, const std::vector<BubbleStats>& bubbles) {
  for (const auto& b : bubbles) {
    out_ << text::formatDouble(time, 17) << ',' << b.region << ',' << b.particles << ','
         << text::formatDouble(b.mean_pressure, 9) << ',' << text::formatDouble(b.centroid[0], 9) << ','
         << text::formatDouble(b.centroid[1], 9) << ',' << text::formatDouble(b.centroid[2], 9) << ','
         << text::formatDouble(b.size, 9) << '\n';
  }
  out_.flush();
  if (!out_) throw std::runtime_error("error writing bubble log '" + file_.string() + "'");
}

}  // namespace mistfall
