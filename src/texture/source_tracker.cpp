// Following isolated particles between frames, by id or by proximity (see source_tracker.hpp).
#include "texture/source_tracker.hpp"

#include <cmath>
#include <unordered_set>

namespace mistfall {

namespace {

std::uint64_t cellKey(const Vec3& x, double cell) {
  const auto c = [&](int a) { return static_cast<std::uint64_t>(std::floor(x[a] / cell) + (1 << 20)) & 0x1fffff; };
  return c(0) | (c(1) << 21) | (c(2) << 42);
}

// An isolated particle's id and category in one key (categories are below 8).
std::uint64_t isolatedKey(std::uint64_t id, std::uint8_t category) { return id << 3 | category; }

}  // namespace

// The nearest not yet taken isolated particle of the previous frame of this category whose advanced position lies
// within the match radius; takes it.
bool IsolatedParticleTracker::matchesByProximity(const Vec3& position, std::uint8_t category, double elapsed) {
  if (predicted_.size() != previous_.size()) {  // first particle of this frame: bin the previous frame
    predicted_.resize(previous_.size());
    taken_.assign(previous_.size(), 0);
    cells_.clear();
    for (std::size_t p = 0; p < previous_.size(); ++p) {
      predicted_[p] = previous_[p].position + previous_[p].velocity * elapsed;
      cells_[cellKey(predicted_[p], match_radius_)].push_back(p);
    }
  }
  std::size_t best = previous_.size();
  double best_distance = match_radius_;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find(cellKey(position + match_radius_ * Vec3(dx, dy, dz), match_radius_));
        if (it == cells_.end()) continue;
        for (std::size_t p : it->second) {
          const double d = (predicted_[p] - position).norm();
          if (!taken_[p] && previous_[p].category == category && d < best_distance) best = p, best_distance = d;
        }
      }
  if (best == previous_.size()) return false;
  taken_[best] = 1;
  return true;
}

std::vector<SourceBirth> IsolatedParticleTracker::update(const std::vector<Vec3>& position,
                                                         const std::vector<Vec3>& velocity,
                                                         const std::vector<std::uint8_t>& category, double time,
                                                         const std::vector<std::uint64_t>* id) {
  const double elapsed = time - time_;
  std::unordered_set<std::uint64_t> isolated_before;
  if (id)
    for (const Isolated& q : previous_) isolated_before.insert(isolatedKey(q.id, q.category));
  predicted_.clear();
  std::vector<SourceBirth> births;
  std::vector<Isolated> current;
  for (std::size_t i = 0; i < position.size(); ++i) {
    const std::uint8_t c = category[i];
    if (c != kCategoryDroplet && c != kCategoryBubble) continue;
    const std::uint64_t particle = id ? (*id)[i] : 0;
    current.push_back({position[i], velocity[i], c, particle});
    const bool seen = id ? isolated_before.count(isolatedKey(particle, c)) > 0
                         : !previous_.empty() && matchesByProximity(position[i], c, elapsed);
    if (seen) continue;
    births.push_back({c == kCategoryDroplet ? TextureKind::Droplet : TextureKind::Bubble, position[i], velocity[i]});
  }
  previous_ = std::move(current);
  predicted_.clear();
  time_ = time;
  return births;
}

}  // namespace mistfall
