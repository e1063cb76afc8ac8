// Builds the initial particles of a case on the lattice described in scene.hpp, and classifies solid
// lattice points into Wall (touching a non-solid point) and Dummy (buried inside the wall).
#include "case/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

namespace mistfall {
namespace {

constexpr double kTolerance = 1e-9;  // in units of l0
constexpr int kBits = 21;
constexpr std::uint64_t kMask = (std::uint64_t{1} << kBits) - 1;

using Index = std::array<std::int64_t, 3>;

// Smallest i >= 0 with origin + (i + 0.5) * l0 >= edge - tol.
std::int64_t firstIndexAtOrAbove(double edge, double origin, double l0) {
  const double t = std::ceil((edge - origin) / l0 - 0.5 - kTolerance);
  if (!(t > 0.0)) return 0;  // also catches NaN
  return static_cast<std::int64_t>(std::min(t, 1.0e15));
}

// Half-open index range [lo, hi) of the lattice points of box b on each axis, clipped to the domain.
struct IndexRange {
  Index lo{0, 0, 0};
  Index hi{1, 1, 1};
  bool empty(int dim) const {
    for (int k = 0; k < dim; ++k)
      if (hi[k] <= lo[k]) return true;
    return false;
  }
};

IndexRange boxRange(const CaseConfig& c, const Box& b) {
  IndexRange r;
  const double l0 = c.numerics.particle_spacing;
  for (int k = 0; k < c.dimension; ++k) {
    const std::int64_t n = domainLatticeCount(c, k);
    r.lo[k] = std::min(firstIndexAtOrAbove(b.min[k], c.domain.min[k], l0), n);
    r.hi[k] = std::min(firstIndexAtOrAbove(b.max[k], c.domain.min[k], l0), n);
  }
  return r;
}

// Calls f(index) for every index of the range, axis 0 slowest.
template <int D, class F>
void forEachIndex(const IndexRange& r, F&& f) {
  if (r.empty(D)) return;
  Index i{0, 0, 0};
  for (i[0] = r.lo[0]; i[0] < r.hi[0]; ++i[0])
    for (i[1] = r.lo[1]; i[1] < r.hi[1]; ++i[1]) {
      if constexpr (D == 3) {
        for (i[2] = r.lo[2]; i[2] < r.hi[2]; ++i[2]) f(i);
      } else {
        f(i);
      }
    }
}

// Packs an index (axis 0 most significant) so that sorting keys sorts lexicographically.
std::uint64_t pack(const Index& i) {
  return (static_cast<std::uint64_t>(i[0]) << (2 * kBits)) | (static_cast<std::uint64_t>(i[1]) << kBits) |
         static_cast<std::uint64_t>(i[2]);
}

Index unpack(std::uint64_t key) {
  return {static_cast<std::int64_t>((key >> (2 * kBits)) & kMask),
          static_cast<std::int64_t>((key >> kBits) & kMask), static_cast<std::int64_t>(key & kMask)};
}

template <int D>
Vec<D> latticePoint(const CaseConfig& c, const Index& i) {
  Vec<D> x;
  for (int k = 0; k < D; ++k)
    x[k] = c.domain.min[k] + (static_cast<double>(i[k]) + 0.5) * c.numerics.particle_spacing;
  return x;
}

}  // namespace

std::int64_t domainLatticeCount(const CaseConfig& c, int axis) {
  if (axis >= c.dimension) return 1;
  return firstIndexAtOrAbove(c.domain.max[axis], c.domain.min[axis], c.numerics.particle_spacing);
}

std::size_t countLatticePoints(const CaseConfig& c, const Box& b) {
  const IndexRange r = boxRange(c, b);
  if (r.empty(c.dimension)) return 0;
  std::size_t n = 1;
  for (int k = 0; k < c.dimension; ++k) n *= static_cast<std::size_t>(r.hi[k] - r.lo[k]);
  return n;
}

template <int D>
Particles<D> buildParticles(const CaseConfig& c) {
  if (c.dimension != D)
    throw std::invalid_argument("buildParticles<" + std::to_string(D) + ">: case dimension is " +
                                std::to_string(c.dimension));
  Index n{1, 1, 1};
  for (int k = 0; k < D; ++k) {
    n[k] = domainLatticeCount(c, k);
    if (n[k] > kMaxLatticeIndex)
      throw std::length_error("buildParticles: too many lattice points along axis " + std::to_string(k));
  }

  Particles<D> p;
  std::size_t water_count = 0;
  for (const Region& r : c.regions)
    if (r.material == Material::Water) water_count += countLatticePoints(c, r.box);

  // Water: one region after another, each in lexicographic lattice order.
  for (const Region& r : c.regions) {
    if (r.material != Material::Water) continue;
    Vec<D> u;
    for (int k = 0; k < D; ++k) u[k] = r.initial_velocity[k];
    forEachIndex<D>(boxRange(c, r.box), [&](const Index& i) {
      p.add(latticePoint<D>(c, i), u, ParticleKind::Fluid, Phase::Liquid);
    });
  }

  // Walls: the union of all wall regions, sorted and deduplicated.
  std::vector<std::uint64_t> solid;
  for (const Region& r : c.regions) {
    if (r.material != Material::Wall) continue;
    forEachIndex<D>(boxRange(c, r.box), [&](const Index& i) { solid.push_back(pack(i)); });
  }
  std::sort(solid.begin(), solid.end());
  solid.erase(std::unique(solid.begin(), solid.end()), solid.end());
  const std::unordered_set<std::uint64_t> is_solid(solid.begin(), solid.end());

  const std::size_t total = water_count + solid.size();
  p.position.reserve(total);
  p.velocity.reserve(total);
  p.pressure.reserve(total);
  p.number_density.reserve(total);
  p.kind.reserve(total);
  p.phase.reserve(total);

  IndexRange around;
  for (int k = 0; k < D; ++k) {
    around.lo[k] = -1;
    around.hi[k] = 2;
  }
  for (const std::uint64_t key : solid) {
    const Index i = unpack(key);
    bool exposed = false;
    forEachIndex<D>(around, [&](const Index& off) {
      if (exposed) return;
      Index j = i;
      bool self = true;
      for (int k = 0; k < D; ++k) {
        j[k] += off[k];
        self = self && off[k] == 0;
        if (j[k] < 0 || j[k] >= n[k]) return;  // outside the domain: does not count
      }
      if (!self && is_solid.count(pack(j)) == 0) exposed = true;
    });
    p.add(latticePoint<D>(c, i), Vec<D>::Zero(), exposed ? ParticleKind::Wall : ParticleKind::Dummy,
          Phase::Liquid);
  }
  return p;
}

template Particles<2> buildParticles<2>(const CaseConfig& c);
template Particles<3> buildParticles<3>(const CaseConfig& c);

}  // namespace mistfall
