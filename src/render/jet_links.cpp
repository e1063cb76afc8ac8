// Links between consecutive particles of a jet (see jet_links.hpp).
#include "render/jet_links.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace mistfall {

std::vector<SectionLink> jetLinks(const std::vector<Vec<2>>& x, const std::vector<Vec<2>>& u,
                                  const JetLinkParameters& p) {
  if (!(p.spacing > 0.0)) throw std::invalid_argument("jetLinks: particle spacing must be > 0");
  if (x.size() != u.size()) throw std::invalid_argument("jetLinks: positions and velocities differ in number");
  const double reach = p.max_length * p.spacing, cos_max = std::cos(p.max_angle * M_PI / 180.0);
  auto key = [reach](const Vec<2>& v) {
    const auto i = static_cast<std::int64_t>(std::floor(v.x() / reach));
    const auto j = static_cast<std::int64_t>(std::floor(v.y() / reach));
    return (i << 32) ^ (j & 0xffffffff);
  };
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  for (std::size_t i = 0; i < x.size(); ++i) cells[key(x[i])].push_back(static_cast<int>(i));
  std::vector<SectionLink> links;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double speed = u[i].norm();
    if (speed < p.min_speed) continue;
    const Vec<2> dir = u[i] / speed;
    // The nearest `per_particle` particles ahead of i that move the same way.
    std::vector<std::pair<double, int>> ahead;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        const auto it = cells.find(key(x[i] + Vec<2>(di * reach, dj * reach)));
        if (it == cells.end()) continue;
        for (int j : it->second) {
          const Vec<2> d = x[j] - x[i];
          const double len = d.norm();
          if (j == static_cast<int>(i) || len <= 0.0 || len > reach) continue;
          const double uj = u[j].norm();
          if (d.dot(dir) < cos_max * len || uj <= 0.0 || u[j].dot(dir) < cos_max * uj) continue;
          ahead.emplace_back(len, j);
        }
      }
    std::sort(ahead.begin(), ahead.end());
    if (ahead.size() > static_cast<std::size_t>(p.per_particle)) ahead.resize(p.per_particle);
    for (const auto& [len, j] : ahead) {
      const double r = std::clamp(p.spacing * p.spacing / (2.0 * len), p.min_radius * p.spacing,
                                  p.max_radius * p.spacing);
      links.push_back({x[i], x[j], r, static_cast<int>(i), j});
    }
  }
  return links;
}

}  // namespace mistfall
