// Particle data as structure-of-arrays: one array per field, index i is particle i in every array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mps/vector.hpp"

namespace mistfall {

// What a particle is to the solver.
//  Fluid: moves, pressure solved.       Wall: fixed, pressure solved (Neumann-like boundary).
//  Dummy: fixed, counts in number density only (fills the wall's influence region).
//  Escaped: left the domain; frozen and ignored by every operator, still counted.
enum class ParticleKind : std::uint8_t { Fluid = 0, Wall = 1, Dummy = 2, Escaped = 3 };

// Which phase a particle carries (the second phase arrives with the gas model).
enum class Phase : std::uint8_t { Liquid = 0, Gas = 1 };

template <int D>
struct Particles {
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<double> pressure;
  std::vector<double> number_density;
  std::vector<ParticleKind> kind;
  std::vector<Phase> phase;
  std::vector<char> enclosed;  // delta_gl of eq. (7) at the last step: 1 for gas of a region enclosed in liquid

  std::size_t size() const { return position.size(); }

  void add(const Vec<D>& x, const Vec<D>& u, ParticleKind k, Phase ph) {
    position.push_back(x);
    velocity.push_back(u);
    pressure.push_back(0.0);
    number_density.push_back(0.0);
    kind.push_back(k);
    phase.push_back(ph);
    enclosed.push_back(0);
  }

  std::size_t count(ParticleKind k) const {
    std::size_t c = 0;
    for (auto v : kind) c += (v == k);
    return c;
  }
  std::size_t count(ParticleKind k, Phase ph) const {
    std::size_t c = 0;
    for (std::size_t i = 0; i < kind.size(); ++i) c += (kind[i] == k && phase[i] == ph);
    return c;
  }
};

inline bool isFixed(ParticleKind k) { return k == ParticleKind::Wall || k == ParticleKind::Dummy; }
inline bool isActive(ParticleKind k) { return k != ParticleKind::Escaped; }

}  // namespace mistfall
