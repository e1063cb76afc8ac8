// Test helpers: per-process scratch folders under the system temp dir, removed after all tests, file slurping, and
// the fields of a CSV line.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace mistfall::test_support {

inline std::filesystem::path scratchRoot() {
  return std::filesystem::temp_directory_path() / ("mistfall_tests_" + std::to_string(::getpid()));
}

// Removes this process's scratch folder after all tests.
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scratchRoot(), ec);
  }
};
inline const auto* const kScratchCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

// A fresh, empty scratch folder for one test.
inline std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = scratchRoot() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The comma-separated fields of one line of a CSV file that mistfall writes (no quoting).
inline std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream cells(line);
  for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
  return fields;
}

// From a particle trace (`MpsSolver::traceParticle`, mps/particle_trace.hpp; its columns: time, step, stage, row, id,
// kind, phase, enclosed, gas_system, x, y, ux, uy, ...): the value in `column` of the last line of stage `stage` and
// row `row` ("self" or "near"), or NaN where there is none.
inline double traceValue(const std::filesystem::path& trace, const std::string& stage, const std::string& row,
                         std::size_t column) {
  std::ifstream in(trace);
  double value = std::nan("");
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> field = csvFields(line);
    if (field.size() > column && field[2] == stage && field[3] == row) value = std::stod(field[column]);
  }
  return value;
}

}  // namespace mistfall::test_support
