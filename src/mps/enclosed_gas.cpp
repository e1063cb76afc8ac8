// Gas regions (connected components of gas particles closer than the link radius), which of them are enclosed
// in liquid (bubbles, flag delta_gl), and per-bubble statistics. Definitions in enclosed_gas.hpp.
#include "mps/enclosed_gas.hpp"

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mistfall {

namespace {

// Union-find whose root is always the smallest index of its component (the region-id order needs it).
struct MinRootUnionFind {
  std::vector<std::int32_t> parent;

  explicit MinRootUnionFind(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::int32_t>(i);
  }

  std::int32_t find(std::int32_t i) {
    while (parent[i] != i) {
      parent[i] = parent[parent[i]];  // path halving: roots never change
      i = parent[i];
    }
    return i;
  }

  void join(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
  }
};

}  // namespace

int latticeNeighbourCount(int dimension, double link_radius, double l0) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("lattice dimension must be 2 or 3");
  if (!(l0 > 0.0) || !(link_radius > 0.0)) throw std::invalid_argument("l0 and link radius must be positive");
  const double ratio2 = (link_radius / l0) * (link_radius / l0);
  const int reach = static_cast<int>(std::ceil(link_radius / l0)) + 1;
  const int zreach = dimension == 3 ? reach : 0;
  int count = 0;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = -zreach; k <= zreach; ++k) {
        const int k2 = i * i + j * j + k * k;
        if (k2 > 0 && k2 < ratio2) ++count;
      }
  return count;
}

template <int D>
void findGasRegions(const Particles<D>& p, const NeighbourList& nl, double link_radius, double l0, GasRegions& out,
                    const GasRegionOptions& options) {
  const std::vector<char>* was_enclosed = options.was_enclosed;
  const std::size_t closed_small_region = options.closed_small_region;
  const double join_radius = options.join_radius;
  const std::size_t n = p.size();
  if (nl.particleCount() != n)
    throw std::invalid_argument("gas regions: neighbour list holds " + std::to_string(nl.particleCount()) +
                                " particles, expected " + std::to_string(n));
  const double min_neighbours = kEnclosedMinNeighbourFraction * latticeNeighbourCount(D, link_radius, l0);
  const double link2 = link_radius * link_radius;
  const auto gas = [&](std::int64_t j) { return isGas(p.kind[j], p.phase[j]); };

  // Per gas particle: does it border something other than liquid (wall, dummy, open space)?
  std::vector<char> open(n, 0), touches_liquid(n, 0), dispersed(n, 0);
  const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i) {
    if (!gas(i)) continue;
    int neighbours = 0, liquid_neighbours = 0;
    bool foreign = false;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (!isActive(p.kind[j]) || (p.position[j] - p.position[i]).squaredNorm() >= link2) continue;
      ++neighbours;
      const bool liquid = p.kind[j] == ParticleKind::Fluid && p.phase[j] == Phase::Liquid;
      if (!gas(j) && !liquid) foreign = true;
      if (liquid) touches_liquid[i] = 1, ++liquid_neighbours;
    }
    dispersed[i] = options.dispersed_fraction > 0.0 && neighbours > 0 &&
                   liquid_neighbours >= options.dispersed_fraction * neighbours;
    const bool exempt = was_enclosed && static_cast<std::size_t>(i) < was_enclosed->size() && (*was_enclosed)[i];
    open[i] = !exempt && (foreign || neighbours < min_neighbours);
  }

  // Components, serially in index order (deterministic whatever the thread count), joining gas particles closer
  // than join_radius (0: the link radius).
  const double join2 = join_radius > 0.0 ? join_radius * join_radius : link2;
  MinRootUnionFind uf(n);
  for (std::int64_t i = 0; i < count; ++i) {
    if (!gas(i) || dispersed[i]) continue;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (gas(j) && !dispersed[j] && (p.position[j] - p.position[i]).squaredNorm() < join2)
        uf.join(static_cast<std::int32_t>(i), j);
    }
  }

  out.dispersed = 0;
  for (std::int64_t i = 0; i < count; ++i) out.dispersed += gas(i) && dispersed[i];
  // Dispersed gas touching undispersed gas joins the nearest such particle's region (never two: no bridge).
  if (options.dispersed_touch > 0.0) {
    const double touch2 = options.dispersed_touch * options.dispersed_touch;
    for (std::int64_t i = 0; i < count; ++i) {
      if (!gas(i) || !dispersed[i]) continue;
      std::int32_t nearest = -1;
      double best = touch2;
      for (auto s = nl.begin(i); s < nl.end(i); ++s) {
        const auto j = nl.indices[s];
        if (!gas(j) || dispersed[j]) continue;
        const double r2 = (p.position[j] - p.position[i]).squaredNorm();
        if (r2 < best || (r2 == best && nearest >= 0 && j < nearest)) best = r2, nearest = j;
      }
      if (nearest >= 0) uf.join(static_cast<std::int32_t>(i), nearest), --out.dispersed;
    }
  }

  // Region ids in the order of each component's root (its smallest index, met before its other particles).
  out.region_of.assign(n, -1);
  out.enclosed.clear();
  for (std::int64_t i = 0; i < count; ++i) {
    if (!gas(i)) continue;
    const std::int32_t root = uf.find(static_cast<std::int32_t>(i));
    if (root == i) {
      out.region_of[i] = static_cast<std::int32_t>(out.enclosed.size());
      out.enclosed.push_back(1);
    } else {
      out.region_of[i] = out.region_of[root];
    }
    if (open[i]) out.enclosed[out.region_of[i]] = 0;
  }
  // A closed gas domain has no open space: a small region touching liquid is a pocket in it, whatever it borders;
  // with the vents given, so is any region touching liquid that holds no vent's gas.
  if (closed_small_region > 0) {
    std::vector<std::size_t> size(out.enclosed.size(), 0);
    std::vector<char> wet(out.enclosed.size(), 0), vented(out.enclosed.size(), 0);
    const std::vector<int>* vent_of = options.vent_of;
    for (std::int64_t i = 0; i < count; ++i) {
      if (out.region_of[i] < 0) continue;
      ++size[out.region_of[i]];
      wet[out.region_of[i]] |= touches_liquid[i];
      if (vent_of && static_cast<std::size_t>(i) < vent_of->size()) vented[out.region_of[i]] |= (*vent_of)[i] >= 0;
    }
    // The largest region is the box's air itself, never a pocket in the water.
    const std::size_t largest = static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
    for (std::size_t r = 0; r < size.size(); ++r) {
      const bool pocket = vent_of ? !vented[r] : size[r] < closed_small_region;
      if (r != largest && pocket && wet[r]) out.enclosed[r] = 1;
    }
  }

  out.enclosed_particle.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i)
    out.enclosed_particle[i] = out.region_of[i] >= 0 && out.enclosed[out.region_of[i]];
}

