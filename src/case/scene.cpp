// Builds the initial particles of a case on the lattice described in scene.hpp (resolving overlaps of
// water, gas and wall regions), and classifies solid lattice points into Wall (touching a non-solid point)
// and Dummy (buried inside the wall).
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

double latticeCoordinate(const CaseConfig& c, const Index& i, int k) {
  return c.domain.min[k] + (static_cast<double>(i[k]) + 0.5) * c.numerics.particle_spacing;
}

template <int D>
Vec<D> latticePoint(const CaseConfig& c, const Index& i) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = latticeCoordinate(c, i, k);
  return x;
}

// Calls f(index) for every index of the range in the case's dimension.
template <class F>
void forEachIndexIn(int dim, const IndexRange& r, F&& f) {
  if (dim == 3) {
    forEachIndex<3>(r, f);
  } else {
    forEachIndex<2>(r, f);
  }
}

// The lattice points of one region: a candidate index range (exact for a box, the bounding box grown by
// one spacing for a circle) and the membership test.
struct RegionLattice {
  const CaseConfig* c = nullptr;
  const Region* region = nullptr;
  IndexRange range;
  double limit2 = 0.0;  // circle: (radius + tolerance)^2

  bool contains(const Index& i) const {
    for (int k = 0; k < c->dimension; ++k)
      if (i[k] < range.lo[k] || i[k] >= range.hi[k]) return false;
    if (region->shape == RegionShape::Box) return true;
    double d2 = 0.0;
    for (int k = 0; k < c->dimension; ++k) {
      const double d = latticeCoordinate(*c, i, k) - region->center[k];
      d2 += d * d;
    }
    return d2 <= limit2;
  }
};

RegionLattice latticeOf(const CaseConfig& c, const Region& r) {
  RegionLattice v;
  v.c = &c;
  v.region = &r;
  if (r.shape == RegionShape::Box) {
    v.range = boxRange(c, r.box);
  } else {
    const double l0 = c.numerics.particle_spacing;
    Box grown;
    for (int k = 0; k < c.dimension; ++k) {
      grown.min[k] = r.center[k] - r.radius - l0;
      grown.max[k] = r.center[k] + r.radius + l0;
    }
    v.range = boxRange(c, grown);
    const double limit = r.radius + kTolerance * l0;
    v.limit2 = limit * limit;
  }
  return v;
}

bool isFluid(Material m) { return m == Material::Water || m == Material::Gas; }

// Calls f(index) for every lattice point region `r` contributes after overlaps are resolved (scene.hpp).
template <class F>
void forEachRegionPoint(const CaseConfig& c, const std::vector<RegionLattice>& all, std::size_t r, F&& f) {
  const RegionLattice& self = all[r];
  const bool fluid = isFluid(self.region->material);
  forEachIndexIn(c.dimension, self.range, [&](const Index& i) {
    if (!self.contains(i)) return;
    if (fluid) {
      for (std::size_t j = 0; j < all.size(); ++j) {
        const Material m = all[j].region->material;
        const bool overrides = m == Material::Wall || (j > r && isFluid(m));
        if (overrides && all[j].contains(i)) return;
      }
    }
    f(i);
  });
}

std::vector<RegionLattice> latticesOf(const CaseConfig& c) {
  std::vector<RegionLattice> v;
  v.reserve(c.regions.size());
  for (const Region& r : c.regions) v.push_back(latticeOf(c, r));
  return v;
}

}  // namespace

std::int64_t domainLatticeCount(const CaseConfig& c, int axis) {
  if (axis >= c.dimension) return 1;
  return firstIndexAtOrAbove(c.domain.max[axis], c.domain.min[axis], c.numerics.particle_spacing);
}

std::vector<double> latticeCoordinates(const CaseConfig& c, const Box& b, int axis) {
  const IndexRange r = boxRange(c, b);
  std::vector<double> x;
  for (std::int64_t i = r.lo[axis]; i < r.hi[axis]; ++i) {
    Index index{0, 0, 0};
    index[axis] = i;
    x.push_back(latticeCoordinate(c, index, axis));
  }
  return x;
}

