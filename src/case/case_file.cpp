// Case file reader: parses TOML with toml++, checks every key against the layout in docs/case-file.md and
// fills a CaseConfig. Errors name the file, the key path, the offending value and what is allowed.
#include "case/case_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <system_error>
#include <vector>

#include <toml++/toml.h>

#include "case/scene.hpp"

namespace mistfall {
namespace {

std::string fmt(double v) { return detail::formatNumber(v); }

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

// Short rendering of any value for error messages.
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

// Interval with open/closed ends; `hi_name` names the key the upper bound comes from, if any.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  std::string hi_name{};
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);  // false for NaN
  }
  std::string text() const {
    return std::string(lo_open ? "(" : "[") + fmt(lo) + ", " + (hi_name.empty() ? "" : hi_name + " = ") +
           fmt(hi) + (hi_open ? ")" : "]");
  }
};

// A value looked up by key; `node` is null when the key is absent.
struct Field {
  const toml::node* node;
  std::string path;
};

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

class Reader {
 public:
  explicit Reader(std::string source) : src_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& msg) const { throw CaseError(src_ + ": " + msg); }

  [[noreturn]] void missing(const Field& f, const std::string& allowed) const {
    fail("missing required key " + f.path + "; allowed " + allowed);
  }
  [[noreturn]] void wrongType(const Field& f, const std::string& allowed) const {
    fail(f.path + " = " + show(*f.node) + " has the wrong type (" + typeName(*f.node) + "); allowed " + allowed);
  }
  [[noreturn]] void outOfRange(const std::string& path, const std::string& value, const std::string& allowed) const {
    fail(path + " = " + value + " is out of range; allowed " + allowed);
  }

  // Rejects keys of `t` not in `allowed`, suggesting the closest valid key (edit distance <= 2).
  void checkKeys(const toml::table& t, const std::string& path, std::initializer_list<std::string_view> allowed) const {
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

  Field field(const toml::table& t, const std::string& path, std::string_view key) const {
    return {t.get(key), join(path, key)};
  }

  // Sub-table (an absent one reads as empty, so its required keys report their full path).
  const toml::table& table(const toml::table& t, const std::string& path, std::string_view key) const {
    static const toml::table empty;
    Field f = field(t, path, key);
    if (!f.node) return empty;
    if (!f.node->is_table()) wrongType(f, "a table [" + f.path + "]");
    return *f.node->as_table();
  }

  double toNumber(const Field& f, const std::string& allowed) const {
    if (auto i = f.node->as_integer()) return static_cast<double>(i->get());
    if (auto d = f.node->as_floating_point()) return d->get();
    wrongType(f, allowed);
  }

  void number(const toml::table& t, const std::string& path, std::string_view key, const Range& r, double& out,
              bool required = false) const {
    Field f = field(t, path, key);
    if (!f.node) {
      if (required) missing(f, "a number in " + r.text());
      return;
    }
    const double v = toNumber(f, "a number in " + r.text());
    if (!r.contains(v)) outOfRange(f.path, show(*f.node), r.text());
    out = v;
  }

  void integer(const toml::table& t, const std::string& path, std::string_view key, std::int64_t lo,
               std::int64_t hi, const std::string& allowed, int& out, bool required = false) const {
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

  std::string string(const Field& f, const std::string& allowed) const {
    if (auto s = f.node->as_string()) return s->get();
    wrongType(f, allowed);
  }

  // One of `choices`; returns the index of the choice, or -1 when the key is absent.
  int choice(const toml::table& t, const std::string& path, std::string_view key,
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

  // Array of exactly `dim` finite numbers; returns false when absent and not required.
  bool vector(const toml::table& t, const std::string& path, std::string_view key, int dim,
              std::array<double, 3>& out, bool required = false) const {
    Field f = field(t, path, key);
    const std::string allowed = "an array of exactly " + std::to_string(dim) + " numbers (case.dimension = " +
                                std::to_string(dim) + ")";
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

 private:
  std::string src_;
};

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

}  // namespace

CaseConfig parseCase(std::string_view toml_text, const std::string& source_name) {
  const toml::table root = parseToml(toml_text, source_name);
  const Reader rd(source_name);
  CaseConfig c;
  rd.checkKeys(root, "", {"case", "domain", "physics", "numerics", "output", "region"});

  // [case]
  const toml::table& cs = rd.table(root, "", "case");
  rd.checkKeys(cs, "case", {"name", "dimension"});
  {
    Field f = rd.field(cs, "case", "name");
    if (!f.node) rd.missing(f, "a non-empty string");
    c.name = rd.string(f, "a non-empty string");
    if (c.name.empty()) rd.fail(f.path + " = \"\" is empty; allowed a non-empty string");
  }
  rd.integer(cs, "case", "dimension", 2, 3, "2 or 3", c.dimension, true);
  const int dim = c.dimension;

  // [domain]
  const toml::table& dm = rd.table(root, "", "domain");
  rd.checkKeys(dm, "domain", {"min", "max"});
  rd.vector(dm, "domain", "min", dim, c.domain.min, true);
  rd.vector(dm, "domain", "max", dim, c.domain.max, true);
  for (int k = 0; k < dim; ++k)
    if (!(c.domain.max[k] > c.domain.min[k]))
      rd.outOfRange("domain.max[" + std::to_string(k) + "]", fmt(c.domain.max[k]),
                    "> domain.min[" + std::to_string(k) + "] = " + fmt(c.domain.min[k]));

  // [physics]
  const toml::table& ph = rd.table(root, "", "physics");
  rd.checkKeys(ph, "physics", {"gravity", "liquid"});
  c.physics.gravity = {0.0, 0.0, 0.0};
  c.physics.gravity[static_cast<std::size_t>(dim - 1)] = -9.81;  // vertical axis is the last one
  rd.vector(ph, "physics", "gravity", dim, c.physics.gravity);
  const toml::table& lq = rd.table(ph, "physics", "liquid");
  rd.checkKeys(lq, "physics.liquid", {"density", "kinematic_viscosity", "sound_speed"});
  rd.number(lq, "physics.liquid", "density", {0.0, 1e5, true, false}, c.physics.liquid.density);
  rd.number(lq, "physics.liquid", "kinematic_viscosity", {0.0, 1.0, false, false},
            c.physics.liquid.kinematic_viscosity);
  if (Field f = rd.field(lq, "physics.liquid", "sound_speed"); f.node) {
    const std::string allowed = "a number > 0 or the string \"inf\"";
    if (f.node->is_string()) {
      if (f.node->as_string()->get() != "inf") rd.fail(f.path + " = " + show(*f.node) + " is not allowed; allowed " + allowed);
      c.physics.liquid.sound_speed = std::numeric_limits<double>::infinity();
    } else {
      const double v = rd.toNumber(f, allowed);
      if (!(v > 0.0)) rd.outOfRange(f.path, show(*f.node), allowed);
      c.physics.liquid.sound_speed = v;
    }
  }

  // [numerics]
  const std::string np = "numerics";
  const toml::table& nm = rd.table(root, "", np);
  rd.checkKeys(nm, np,
               {"particle_spacing", "radius_number_density", "radius_laplacian", "courant", "dt_max", "dt_min",
                "surface_threshold", "collision_distance", "collision_restitution", "pressure_source", "source_relaxation", "pressure_solver",
                "solver_tolerance", "solver_max_iterations", "max_escaped_fraction"});
  NumericsConfig& n = c.numerics;
  rd.number(nm, np, "particle_spacing", {0.0, 10.0, true, false}, n.particle_spacing, true);
  rd.number(nm, np, "radius_number_density", {1.5, 5.0, false, false}, n.radius_number_density);
  rd.number(nm, np, "radius_laplacian", {1.5, 5.0, false, false}, n.radius_laplacian);
  rd.number(nm, np, "courant", {0.0, 1.0, true, false}, n.courant);
  rd.number(nm, np, "dt_max", {0.0, 1.0, true, false}, n.dt_max);
  rd.number(nm, np, "dt_min", {0.0, n.dt_max, true, true, "numerics.dt_max"}, n.dt_min);
  rd.number(nm, np, "surface_threshold", {0.0, 1.0, true, true}, n.surface_threshold);
  rd.number(nm, np, "collision_distance", {0.0, 1.0, false, true}, n.collision_distance);
  rd.number(nm, np, "collision_restitution", {0.0, 1.0, false, false}, n.collision_restitution);
  if (int s = rd.choice(nm, np, "pressure_source", {"standard", "mixed"}); s >= 0)
    n.pressure_source = s == 0 ? PressureSource::Standard : PressureSource::Mixed;
  rd.number(nm, np, "source_relaxation", {0.0, 1.0, true, false}, n.source_relaxation);
  if (int s = rd.choice(nm, np, "pressure_solver", {"iccg", "amg"}); s >= 0)
    n.pressure_solver = s == 0 ? PressureSolverKind::EigenIccg : PressureSolverKind::HypreAmg;
  rd.number(nm, np, "solver_tolerance", {0.0, 1e-2, true, false}, n.solver_tolerance);
  rd.integer(nm, np, "solver_max_iterations", 1, 100000, "[1, 100000]", n.solver_max_iterations);
  rd.number(nm, np, "max_escaped_fraction", {0.0, 1.0, true, false}, n.max_escaped_fraction);
  for (int k = 0; k < dim; ++k) {
    const double cells = (c.domain.max[k] - c.domain.min[k]) / n.particle_spacing;
    if (!(cells <= static_cast<double>(kMaxLatticeIndex)))
      rd.outOfRange("numerics.particle_spacing", fmt(n.particle_spacing),
                    "a spacing giving at most " + std::to_string(kMaxLatticeIndex) +
                        " lattice points along each domain axis (axis " + std::to_string(k) + " has " +
                        fmt(std::floor(cells)) + ")");
  }

  // [output]
  const toml::table& out = rd.table(root, "", "output");
  rd.checkKeys(out, "output", {"end_time", "interval"});
  rd.number(out, "output", "end_time", {0.0, 1e4, true, false}, c.output.end_time, true);
  rd.number(out, "output", "interval", {0.0, c.output.end_time, true, false, "output.end_time"}, c.output.interval);

  // [[region]]
  Field rf = rd.field(root, "", "region");
  const std::string regions_allowed = "an array of tables written as [[region]], at least one with material = \"water\"";
  if (!rf.node) rd.missing(rf, regions_allowed);
  if (!rf.node->is_array_of_tables() || rf.node->as_array()->empty()) rd.wrongType(rf, regions_allowed);
  const toml::array& ra = *rf.node->as_array();
  for (std::size_t i = 0; i < ra.size(); ++i) {
    const toml::table& t = *ra[i].as_table();
    const std::string p = "region[" + std::to_string(i) + "]";
    rd.checkKeys(t, p, {"name", "material", "min", "max", "velocity"});
    Region r;
    Field nf = rd.field(t, p, "name");
    if (!nf.node) rd.missing(nf, "a non-empty unique string");
    r.name = rd.string(nf, "a non-empty unique string");
    if (r.name.empty()) rd.fail(nf.path + " = \"\" is empty; allowed a non-empty unique string");
    for (std::size_t j = 0; j < c.regions.size(); ++j)
      if (c.regions[j].name == r.name)
        rd.fail(nf.path + " = \"" + r.name + "\" duplicates region[" + std::to_string(j) +
                "].name; allowed unique region names");
    if (rd.choice(t, p, "material", {"water", "wall"}) == 1) r.material = Material::Wall;
    rd.vector(t, p, "min", dim, r.box.min, true);
    rd.vector(t, p, "max", dim, r.box.max, true);
    if (Field vf = rd.field(t, p, "velocity"); vf.node && r.material == Material::Wall)
      rd.fail(vf.path + " = " + show(*vf.node) + " is not allowed for material = \"wall\"; allowed only in water regions");
    rd.vector(t, p, "velocity", dim, r.initial_velocity);
    c.regions.push_back(std::move(r));
  }
  detail::validateRegions(c, source_name);
  return c;
}

CaseConfig loadCaseFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CaseError(name + ": case file does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw CaseError(name + ": case file is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(name + ": cannot open case file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError(name + ": error while reading case file");
  return parseCase(text.str(), name);
}

}  // namespace mistfall
