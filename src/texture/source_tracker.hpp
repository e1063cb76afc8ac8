// Birth of texture sources from the classified MPS frames. A liquid particle whose category becomes 3 (droplet)
// spawns one droplet (mist) source, a gas particle whose category becomes 6 (bubble) one bubble (micro-bubble)
// source, at its position and with its MPS velocity (section 3.2).
// "Becomes": a particle is followed from one frame to the next by its id (the frames' `id` array: every particle
// keeps its id for its life, particles.hpp): an isolated particle of frame n whose id was isolated, in the same
// category, in frame n-1 is not new. Frames written before ids existed are followed by proximity instead: an
// isolated particle of frame n is the same as an isolated particle of the same category in frame n-1 whose
// position advanced by its velocity, x + u (t_n - t_{n-1}), lies within the match radius (texture.match_radius
// l0); the nearest such one is taken, each at most once. Only new isolated particles spawn a source, so a
// particle that stays isolated over consecutive frames spawns one source.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "texture/particle_motion.hpp"
#include "texture/texture_kind.hpp"

namespace mistfall {

// Category values written by `mistfall classify` (section 3.1; 0 = not fluid).
inline constexpr std::uint8_t kCategoryDroplet = 3;
inline constexpr std::uint8_t kCategoryBubble = 6;

struct SourceBirth {
  TextureKind kind;
  Vec3 position;
  Vec3 velocity;
};

class IsolatedParticleTracker {
 public:
  explicit IsolatedParticleTracker(double match_radius) : match_radius_(match_radius) {}

  // The particles of the frame at `time` (positions and velocities padded to 3D, one category each; their ids,
  // or nullptr for a frame without ids) that are newly isolated, in particle order; remembers this frame's
  // isolated particles for the next call.
  std::vector<SourceBirth> update(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
                                  const std::vector<std::uint8_t>& category, double time,
                                  const std::vector<std::uint64_t>* id = nullptr);

 private:
  struct Isolated {
    Vec3 position, velocity;
    std::uint8_t category;
    std::uint64_t id;
  };
  bool matchesByProximity(const Vec3& position, std::uint8_t category, double elapsed);
  double match_radius_;
  double time_ = 0.0;
  std::vector<Isolated> previous_;
  // proximity matching: the previous frame's isolated particles advanced to this frame, binned by match radius
  std::vector<Vec3> predicted_;
  std::vector<char> taken_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

}  // namespace mistfall
