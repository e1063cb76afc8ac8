// Particle count and memory of a case from its regions' volumes (see case_size.hpp).
//
// Per-particle peak memory of `simulate`, measured (peak RSS, /usr/bin/time, one thread, first steps):
//   2D, mostly fluid: waterfall.toml, 32,096 particles, 100 MB; waterfall_small.toml, 8,024, 62 MB: 1.5 KB a particle
//   2D, mostly walls: dam_break.toml at l0 = 0.5 mm, 80,000 fluid and 72,448 wall/dummy, 236 MB: 1.2 KB a particle
//   3D, mostly fluid: a 0.3 m water cube at l0 = 5 mm, 216,000 fluid and 18,496 wall/dummy, 1.71 GB: 7.1 KB
//   3D, mostly walls: dam_break_3d.toml at l0 = 3 mm, 16,000 fluid and 88,896 wall/dummy, 228 MB: 1.7 KB
// above a base of about 50 MB (libraries). The estimate rounds these up: a fluid particle 2 KB (2D) or 8 KB (3D),
// a wall or dummy particle 1 KB (2D) or 1.5 KB (3D), plus 64 MB.
#include "case/case_size.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "io/errors.hpp"

namespace mistfall {

namespace {

constexpr double kBase = 64e6;
constexpr double kFluid2 = 2e3, kFluid3 = 8e3, kSolid2 = 1e3, kSolid3 = 1.5e3;

double regionPoints(const CaseConfig& c, const Region& r) {
  const double boxed = static_cast<double>(countLatticePoints(c, r.box));  // O(1): index ranges
  if (r.shape == RegionShape::Box) return boxed;
  const double l0 = c.numerics.particle_spacing;
  const double round = c.dimension == 2 ? std::numbers::pi * r.radius * r.radius / (l0 * l0)
                                        : 4.0 / 3.0 * std::numbers::pi * std::pow(r.radius / l0, 3);
  return std::min(boxed, round);
}

// A number read from the first line of `file` ("max" or unreadable: nullopt).
std::optional<double> readNumber(const char* file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word)) return std::nullopt;
  try {
    std::size_t used = 0;
    const double v = std::stod(word, &used);
    if (used != word.size()) return std::nullopt;
    return v;
  } catch (...) {
    return std::nullopt;
  }
}

}  // namespace

CaseSize estimateCaseSize(const CaseConfig& c) {
  double domain = 1.0;
  for (int k = 0; k < c.dimension; ++k) domain *= static_cast<double>(domainLatticeCount(c, k));
  CaseSize s;
  for (const Region& r : c.regions) (r.material == Material::Wall ? s.solid : s.fluid) += regionPoints(c, r);
  for (const Inflow& in : c.inflows) s.fluid += static_cast<double>(countLatticePoints(c, in.box));
  s.fluid = std::min(s.fluid, domain);
  s.solid = std::min(s.solid, domain);
  const bool two = c.dimension == 2;
  s.bytes = kBase + s.fluid * (two ? kFluid2 : kFluid3) + s.solid * (two ? kSolid2 : kSolid3);
  return s;
}

std::optional<double> availableMemory() {
  std::optional<double> available;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double value = 0.0;
  std::string unit;
  while (meminfo >> key >> value >> unit)
    if (key == "MemAvailable:") {
      available = value * 1024.0;  // kB
      break;
    }
  const auto limit = readNumber("/sys/fs/cgroup/memory.max");
  const auto used = readNumber("/sys/fs/cgroup/memory.current");
  if (limit && used) {
    const double left = std::max(0.0, *limit - *used);
    available = available ? std::min(*available, left) : left;
  }
  return available;
}

std::string formatBytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char buf[64];
  std::snprintf(buf, sizeof buf, bytes < 10.0 && u > 0 ? "%.1f %s" : "%.0f %s", bytes, units[u]);
  return buf;
}

void checkCaseFitsInMemory(const CaseConfig& c, const std::string& source_name) {
  const CaseSize s = estimateCaseSize(c);
  const auto available = availableMemory();
  if (!available || s.bytes <= *available) return;
  std::ostringstream msg;
  auto count = [](double n) { return detail::formatNumber(std::round(n)); };
  msg << source_name << ": the case needs about " << count(s.fluid + s.solid) << " particles (" << count(s.fluid)
      << " water and gas, " << count(s.solid) << " wall, from the regions' volumes at numerics.particle_spacing = "
      << detail::formatNumber(c.numerics.particle_spacing) << ") and about " << formatBytes(s.bytes)
      << " of memory, but " << formatBytes(*available)
      << " is available (MemAvailable in /proc/meminfo); refused before anything is written: use a larger "
         "numerics.particle_spacing or smaller regions";
  throw ResourceError(msg.str());
}

}  // namespace mistfall
