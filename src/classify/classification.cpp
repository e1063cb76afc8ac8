// Six-category classification, section 3.1: number-density level and its spatial rate of change, liquid and gas
// classified separately (the criteria are written out in classification.hpp).
#include "classify/classification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mps/enclosed_gas.hpp"
#include "mps/weight.hpp"

namespace mistfall {

namespace {

bool isWallLike(ParticleKind k) { return k == ParticleKind::Wall || k == ParticleKind::Dummy; }
bool carriesPhase(ParticleKind k) { return k == ParticleKind::Fluid || k == ParticleKind::Inflow; }

Category isolatedOf(Phase ph) { return ph == Phase::Liquid ? Category::Droplet : Category::Bubble; }
Category surfaceOf(Phase ph) { return ph == Phase::Liquid ? Category::LiquidSurface : Category::GasSurface; }
Category bulkOf(Phase ph) { return ph == Phase::Liquid ? Category::LiquidBulk : Category::GasBulk; }

// The sums of classification.hpp for one particle.
template <int D>
struct Neighbourhood {
  double n_own = 0.0;
  int count_own = 0;
  double n_all = 0.0;
  Vec<D> grad = Vec<D>::Zero();
};

template <int D>
Neighbourhood<D> neighbourhoodOf(std::size_t i, const Particles<D>& p, const NeighbourList& nl, double re) {
  Neighbourhood<D> h;
  const Phase ph = p.phase[i];
  for (auto s = nl.begin(i); s < nl.end(i); ++s) {
    const auto j = nl.indices[s];
    const bool own = carriesPhase(p.kind[j]) && p.phase[j] == ph;
    if (!own && !isWallLike(p.kind[j])) continue;
    const Vec<D> rij = p.position[j] - p.position[i];
    const double r = rij.norm();
    const double w = weight(r, re);
    if (!(w > 0.0)) continue;  // beyond re (or coincident: no direction, no finite weight)
    if (own) {
      h.n_own += w;
      h.count_own += 1;
    }
    h.n_all += w;
    h.grad += rij * (re / (r * r * r));
  }
  return h;
}

}  // namespace

std::string_view categoryName(Category c) {
  switch (c) {
    case Category::LiquidBulk: return "liquid_bulk";
    case Category::LiquidSurface: return "liquid_surface";
    case Category::Droplet: return "droplet";
    case Category::GasBulk: return "gas_bulk";
    case Category::GasSurface: return "gas_surface";
    case Category::Bubble: return "bubble";
    default: return "none";
  }
}

template <int D>
std::vector<Category> classifyParticles(const Particles<D>& p, const NeighbourList& nl, const MpsConstants& c,
                                        const ClassificationParameters& params) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Category> out(p.size(), Category::None);
  const double re = c.re_number_density;
  const double min_count = params.isolated_neighbour_fraction * latticeNeighbourCount(D, re, c.l0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto pi = static_cast<std::size_t>(i);
    if (p.kind[pi] == ParticleKind::Point) {  // entrained gas moved as a point: an isolated gas particle by construction
      out[pi] = Category::Bubble;
      continue;
    }
    if (p.kind[pi] != ParticleKind::Fluid) continue;
    const Neighbourhood<D> h = neighbourhoodOf<D>(pi, p, nl, re);
    const Phase ph = p.phase[pi];
    if (h.n_own < params.isolated_number_density * c.n0 || h.count_own < min_count) {
      out[pi] = isolatedOf(ph);
    } else if (h.n_all < params.surface_number_density * c.n0 ||
               h.grad.norm() * c.l0 / c.n0 > params.surface_gradient) {
      out[pi] = surfaceOf(ph);
    } else {
      out[pi] = bulkOf(ph);
    }
  }
  return out;
}

template <int D>
std::vector<Category> classifyParticles(const Particles<D>& p, const MpsConstants& c,
                                        const ClassificationParameters& params) {
  Vec<D> lower = Vec<D>::Constant(std::numeric_limits<double>::max());
  Vec<D> upper = Vec<D>::Constant(std::numeric_limits<double>::lowest());
  bool any = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isActive(p.kind[i]) || !std::isfinite(p.position[i].squaredNorm())) continue;
    lower = lower.cwiseMin(p.position[i]);
    upper = upper.cwiseMax(p.position[i]);
    any = true;
  }
  if (!any) lower = upper = Vec<D>::Zero();
  NeighbourSearch<D> search(lower, upper, c.re_number_density);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  return classifyParticles<D>(p, nl, c, params);
}

std::array<std::size_t, kCategoryCount> countCategories(const std::vector<Category>& categories) {
  std::array<std::size_t, kCategoryCount> counts{};
  for (Category c : categories) counts[static_cast<std::size_t>(c)] += 1;
  return counts;
}

std::vector<std::uint8_t> categoryBytes(const std::vector<Category>& categories) {
  std::vector<std::uint8_t> out(categories.size());
  std::transform(categories.begin(), categories.end(), out.begin(),
                 [](Category c) { return static_cast<std::uint8_t>(c); });
  return out;
}

template std::vector<Category> classifyParticles<2>(const Particles<2>&, const NeighbourList&, const MpsConstants&,
                                                    const ClassificationParameters&);
template std::vector<Category> classifyParticles<3>(const Particles<3>&, const NeighbourList&, const MpsConstants&,
                                                    const ClassificationParameters&);
template std::vector<Category> classifyParticles<2>(const Particles<2>&, const MpsConstants&,
                                                    const ClassificationParameters&);
template std::vector<Category> classifyParticles<3>(const Particles<3>&, const MpsConstants&,
                                                    const ClassificationParameters&);

}  // namespace mistfall
