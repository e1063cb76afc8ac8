// Test helpers for case-file tests: a minimal valid 2D case assembled from replaceable sections, and
// parsing that expects a CaseError.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "case/case_file.hpp"

namespace mistfall::test_support {

// A minimal valid 2D case, assembled from replaceable sections.
struct Parts {
  std::string header = "name = \"t\"\ndimension = 2\n";
  std::string domain = "min = [0.0, 0.0]\nmax = [1.0, 1.0]\n";
  std::string physics = "";
  std::string numerics = "particle_spacing = 0.1\n";
  std::string output = "end_time = 1.0\n";
  std::string regions = "[[region]]\nname = \"w\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n";
  std::string text() const {
    return "[case]\n" + header + "[domain]\n" + domain + physics + "[numerics]\n" + numerics + "[output]\n" +
           output + regions;
  }
};

// Parses `text` expecting a CaseError; returns its message.
inline std::string errorOf(const std::string& text) {
  try {
    parseCase(text, "cases/x.toml");
  } catch (const CaseError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no CaseError for:\n" << text;
  return "";
}

}  // namespace mistfall::test_support

#define EXPECT_HAS(msg, sub) EXPECT_NE((msg).find(sub), std::string::npos) << "missing '" << (sub) << "' in: " << (msg)
