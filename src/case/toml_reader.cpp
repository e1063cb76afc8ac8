// Checked access to the TOML tree of a case file: typed look-ups, ranges and error messages.
#include "case/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "case/case_file.hpp"

namespace mistfall::detail {
namespace {

std::string fmt(double v) { return formatNumber(v); }

std::string typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::array: return "array";
    case toml::node_type::table: return "table";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    default: return "none";
  }
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string show(const toml::node& n) {
  if (auto s = n.as_string()) return "\"" + s->get() + "\"";
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (auto f = n.as_floating_point()) return fmt(f->get());
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  if (auto a = n.as_array()) {
    std::string s = "[";
    for (std::size_t i = 0; i < a->size(); ++i) s += (i ? ", " : "") + show((*a)[i]);
    return s + "]";
  }
  if (auto t = n.as_table()) {
    std::string s = "{";
    bool first = true;
    for (auto&& [k, v] : *t) {
      s += (first ? "" : ", ") + std::string(k.str()) + " = " + show(v);
      first = false;
    }
    return s + "}";
  }
  std::ostringstream os;
  if (auto d = n.as_date()) os << d->get();
  else if (auto t = n.as_time()) os << t->get();
  else if (auto dt = n.as_date_time()) os << dt->get();
  return os.str();
}

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::text() const {
  return std::string(lo_open ? "(" : "[") + fmt(lo) + ", " + (hi_name.empty() ? "" : hi_name + " = ") + fmt(hi) +
         (hi_open ? ")" : "]");
}

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

toml::table parseToml(std::string_view text, const std::string& source) {
#if TOML_EXCEPTIONS
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw CaseError(source + ": TOML syntax error at line " + std::to_string(where.line) + ", column " +
                    std::to_string(where.column) + ": " + std::string(e.description()));
  }
#else
  toml::parse_result r = toml::parse(text, source);
  if (!r) {
    const auto& where = r.error().source().begin;
    throw CaseError(source + ": TOML syntax error at line " + std::to_string(where.line) + ", column " +
                    std::to_string(where.column) + ": " + std::string(r.error().description()));
  }
  return std::move(r).table();
#endif
}

void Reader::fail(const std::string& msg) const { throw CaseError(src_ + ": " + msg); }

void Reader::missing(const Field& f, const std::string& allowed) const {
  fail("missing required key " + f.path + "; allowed " + allowed);
}

void Reader::wrongType(const Field& f, const std::string& allowed) const {
  fail(f.path + " = " + show(*f.node) + " has the wrong type (" + typeName(*f.node) + "); allowed " + allowed);
}

void Reader::outOfRange(const std::string& path, const std::string& value, const std::string& allowed) const {
  fail(path + " = " + value + " is out of range; allowed " + allowed);
}

void Reader::checkKeys(const toml::table& t, const std::string& path,
                       std::initializer_list<std::string_view> allowed) const {
  for (auto&& [k, v] : t) {
    const std::string_view key = k.str();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string msg = "unknown key " + join(path, key);
    std::string_view best;
    std::size_t best_d = 3;
    for (auto a : allowed) {
      const std::size_t d = editDistance(key, a);
      if (d < best_d) best_d = d, best = a;
    }
    if (!best.empty()) msg += "; did you mean '" + std::string(best) + "'?";
    msg += best.empty() ? "; " : " ";
    const std::string table = path.rfind("region[", 0) == 0 ? "[[region]]" : "[" + path + "]";
    msg += path.empty() ? "allowed top-level keys: " : "allowed keys in " + table + ": ";
    bool first = true;
    for (auto a : allowed) msg += (first ? "" : ", ") + std::string(a), first = false;
    fail(msg);
  }
}

const toml::table& Reader::table(const toml::table& t, const std::string& path, std::string_view key) const {
  static const toml::table empty;
  Field f = field(t, path, key);
  if (!f.node) return empty;
  if (!f.node->is_table()) wrongType(f, "a table [" + f.path + "]");
  return *f.node->as_table();
}

double Reader::toNumber(const Field& f, const std::string& allowed) const {
  if (auto i = f.node->as_integer()) return static_cast<double>(i->get());
  if (auto d = f.node->as_floating_point()) return d->get();
  wrongType(f, allowed);
}

void Reader::number(const toml::table& t, const std::string& path, std::string_view key, const Range& r,
                    double& out, bool required) const {
  Field f = field(t, path, key);
  if (!f.node) {
    if (required) missing(f, "a number in " + r.text());
    return;
  }
  const double v = toNumber(f, "a number in " + r.text());
  if (!r.contains(v)) outOfRange(f.path, show(*f.node), r.text());
  out = v;
}

void Reader::integer(const toml::table& t, const std::string& path, std::string_view key, std::int64_t lo,
                     std::int64_t hi, const std::string& allowed, int& out, bool required) const {
  Field f = field(t, path, key);
  if (!f.node) {
    if (required) missing(f, allowed);
    return;
  }
  const double v = toNumber(f, "an integer " + allowed);
  if (v != std::floor(v)) wrongType(f, "an integer " + allowed);
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi))) outOfRange(f.path, show(*f.node), allowed);
  out = static_cast<int>(v);
}

std::string Reader::string(const Field& f, const std::string& allowed) const {
  if (auto s = f.node->as_string()) return s->get();
  wrongType(f, allowed);
}

void Reader::boolean(const toml::table& t, const std::string& path, std::string_view key, bool& out) const {
  Field f = field(t, path, key);
  if (!f.node) return;
  if (auto b = f.node->as_boolean()) {
    out = b->get();
    return;
  }
  wrongType(f, "true or false");
}

int Reader::choice(const toml::table& t, const std::string& path, std::string_view key,
                   std::initializer_list<std::string_view> choices) const {
  Field f = field(t, path, key);
  if (!f.node) return -1;
  std::string allowed;
  for (auto c : choices) allowed += (allowed.empty() ? "\"" : " or \"") + std::string(c) + "\"";
  const std::string s = string(f, allowed);
  const auto it = std::find(choices.begin(), choices.end(), s);
  if (it == choices.end()) fail(f.path + " = \"" + s + "\" is not allowed; allowed " + allowed);
  return static_cast<int>(it - choices.begin());
}

bool Reader::vector(const toml::table& t, const std::string& path, std::string_view key, int dim,
                    std::array<double, 3>& out, bool required) const {
  Field f = field(t, path, key);
  const std::string allowed =
      "an array of exactly " + std::to_string(dim) + " numbers (case.dimension = " + std::to_string(dim) + ")";
  if (!f.node) {
    if (required) missing(f, allowed);
    return false;
  }
  const toml::array* a = f.node->as_array();
  if (!a) wrongType(f, allowed);
  if (a->size() != static_cast<std::size_t>(dim))
    fail(f.path + " = " + show(*f.node) + " has " + std::to_string(a->size()) + " elements; allowed " + allowed);
  std::array<double, 3> v{0.0, 0.0, 0.0};
  for (int k = 0; k < dim; ++k) {
    Field e{&(*a)[static_cast<std::size_t>(k)], f.path + "[" + std::to_string(k) + "]"};
    v[k] = toNumber(e, "a number");
    if (!std::isfinite(v[k])) outOfRange(e.path, show(*e.node), "a finite number");
  }
  out = v;
  return true;
}

}  // namespace mistfall::detail
