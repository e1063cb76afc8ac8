// Checked access to the TOML tree of a case file, used by the case-file reader (case_file.cpp). Every
// failure throws CaseError naming the file, the full key path, the offending value and what is allowed.
// Internal to src/case.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace mistfall {
struct CaseConfig;
}

namespace mistfall::detail {

// Short rendering of any value for error messages.
std::string show(const toml::node& n);

// Interval with open/closed ends; `hi_name` names the key the upper bound comes from, if any.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  std::string hi_name{};
  bool contains(double v) const;  // false for NaN
  std::string text() const;
};

// A value looked up by key; `node` is null when the key is absent.
struct Field {
  const toml::node* node;
  std::string path;
};

std::string join(const std::string& path, std::string_view key);

// Parses TOML text; a syntax error is a CaseError naming the line and column.
toml::table parseToml(std::string_view text, const std::string& source);

class Reader {
 public:
  explicit Reader(std::string source) : src_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& msg) const;
  [[noreturn]] void missing(const Field& f, const std::string& allowed) const;
  [[noreturn]] void wrongType(const Field& f, const std::string& allowed) const;
  [[noreturn]] void outOfRange(const std::string& path, const std::string& value, const std::string& allowed) const;

  // Rejects keys of `t` not in `allowed`, suggesting the closest valid key (edit distance <= 2).
  void checkKeys(const toml::table& t, const std::string& path, std::initializer_list<std::string_view> allowed) const;

  Field field(const toml::table& t, const std::string& path, std::string_view key) const {
    return {t.get(key), join(path, key)};
  }

  // Sub-table (an absent one reads as empty, so its required keys report their full path).
  const toml::table& table(const toml::table& t, const std::string& path, std::string_view key) const;

  double toNumber(const Field& f, const std::string& allowed) const;

  void number(const toml::table& t, const std::string& path, std::string_view key, const Range& r, double& out,
              bool required = false) const;

  void integer(const toml::table& t, const std::string& path, std::string_view key, std::int64_t lo,
               std::int64_t hi, const std::string& allowed, int& out, bool required = false) const;

  std::string string(const Field& f, const std::string& allowed) const;

  // true or false; leaves `out` unchanged when the key is absent.
  void boolean(const toml::table& t, const std::string& path, std::string_view key, bool& out) const;

  // One of `choices`; returns the index of the choice, or -1 when the key is absent.
  int choice(const toml::table& t, const std::string& path, std::string_view key,
             std::initializer_list<std::string_view> choices) const;

  // Array of exactly `dim` finite numbers; returns false when absent and not required.
  bool vector(const toml::table& t, const std::string& path, std::string_view key, int dim,
              std::array<double, 3>& out, bool required = false) const;

 private:
  std::string src_;
};

// The [[inflow]] and [[outflow]] tables (case_boundaries.cpp); needs the domain, gravity and regions already read.
void readOpenBoundaries(const Reader& rd, const toml::table& root, CaseConfig& c);

// The optional [texture] table (case_texture.cpp); needs [numerics] and [output] already read.
void readTexture(const Reader& rd, const toml::table& root, CaseConfig& c);

// The optional [render] table (case_render.cpp); needs [domain], [numerics] and [texture] already read.
void readRender(const Reader& rd, const toml::table& root, CaseConfig& c);

}  // namespace mistfall::detail
