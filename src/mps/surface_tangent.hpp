// Which particles lie near a free surface, and the surface's normal there (numerics.scheme = "stabilised"): used by
// the repulsive term (pressure_repulsion.hpp) and the particle shifting (particle_shifting.hpp), which both act
// only along the surface near it, as Khayyer, Gotoh & Shimizu (2017, J. Comput. Phys. 332, 236) do with the
// shifting vector: a truncated neighbourhood has a first moment along the normal that is not disorder.
// A particle is near the surface when it is a free-surface particle (`surface(j)`) or one lies within re (of the
// Laplacian); its
// normal is the direction of the last step's pressure gradient (the free surface is an isobar). Near the surface
// with no gradient (free fall, a droplet) there is no normal: `near` without `normal`.
#pragma once

#include <vector>

#include "mps/pair_loop.hpp"

namespace mistfall {

template <int D>
struct SurfaceTangents {
  std::vector<char> near;      // a free-surface particle within re
  std::vector<Vec<D>> normal;  // unit normal where near and the last gradient is not zero, else zero

  bool empty() const { return near.empty(); }
  // P v: v without its normal part near the surface; v elsewhere
  Vec<D> alongSurface(std::size_t i, const Vec<D>& v) const { return v - v.dot(normal[i]) * normal[i]; }
};

template <int D, class Surface>
SurfaceTangents<D> surfaceTangents(const std::vector<Vec<D>>& position, const NeighbourList& nl, double re,
                                   const std::vector<Vec<D>>& last_gradient, Surface&& surface) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  SurfaceTangents<D> t;
  t.near.assign(n, 0);
  t.normal.assign(n, Vec<D>::Zero());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    bool near = surface(static_cast<std::int32_t>(i));
    forEachPairWithin<D>(i, position, nl, re, surface, [&](std::int32_t, const Vec<D>&, double, double) { near = true; });
    t.near[i] = near;
    const double norm = last_gradient[i].norm();
    if (near && norm > 0.0) t.normal[i] = last_gradient[i] / norm;
  }
  return t;
}

}  // namespace mistfall
