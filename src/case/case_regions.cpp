// Geometry checks of the [[region]] entries of a case: each box well formed, inside the domain and holding
// at least one lattice point; water regions overlap nothing; at least one water region exists.
// Also the number formatting shared by all case-file error messages.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"

namespace mistfall::detail {
namespace {

std::string num(double v) { return formatNumber(v); }

std::string vec(const std::array<double, 3>& v, int dim) {
  std::string s = "[";
  for (int k = 0; k < dim; ++k) s += (k ? ", " : "") + num(v[k]);
  return s + "]";
}

std::string label(const CaseConfig& c, std::size_t i) {
  return "region[" + std::to_string(i) + "] (\"" + c.regions[i].name + "\")";
}

bool overlap(const Box& a, const Box& b, int dim, double tol) {
  for (int k = 0; k < dim; ++k)
    if (std::min(a.max[k], b.max[k]) - std::max(a.min[k], b.min[k]) <= tol) return false;
  return true;
}

}  // namespace

std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const double a = std::fabs(v);
  const bool fixed = a == 0.0 || (a >= 1e-4 && a < 1e6);
  auto res = std::to_chars(buf, buf + sizeof buf, v, fixed ? std::chars_format::fixed : std::chars_format::scientific);
  // Tidy the exponent: "1e+05" -> "1e5", "1e-08" -> "1e-8".
  std::string s;
  bool in_exp = false, leading = false;
  for (const char* p = buf; p < res.ptr; ++p) {
    const char ch = *p;
    if (ch == 'e') {
      in_exp = leading = true;
      s.push_back(ch);
    } else if (in_exp && ch == '+') {
      continue;
    } else if (in_exp && leading && ch == '0' && p + 1 < res.ptr) {
      continue;
    } else {
      if (ch != '-') leading = false;
      s.push_back(ch);
    }
  }
  return s;
}

void validateRegions(const CaseConfig& c, const std::string& source) {
  auto fail = [&](const std::string& msg) { throw CaseError(source + ": " + msg); };
  const int dim = c.dimension;
  const double l0 = c.numerics.particle_spacing;
  const double tol = 1e-9 * l0;
  bool any_water = false;

  for (std::size_t i = 0; i < c.regions.size(); ++i) {
    const Region& r = c.regions[i];
    const std::string p = "region[" + std::to_string(i) + "]";
    any_water = any_water || r.material == Material::Water;
    for (int k = 0; k < dim; ++k) {
      std::string ax = "[";  // (built by appending: GCC 12 warns falsely on "[" + to_string)
      ax += std::to_string(k);
      ax += ']';
      if (!(r.box.max[k] > r.box.min[k]))
        fail(p + ".max" + ax + " = " + num(r.box.max[k]) + " is not greater than " + p + ".min" + ax + " = " +
             num(r.box.min[k]) + "; allowed " + p + ".max > " + p + ".min on every axis");
      const std::string within = "; allowed [" + num(c.domain.min[k]) + ", " + num(c.domain.max[k]) +
                                 "] (domain.min" + ax + " to domain.max" + ax + "): regions must lie inside the domain";
      if (r.box.min[k] < c.domain.min[k] - tol)
        fail(p + ".min" + ax + " = " + num(r.box.min[k]) + " lies outside the domain" + within);
      if (r.box.max[k] > c.domain.max[k] + tol)
        fail(p + ".max" + ax + " = " + num(r.box.max[k]) + " lies outside the domain" + within);
    }
    if (countLatticePoints(c, r.box) == 0)
      fail(label(c, i) + " is empty: " + p + ".min = " + vec(r.box.min, dim) + ", " + p + ".max = " +
           vec(r.box.max, dim) + " contains no lattice point; allowed a box holding at least one point " +
           "domain.min + (i + 0.5) * l0 with l0 = numerics.particle_spacing = " + num(l0));
  }

  for (std::size_t i = 0; i < c.regions.size(); ++i)
    for (std::size_t j = i + 1; j < c.regions.size(); ++j) {
      const bool water = c.regions[i].material == Material::Water || c.regions[j].material == Material::Water;
      if (water && overlap(c.regions[i].box, c.regions[j].box, dim, tol))
        fail(label(c, j) + " overlaps " + label(c, i) +
             "; allowed: a water region must not overlap any other region (wall regions may overlap each other)");
    }

  if (!any_water)
    fail("region: no region has material = \"water\"; allowed at least one [[region]] with material = \"water\"");
}

}  // namespace mistfall::detail
