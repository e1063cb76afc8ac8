// Counter-based random numbers for the texture: every draw is a pure function of (seed, particle id, step,
// stream), so a particle's noise does not depend on which thread steps it or in what order, and the same seed
// gives the same cloud on any thread count. The mixer is the splitmix64 finaliser (Steele, Lea & Flood 2014,
// "Fast splittable pseudorandom number generators"), applied to a combination of the counters; normal deviates
// come from two uniforms by the Box-Muller transform.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "mps/splitmix.hpp"

namespace mistfall {

// Independent streams of one particle in one step.
enum class RandomStream : std::uint64_t { Fluctuation = 1, Birth = 2, Across = 3 };

class CounterRng {
 public:
  CounterRng(std::uint64_t seed, std::uint64_t particle_id, std::uint64_t step, RandomStream stream)
      : state_(splitmix64(splitmix64(splitmix64(seed) ^ particle_id) ^ step) ^
               static_cast<std::uint64_t>(stream) * 0xd1b54a32d192ed03ULL) {}

  std::uint64_t next() { return splitmix64(state_ += 0x9e3779b97f4a7c15ULL); }
  // Uniform in (0, 1): 53 random bits, never 0.
  double uniform() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }
  // Standard normal by Box-Muller (one of the pair; the other is discarded so a draw's position in the stream
  // does not depend on how many draws came before in another stream).
  double normal() {
    const double r = std::sqrt(-2.0 * std::log(uniform()));
    return r * std::cos(2.0 * std::numbers::pi * uniform());
  }

 private:
  std::uint64_t state_;
};

}  // namespace mistfall
