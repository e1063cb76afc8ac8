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
    const auto i = static_cast<std::int64_t>(std::floor(v.x() / reach)), j = static_cast<std::int64_t>(std::floor(v.y() / reach));
    return (i << 32) ^ (j & 0xffffffff);
  };
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  for (std::size_t i = 0; i < x.size(); ++i) cells[key(x[i])].push_back(static_cast<int>(i));
  std::vector<SectionLink> links;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double speed = u[i].norm();
    if (speed < p.min_speed) continue;
    const Vec<2> dir = u[i] / speed;
    int best = -1;
    double best_d = reach;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        const auto it = cells.find(key(x[i] + Vec<2>(di * reach, dj * reach)));
        if (it == cells.end()) continue;
        for (int j : it->second) {
          const Vec<2> d = x[j] - x[i];
          const double len = d.norm();
          if (j == static_cast<int>(i) || len <= 0.0 || len > best_d) continue;
          const double uj = u[j].norm();
          if (d.dot(dir) < cos_max * len || uj <= 0.0 || u[j].dot(dir) < cos_max * uj) continue;
          best = j, best_d = len;
        }
      }
    if (best < 0) continue;
    const double r = std::clamp(p.spacing * p.spacing / (2.0 * best_d), p.min_radius * p.spacing,
                                p.max_radius * p.spacing);
    links.push_back({x[i], x[best], r, static_cast<int>(i), best});
  }
  return links;
}

}  // namespace mistfall
