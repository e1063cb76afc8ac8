// Proximity tracking of isolated particles between frames (see source_tracker.hpp).
#include "texture/source_tracker.hpp"

#include <cmath>
#include <unordered_map>

namespace mistfall {

namespace {

std::uint64_t cellKey(const Vec3& x, double cell) {
  const auto c = [&](int a) { return static_cast<std::uint64_t>(std::floor(x[a] / cell) + (1 << 20)) & 0x1fffff; };
  return c(0) | (c(1) << 21) | (c(2) << 42);
}

}  // namespace

std::vector<SourceBirth> IsolatedParticleTracker::update(const std::vector<Vec3>& position,
                                                         const std::vector<Vec3>& velocity,
                                                         const std::vector<std::uint8_t>& category, double time) {
  // Last frame's isolated particles, advanced to this frame's time, binned in cells of the match radius.
  const double elapsed = time - time_;
  std::vector<Vec3> predicted(previous_.size());
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t p = 0; p < previous_.size(); ++p) {
    predicted[p] = previous_[p].position + previous_[p].velocity * elapsed;
    cells[cellKey(predicted[p], match_radius_)].push_back(p);
  }
  std::vector<char> taken(previous_.size(), 0);
  std::vector<SourceBirth> births;
  std::vector<Isolated> current;
  for (std::size_t i = 0; i < position.size(); ++i) {
    const std::uint8_t c = category[i];
    if (c != kCategoryDroplet && c != kCategoryBubble) continue;
    current.push_back({position[i], velocity[i], c});
    std::size_t best = previous_.size();
    double best_distance = match_radius_;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Vec3 probe = position[i] + match_radius_ * Vec3(dx, dy, dz);
          const auto it = cells.find(cellKey(probe, match_radius_));
          if (it == cells.end()) continue;
          for (std::size_t p : it->second) {
            const double d = (predicted[p] - position[i]).norm();
            if (!taken[p] && previous_[p].category == c && d < best_distance) best = p, best_distance = d;
          }
        }
    if (best < previous_.size()) {
      taken[best] = 1;
      continue;
    }
    births.push_back({c == kCategoryDroplet ? TextureKind::Droplet : TextureKind::Bubble, position[i], velocity[i]});
  }
  previous_ = std::move(current);
  time_ = time;
  return births;
}

}  // namespace mistfall