std::size_t countLatticePoints(const CaseConfig& c, const Box& b) {
  const IndexRange r = boxRange(c, b);
  if (r.empty(c.dimension)) return 0;
  std::size_t n = 1;
  for (int k = 0; k < c.dimension; ++k) n *= static_cast<std::size_t>(r.hi[k] - r.lo[k]);
  return n;
}

std::size_t countLatticePoints(const CaseConfig& c, const Region& r) {
  if (r.shape == RegionShape::Box) return countLatticePoints(c, r.box);
  const RegionLattice v = latticeOf(c, r);
  std::size_t n = 0;
  forEachIndexIn(c.dimension, v.range, [&](const Index& i) { n += v.contains(i); });
  return n;
}

std::vector<std::size_t> regionParticleCounts(const CaseConfig& c) {
  const std::vector<RegionLattice> all = latticesOf(c);
  std::vector<std::size_t> n(c.regions.size(), 0);
  for (std::size_t r = 0; r < c.regions.size(); ++r) forEachRegionPoint(c, all, r, [&](const Index&) { ++n[r]; });
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
  const std::vector<RegionLattice> all = latticesOf(c);
  std::size_t fluid_count = 0;
  for (std::size_t r = 0; r < c.regions.size(); ++r)
    if (isFluid(c.regions[r].material)) forEachRegionPoint(c, all, r, [&](const Index&) { ++fluid_count; });

  // Walls: the union of all wall regions, sorted and deduplicated.
  std::vector<std::uint64_t> solid;
  for (std::size_t r = 0; r < c.regions.size(); ++r) {
    if (c.regions[r].material != Material::Wall) continue;
    forEachRegionPoint(c, all, r, [&](const Index& i) { solid.push_back(pack(i)); });
  }
  std::sort(solid.begin(), solid.end());
  solid.erase(std::unique(solid.begin(), solid.end()), solid.end());
  const std::unordered_set<std::uint64_t> is_solid(solid.begin(), solid.end());

  const std::size_t total = fluid_count + solid.size();
  p.position.reserve(total);
  p.velocity.reserve(total);
  p.pressure.reserve(total);
  p.number_density.reserve(total);
  p.kind.reserve(total);
  p.phase.reserve(total);

  // Inflow buffers replace the water and gas inside them.
  std::vector<IndexRange> inflow_ranges;
  for (const Inflow& in : c.inflows) inflow_ranges.push_back(boxRange(c, in.box));
  auto inInflow = [&](const Index& i) {
    for (const IndexRange& r : inflow_ranges) {
      bool inside = true;
      for (int k = 0; k < D; ++k) inside = inside && r.lo[k] <= i[k] && i[k] < r.hi[k];
      if (inside) return true;
    }
    return false;
  };

  // Water, then gas: one region after another in file order, each in lexicographic lattice order.
  std::unordered_set<std::uint64_t> fluid_points;  // kept only for the vents below
  for (const Material m : {Material::Water, Material::Gas}) {
    const Phase phase = m == Material::Water ? Phase::Liquid : Phase::Gas;
    for (std::size_t r = 0; r < c.regions.size(); ++r) {
      if (c.regions[r].material != m) continue;
      Vec<D> u;
      for (int k = 0; k < D; ++k) u[k] = c.regions[r].initial_velocity[k];
      forEachRegionPoint(c, all, r, [&](const Index& i) {
        if (inInflow(i)) return;
        p.add(latticePoint<D>(c, i), u, ParticleKind::Fluid, phase);
        if (!c.vents.empty()) fluid_points.insert(pack(i));
      });
    }
  }
  // Then the vents' gas (mps/gas_vent.hpp): the points of each vent box that no region's fluid holds, at rest.
  for (const Vent& v : c.vents)
    forEachIndex<D>(boxRange(c, v.box), [&](const Index& i) {
      if (fluid_points.insert(pack(i)).second) p.add(latticePoint<D>(c, i), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Gas);
    });
  // Then the inflow buffers' water, driven at the inflow speed (kind Inflow), in file order.
  for (std::size_t b = 0; b < c.inflows.size(); ++b) {
    Vec<D> u = Vec<D>::Zero();
    u[c.inflows[b].axis] = c.inflows[b].sign * c.inflows[b].speed;
    forEachIndex<D>(inflow_ranges[b], [&](const Index& i) {
      p.add(latticePoint<D>(c, i), u, ParticleKind::Inflow, Phase::Liquid);
    });
  }

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
