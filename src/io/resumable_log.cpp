#include "io/resumable_log.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/text_format.hpp"

namespace mistfall {

std::ofstream openResumableLog(const std::filesystem::path& file, const std::string& header,
                               std::optional<double> resume_time, const std::string& what) {
  std::vector<std::string> kept;
  if (resume_time && std::filesystem::exists(file)) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      if (in.eof()) break;  // a torn last line (no newline) is dropped
      const auto time = text::parseDouble(line.substr(0, line.find(',')));
      if (time && *time <= *resume_time + 1e-12) kept.push_back(line);
    }
  }
  // A line written before a column was added gets that column empty (not recorded), so every line has the header's.
  const auto fields = [](const std::string& l) { return std::count(l.begin(), l.end(), ',') + 1; };
  for (auto& l : kept)
    if (fields(l) < fields(header)) l.append(static_cast<std::size_t>(fields(header) - fields(l)), ',');
  writeFileAtomically(file, [&](std::ostream& os) {
    os << header << '\n';
    for (const auto& l : kept) os << l << '\n';
  });
  std::ofstream out(file, std::ios::binary | std::ios::app);
  if (!out) throw std::runtime_error("cannot open " + what + " '" + file.string() + "' for appending");
  return out;
}

}  // namespace mistfall
