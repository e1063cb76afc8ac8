// The fingerprint of a case file and its comparison (see case_fingerprint.hpp).
#include "case/case_fingerprint.hpp"

#include <map>
#include <regex>
#include <sstream>

#include "case/case_file.hpp"
#include "case/toml_reader.hpp"

namespace mistfall {

namespace {

std::string value(const toml::node& n) {
  if (auto s = n.as_string()) {
    std::string out = "\"";
    for (char ch : s->get()) out += ch == '\n' ? std::string("\\n") : ch == '"' ? std::string("\\\"") : std::string(1, ch);
    return out + "\"";
  }
  if (auto i = n.as_integer()) return detail::formatNumber(static_cast<double>(i->get()));
  if (auto f = n.as_floating_point()) return detail::formatNumber(f->get());
  if (auto a = n.as_array()) {
    std::string s = "[";
    for (std::size_t k = 0; k < a->size(); ++k) s += (k ? ", " : "") + value((*a)[k]);
    return s + "]";
  }
  return detail::show(n);
}

void flatten(const toml::table& t, const std::string& prefix, std::map<std::string, std::string>& out) {
  for (auto&& [k, v] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (auto sub = v.as_table()) {
      flatten(*sub, key, out);
    } else if (v.is_array_of_tables()) {
      const toml::array& a = *v.as_array();
      for (std::size_t i = 0; i < a.size(); ++i) flatten(*a[i].as_table(), key + "[" + std::to_string(i) + "]", out);
    } else {
      out[key] = value(v);
    }
  }
}

std::map<std::string, std::string> parse(const std::string& fingerprint) {
  std::map<std::string, std::string> m;
  std::istringstream in(fingerprint);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t eq = line.find(" = ");
    if (eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return m;
}

}  // namespace

std::string caseFingerprint(std::string_view toml_text, const std::string& source_name) {
  std::map<std::string, std::string> keys;
  flatten(detail::parseToml(toml_text, source_name), "", keys);
  std::string s;
  for (const auto& [k, v] : keys) s += k + " = " + v + "\n";
  return s;
}

bool changesTheSimulation(std::string_view key) {
  static const std::regex harmless(
      R"((case\.name|output\.end_time|numerics\.dt_min|numerics\.max_escaped_fraction|(classify|texture|render)\..*|(region|inflow|outflow)\[[0-9]+\]\.name))");
  return !std::regex_match(key.begin(), key.end(), harmless);
}

std::vector<CaseChange> compareFingerprints(const std::string& before, const std::string& after) {
  const auto a = parse(before), b = parse(after);
  std::map<std::string, CaseChange> changes;
  for (const auto& [k, v] : a) {
    const auto it = b.find(k);
    if (it == b.end() || it->second != v) changes[k] = {k, v, it == b.end() ? "(absent)" : it->second, false};
  }
  for (const auto& [k, v] : b)
    if (!a.count(k)) changes[k] = {k, "(absent)", v, false};
  std::vector<CaseChange> out;
  for (auto& [k, c] : changes) {
    c.harmless = !changesTheSimulation(k);
    out.push_back(c);
  }
  return out;
}

std::string describe(const CaseChange& c) {
  return c.key + " = " + c.before + " in the checkpoint, " + c.after + " in case.toml";
}

}  // namespace mistfall
