#include "io/bubble_log.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"
#include "io/text_format.hpp"

namespace mistfall {

const char* BubbleLog::header() {
  return "time,bubble,particles,mean_pressure,centroid_x,centroid_y,centroid_z,size";
}

BubbleLog::BubbleLog(const std::filesystem::path& file, std::optional<double> resume_time) : file_(file) {
  std::vector<std::string> kept;
  if (resume_time && std::filesystem::exists(file_)) {
    std::ifstream in(file_, std::ios::binary);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      if (in.eof()) break;  // a torn last line (no newline) is dropped
      const auto time = text::parseDouble(line.substr(0, line.find(',')));
      if (time && *time <= *resume_time + 1e-12) kept.push_back(line);
    }
  }
  writeFileAtomically(file_, [&](std::ostream& os) {
    os << header() << '\n';
    for (const auto& l : kept) os << l << '\n';
  });
  out_.open(file_, std::ios::binary | std::ios::app);
  if (!out_) throw std::runtime_error("cannot open bubble log '" + file_.string() + "' for appending");
}

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
