// Test helpers: per-process scratch folders under the system temp dir, removed after all tests, file slurping, and
// the fields of a CSV line.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
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

}  // namespace mistfall::test_support