template <int D>
std::vector<BubbleStats> bubbleStatistics(const Particles<D>& p, const GasRegions& r, double l0) {
  const std::size_t n = p.size();
  if (r.region_of.size() != n) throw std::invalid_argument("bubble statistics: gas regions of another particle set");
  const std::size_t regions = r.enclosed.size();
  std::vector<std::size_t> particles(regions, 0);
  std::vector<double> pressure_sum(regions, 0.0);
  // Positions are summed relative to each region's first particle: the centroid keeps full precision far
  // from the origin.
  std::vector<Vec<D>> reference(regions, Vec<D>::Zero()), offset_sum(regions, Vec<D>::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = r.region_of[i];
    if (id < 0 || !r.enclosed[id]) continue;
    if (particles[id] == 0) reference[id] = p.position[i];
    ++particles[id];
    pressure_sum[id] += p.pressure[i];
    offset_sum[id] += p.position[i] - reference[id];
  }

  std::vector<BubbleStats> stats;
  const double cell = std::pow(l0, D);
  for (std::size_t id = 0; id < regions; ++id) {
    if (!r.enclosed[id] || particles[id] == 0) continue;
    BubbleStats b;
    b.region = static_cast<std::int32_t>(id);
    b.particles = particles[id];
    const double count = static_cast<double>(particles[id]);
    b.mean_pressure = pressure_sum[id] / count;
    const Vec<D> centroid = reference[id] + offset_sum[id] / count;
    for (int k = 0; k < D; ++k) b.centroid[k] = centroid[k];
    b.size = count * cell;
    stats.push_back(b);
  }
  return stats;
}

template void findGasRegions<2>(const Particles<2>&, const NeighbourList&, double, double, GasRegions&,
                                const GasRegionOptions&);
template void findGasRegions<3>(const Particles<3>&, const NeighbourList&, double, double, GasRegions&,
                                const GasRegionOptions&);
template std::vector<BubbleStats> bubbleStatistics<2>(const Particles<2>&, const GasRegions&, double);
template std::vector<BubbleStats> bubbleStatistics<3>(const Particles<3>&, const GasRegions&, double);

}  // namespace mistfall
