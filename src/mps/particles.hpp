// Particle data as structure-of-arrays: one array per field, index i is particle i in every array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mps/erase_marked.hpp"
#include "mps/spatial_order.hpp"
#include "mps/vector.hpp"

namespace mistfall {

// What a particle is to the solver.
//  Fluid: moves, pressure solved.       Wall: fixed, pressure solved (Neumann-like boundary).
//  Dummy: fixed, counts in number density only (fills the wall's influence region).
//  Escaped: left the domain; frozen and ignored by every operator, still counted.
//  Inflow: water in an inflow buffer (open_boundaries.hpp): driven at the inflow velocity, its pressure solved (its
//          rows by [[inflow]] pressure, inflow_pressure.hpp); it becomes Fluid when it leaves the buffer.
//  Point: gas below a bubble's resolution moved as a point through the water by eq. (18) (entrained_bubbles.hpp);
//         ignored by every MPS operator; it becomes Fluid again when it reaches the surface.
enum class ParticleKind : std::uint8_t { Fluid = 0, Wall = 1, Dummy = 2, Escaped = 3, Inflow = 4, Point = 5 };

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
  // A particle's id: unique over the run and kept for its life (0, 1, ... in the order particles are made: the case's
  // lattice, then each particle an inflow creates; an outflow's removal never reuses one). The frames carry it (array
  // `id`), so VFX tools and the texture stage can follow a particle.
  std::vector<std::uint64_t> id;
  std::uint64_t next_id = 0;  // the id of the next particle made

  std::size_t size() const { return position.size(); }

  void add(const Vec<D>& x, const Vec<D>& u, ParticleKind k, Phase ph) {
    position.push_back(x);
    velocity.push_back(u);
    pressure.push_back(0.0);
    number_density.push_back(0.0);
    kind.push_back(k);
    phase.push_back(ph);
    enclosed.push_back(0);
    id.push_back(next_id++);
  }

  std::size_t count(ParticleKind k) const {
    std::size_t c = 0;
    for (auto v : kind) c += (v == k);
    return c;
  }
  // Removes the particles with remove[i] != 0 from every array, keeping the order of the others.
  void erase(const std::vector<char>& remove) {
    eraseMarked(remove, position, velocity, pressure, number_density, kind, phase, enclosed, id);
  }
  // Puts particle order[k] at place k in every array (spatial_order.hpp).
  void reorder(const std::vector<std::size_t>& order) {
    permuteAll(order, position, velocity, pressure, number_density, kind, phase, enclosed, id);
  }
  std::size_t count(ParticleKind k, Phase ph) const {
    std::size_t c = 0;
    for (std::size_t i = 0; i < kind.size(); ++i) c += (kind[i] == k && phase[i] == ph);
    return c;
  }
};

// Not moved by fluid forces (pressure, collisions): walls, dummies and the driven inflow particles.
inline bool isFixed(ParticleKind k) {
  return k == ParticleKind::Wall || k == ParticleKind::Dummy || k == ParticleKind::Inflow;
}
// Carries a pressure unknown (off the free surface): fluid, wall and inflow particles.
inline bool hasPressureUnknown(ParticleKind k) {
  return k == ParticleKind::Fluid || k == ParticleKind::Wall || k == ParticleKind::Inflow;
}
// Takes part in the MPS operators: every kind but escaped particles and points.
inline bool isActive(ParticleKind k) { return k != ParticleKind::Escaped && k != ParticleKind::Point; }

}  // namespace mistfall
