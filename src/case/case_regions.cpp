// Geometry checks of the [[region]] entries of a case: each box or circle well formed, inside the domain and
// holding at least one lattice point; a water region overlaps no other water or wall region; every water or
// gas region keeps at least one lattice point after overlaps are resolved; at least one water region exists.
// Also the number formatting shared by all case-file error messages.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_size.hpp"
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

// Whether the interiors of two regions (box or circle) intersect by more than `tol`; touching is no overlap.
bool overlap(const Region& a, const Region& b, int dim, double tol) {
  const bool ca = a.shape == RegionShape::Circle, cb = b.shape == RegionShape::Circle;
  if (!ca && !cb) return overlap(a.box, b.box, dim, tol);
  double d2 = 0.0;
  if (ca && cb) {
    for (int k = 0; k < dim; ++k) d2 += (a.center[k] - b.center[k]) * (a.center[k] - b.center[k]);
    return std::sqrt(d2) < a.radius + b.radius - tol;
  }
  const Region& circle = ca ? a : b;
  const Box& box = ca ? b.box : a.box;
  for (int k = 0; k < dim; ++k) {  // distance from the centre to the box
    const double d = circle.center[k] - std::clamp(circle.center[k], box.min[k], box.max[k]);
    d2 += d * d;
  }
  return std::sqrt(d2) < circle.radius - tol;
}

const char* materialName(Material m) {
  switch (m) {
    case Material::Water: return "water";
    case Material::Wall: return "wall";
    case Material::Gas: return "gas";
  }
  return "?";
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

namespace {

// Box regions: max > min on every axis, inside the domain.
void checkBox(const CaseConfig& c, std::size_t i, double tol, const std::function<void(const std::string&)>& fail) {
  const Region& r = c.regions[i];
  const std::string p = "region[" + std::to_string(i) + "]";
  for (int k = 0; k < c.dimension; ++k) {
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
}

// Circle regions: centre inside the domain, and the whole disc / sphere too.
void checkCircle(const CaseConfig& c, std::size_t i, double tol,
                 const std::function<void(const std::string&)>& fail) {
  const Region& r = c.regions[i];
  const std::string p = "region[" + std::to_string(i) + "]";
  for (int k = 0; k < c.dimension; ++k) {
    std::string ax = "[";
    ax += std::to_string(k);
    ax += ']';
    std::string range = "[";  // (appended, see checkBox)
    range += num(c.domain.min[k]) + ", " + num(c.domain.max[k]) + "] (domain.min" + ax + " to domain.max" + ax + ")";
    if (r.center[k] < c.domain.min[k] - tol || r.center[k] > c.domain.max[k] + tol)
      fail(p + ".center" + ax + " = " + num(r.center[k]) + " lies outside the domain; allowed " + range);
    const double lo = r.center[k] - r.radius, hi = r.center[k] + r.radius;
    if (lo < c.domain.min[k] - tol || hi > c.domain.max[k] + tol)
      fail(p + ".radius = " + num(r.radius) + " takes the " + (c.dimension == 2 ? "circle" : "sphere") +
           " outside the domain on axis " + std::to_string(k) + ": center" + ax + " -/+ radius = [" + num(lo) + ", " +
           num(hi) + "]; allowed a radius keeping it inside " + range);
  }
}

}  // namespace

void validateRegions(const CaseConfig& c, const std::string& source) {
  const std::function<void(const std::string&)> fail = [&](const std::string& msg) {
    throw CaseError(source + ": " + msg);
  };
  // First, whether the case fits in memory at all: the checks below visit every lattice point.
  checkCaseFitsInMemory(c, source);
  const int dim = c.dimension;
  const double l0 = c.numerics.particle_spacing;
  const double tol = 1e-9 * l0;
  bool any_water = false;

  for (std::size_t i = 0; i < c.regions.size(); ++i) {
    const Region& r = c.regions[i];
    const std::string p = "region[" + std::to_string(i) + "]";
    any_water = any_water || r.material == Material::Water;
    if (r.shape == RegionShape::Box) {
      checkBox(c, i, tol, fail);
    } else {
      checkCircle(c, i, tol, fail);
    }
    if (countLatticePoints(c, r) == 0) {
      const std::string where = r.shape == RegionShape::Box
                                    ? p + ".min = " + vec(r.box.min, dim) + ", " + p + ".max = " + vec(r.box.max, dim)
                                    : p + ".center = " + vec(r.center, dim) + ", " + p + ".radius = " + num(r.radius);
      fail(label(c, i) + " is empty: " + where + " contains no lattice point; allowed a " +
           (r.shape == RegionShape::Box ? "box" : "circle") + " holding at least one point " +
           "domain.min + (i + 0.5) * l0 with l0 = numerics.particle_spacing = " + num(l0));
    }
  }

  // Water must not overlap water or wall; gas may overlap anything (resolved below and in the scene).
  for (std::size_t i = 0; i < c.regions.size(); ++i)
    for (std::size_t j = i + 1; j < c.regions.size(); ++j) {
      const Material a = c.regions[i].material, b = c.regions[j].material;
      const bool water = (a == Material::Water && b != Material::Gas) || (b == Material::Water && a != Material::Gas);
      if (water && overlap(c.regions[i], c.regions[j], dim, tol))
        fail(label(c, j) + " overlaps " + label(c, i) + " (" + materialName(b) + " and " + materialName(a) +
             "); allowed: a water region must not overlap another water region or a wall region (wall regions may "
             "overlap each other; gas regions may overlap any region)");
    }

  if (!any_water)
    fail("region: no region has material = \"water\"; allowed at least one [[region]] with material = \"water\"");

  const std::vector<std::size_t> kept = regionParticleCounts(c);
  for (std::size_t i = 0; i < c.regions.size(); ++i)
    if (c.regions[i].material != Material::Wall && kept[i] == 0)
      fail(label(c, i) + " contains no lattice point not taken by a wall region or by a later water or gas "
           "region (material = \"" + materialName(c.regions[i].material) + "\"); allowed a "
           "water or gas region that keeps at least one lattice point (walls always win; among water and gas "
           "regions the one declared last wins)");
}

}  // namespace mistfall::detail
