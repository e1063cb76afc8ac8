#include "mps/open_boundaries.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "case/scene.hpp"

namespace mistfall {

namespace {

// Lattice points of the box across the flow (all axes but the flow's), as positions with the flow coordinate 0.
template <int D>
std::vector<Vec<D>> crossSection(const CaseConfig& c, const Inflow& in) {
  std::vector<Vec<D>> points{Vec<D>::Zero()};
  for (int k = 0; k < D; ++k) {
    if (k == in.axis) continue;
    std::vector<Vec<D>> next;
    for (const double x : latticeCoordinates(c, in.box, k))
      for (Vec<D> q : points) {
        q[k] = x;
        next.push_back(q);
      }
    points.swap(next);
  }
  return points;
}

}  // namespace

template <int D>
std::int64_t advanceInflows(Particles<D>& p, const CaseConfig& c, double dt) {
  const double l0 = c.numerics.particle_spacing;
  std::int64_t created = 0;
  for (const Inflow& in : c.inflows) {
    const int a = in.axis;
    Vec<D> u = Vec<D>::Zero();
    u[a] = in.sign * in.speed;
    // Upstream face, and the flow coordinate of the upstream-most layer after the move (measured along the flow).
    const double face = in.sign > 0 ? in.box.min[a] : in.box.max[a];
    double upstream = std::numeric_limits<double>::infinity();
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (p.kind[i] != ParticleKind::Inflow || !insideBox<D>(p.position[i], in.box)) continue;
      p.velocity[i] = u;
      p.position[i] += dt * u;
      const double x = p.position[i][a];
      const bool released = in.sign > 0 ? x >= in.box.max[a] : x < in.box.min[a];
      if (released)
        p.kind[i] = ParticleKind::Fluid;
      else
        upstream = std::min(upstream, in.sign * x);
    }
    if (!std::isfinite(upstream)) upstream = in.sign * face + l0;  // an emptied buffer restarts at its face
    // New layers one l0 behind the upstream-most one while they lie inside the box (x >= min, or x < max).
    const std::vector<Vec<D>> section = crossSection<D>(c, in);
    for (double x = in.sign * (upstream - l0); in.sign > 0 ? x >= in.box.min[a] : x < in.box.max[a];
         x -= in.sign * l0) {
      for (Vec<D> q : section) {
        q[a] = x;
        p.add(q, u, ParticleKind::Inflow, Phase::Liquid);
        ++created;
      }
    }
  }
  return created;
}

template <int D>
std::int64_t removeOutflow(Particles<D>& p, const CaseConfig& c) {
  if (c.outflows.empty()) return 0;
  std::vector<char> remove(p.size(), 0);
  std::int64_t removed = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Liquid) continue;
    for (const Outflow& out : c.outflows)
      if (insideBox<D>(p.position[i], out.box)) {
        remove[i] = 1;
        ++removed;
        break;
      }
  }
  if (removed) p.erase(remove);
  return removed;
}

template std::int64_t advanceInflows<2>(Particles<2>&, const CaseConfig&, double);
template std::int64_t advanceInflows<3>(Particles<3>&, const CaseConfig&, double);
template std::int64_t removeOutflow<2>(Particles<2>&, const CaseConfig&);
template std::int64_t removeOutflow<3>(Particles<3>&, const CaseConfig&);

}  // namespace mistfall
