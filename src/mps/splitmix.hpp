// The splitmix64 mixer (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number generators"): the hash
// behind every counter-based random draw of mistfall (the texture's CounterRng, the entrained-gas exchange), so a
// draw is a pure function of its counters and does not depend on threads or order.
#pragma once

#include <cstdint>

namespace mistfall {

// The splitmix64 finaliser: a bijective avalanche mix of a 64-bit word.
inline std::uint64_t splitmixFinalise(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The splitmix64 output function: the golden-ratio increment, then the finaliser.
inline std::uint64_t splitmix64(std::uint64_t z) { return splitmixFinalise(z + 0x9e3779b97f4a7c15ULL); }

}  // namespace mistfall
