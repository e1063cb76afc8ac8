// The per-output-time logs next to diagnostics.csv (bubbles.csv, vents.csv): a CSV file whose lines start with the
// output time, started afresh by a new run and cut back to the checkpoint's time by a resumed one.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace mistfall {

// Writes `file` anew with its header line, keeping, on resume, the lines whose time is <= resume_time (+1e-12; a torn
// last line without its newline is dropped; a kept line with fewer fields than the header, from before a column was
// added, gets the missing ones empty), and returns it opened for appending (`what` names it in errors).
std::ofstream openResumableLog(const std::filesystem::path& file, const std::string& header,
                               std::optional<double> resume_time, const std::string& what);

}  // namespace mistfall
