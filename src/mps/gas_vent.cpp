#include "mps/gas_vent.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "case/scene.hpp"
#include "mps/open_boundaries.hpp"

namespace mistfall {

namespace {

// The lattice columns of a vent: one per lattice point of the box's cross-section (the axes but the vent's).
template <int D>
struct Columns {
  std::array<double, 3> first{0.0, 0.0, 0.0};  // the first lattice coordinate on each cross axis
  std::array<int, 3> count{1, 1, 1};           // lattice points on each cross axis (1 on the vent's axis)
  int total = 1;
  double outer = 0.0, inner = 0.0;             // the outer and inner faces, as outward coordinates sign * x[axis]

  Columns(const CaseConfig& c, const Vent& v) {
    for (int k = 0; k < D; ++k) {
      if (k == v.axis) continue;
      const std::vector<double> x = latticeCoordinates(c, v.box, k);
      first[k] = x.front();
      count[k] = static_cast<int>(x.size());
      total *= count[k];
    }
    outer = v.sign > 0 ? v.box.max[v.axis] : -v.box.min[v.axis];
    inner = v.sign > 0 ? v.box.min[v.axis] : -v.box.max[v.axis];
  }
  // The column of a point inside the box's cross-section (-1 outside it).
  int of(const Vec<D>& x, const Vent& v, double l0) const {
    int index = 0;
    for (int k = D - 1; k >= 0; --k) {
      if (k == v.axis) continue;
      if (x[k] < v.box.min[k] || x[k] >= v.box.max[k]) return -1;
      const int i = std::clamp(static_cast<int>(std::lround((x[k] - first[k]) / l0)), 0, count[k] - 1);
      index = index * count[k] + i;
    }
    return index;
  }
  // The lattice point of column `col` at outward coordinate xi.
  Vec<D> point(int col, double xi, const Vent& v, double l0) const {
    Vec<D> x = Vec<D>::Zero();
    for (int k = 0; k < D; ++k) {
      if (k == v.axis) continue;
      x[k] = first[k] + l0 * (col % count[k]);
      col /= count[k];
    }
    x[v.axis] = v.sign * xi;
    return x;
  }
};

// Gas that entered vent v's box in the step (in the domain at the step's start, inside the box now) joins its column
// on the column's line across the vent, keeping its place along it, with the column's velocity; where it would lie
// within l0/2 of another particle of the column (two arrived side by side within one column's width), it has left
// through the vent: it is removed (`remove`) and counted as gas out (the return value). Without this the air
// entering a vent kept its place across it, so neighbouring columns held pairs 0.2-0.4 l0 apart (waterfall_small's
// roof vent, at most frames), and when the flow turned such a pair came back into the domain at twice n0 and the
// gas correction threw it out at 100 m/s (docs/two-phase.md, twentieth session). (Snapping along the vent too, onto
// the column's sites l0 apart, removed the air arriving up to l0/2 early behind a column: the duct's air, drawn by
// the gap, left at 0.35 m/s instead of 0.2.) With `at_mouth` (numerics.vent_crowding_at_mouth) the domain's gas
// within l0/2 in front of the inner face counts too: gas that went back into the roof vent was put on its column's
// line 0.04 l0 from gas that had just left the box there, and the pair threw one of them across the 5 mm waterfall
// at 2,700 m/s (docs/waterfall.md, thirty-seventh session).
template <int D>
std::int64_t placeEnteringGas(Particles<D>& p, const Columns<D>& cols, const Vent& vent, std::size_t v,
                              const std::vector<int>& start_vent, const std::vector<double>& un, double l0,
                              bool at_mouth, std::vector<char>& remove) {
  const int a = vent.axis;
  const std::size_t n = start_vent.size();
  // Each column's gas along the vent's axis (its own, then what joins it).
  std::vector<std::vector<double>> held(cols.total);
  std::vector<std::pair<std::size_t, int>> entering;  // a particle and its column
  for (std::size_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Gas) continue;
    const double xi = vent.sign * p.position[i][a];
    const bool mouth = at_mouth && xi < cols.inner && xi >= cols.inner - 0.5 * l0;  // gas just out of the box
    if (!mouth && (xi < cols.inner || xi >= cols.outer)) continue;
    const int col = cols.of(p.position[i], vent, l0);
    if (col < 0) continue;
    if (start_vent[i] == static_cast<int>(v) || mouth) held[col].push_back(xi);
    else if (start_vent[i] < 0) entering.emplace_back(i, col);
  }
  std::int64_t left = 0;
  for (const auto& [i, col] : entering) {
    const double xi = vent.sign * p.position[i][a];
    auto& column = held[col];
    const bool taken =
        std::any_of(column.begin(), column.end(), [&](double other) { return std::abs(other - xi) < 0.5 * l0; });
    if (taken) {
      remove[i] = 1;
      ++left;
      continue;
    }
    column.push_back(xi);
    p.position[i] = cols.point(col, xi, vent, l0);
    p.velocity[i] = Vec<D>::Zero();
    p.velocity[i][a] = vent.sign * un[col];
  }
  return left;
}

// numerics.vent_liquid_stop (gas_vent.hpp): the columns of vent v drawn inward whose drive over dt would bring one of
// their particles within collision_distance of a liquid particle, approaching it, get u_n = 0. Returns how many.
template <int D>
std::int64_t holdColumnsAtLiquid(const Particles<D>& p, const CaseConfig& c, const Vent& vent, const Columns<D>& cols,
                                 const std::vector<int>& start_vent, const std::vector<Vec<D>>& start, std::size_t v,
                                 double dt, std::vector<double>& un) {
  const double l0 = c.numerics.particle_spacing, reach = c.numerics.collision_distance * l0;
  if (reach <= 0.0) return 0;
  // The liquid near the box (within l0 of it): the only liquid a column's step can reach.
  std::vector<Vec<D>> liquid;
  for (std::size_t i = 0; i < start_vent.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Liquid) continue;
    bool near = true;
    for (int k = 0; k < D; ++k)
      near = near && p.position[i][k] > vent.box.min[k] - l0 && p.position[i][k] < vent.box.max[k] + l0;
    if (near) liquid.push_back(p.position[i]);
  }
  if (liquid.empty()) return 0;
  std::vector<char> held(un.size(), 0);
  for (std::size_t i = 0; i < start_vent.size(); ++i) {
    if (start_vent[i] != static_cast<int>(v) || p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Gas) continue;
    const int col = cols.of(start[i], vent, l0);
    if (col < 0 || un[col] >= 0.0 || held[col]) continue;
    Vec<D> move = Vec<D>::Zero();
    move[vent.axis] = dt * vent.sign * un[col];
    for (const Vec<D>& q : liquid) {
      const Vec<D> r = q - start[i];
      if (move.dot(r) > 0.0 && (r - move).squaredNorm() < reach * reach) held[col] = 1;
    }
  }
  std::int64_t count = 0;
  for (std::size_t k = 0; k < un.size(); ++k)
    if (held[k]) un[k] = 0.0, ++count;
  return count;
}

}  // namespace

template <int D>
std::vector<int> ventOf(const Particles<D>& p, const CaseConfig& c) {
  std::vector<int> vent(p.size(), -1);
  if (c.vents.empty()) return vent;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    for (std::size_t v = 0; v < c.vents.size(); ++v)
      if (insideBox<D>(p.position[i], c.vents[v].box)) {
        vent[i] = static_cast<int>(v);
        break;
      }
  }
  return vent;
}

template <int D>
VentExchange exchangeVentGas(Particles<D>& p, const CaseConfig& c, const std::vector<int>& start_vent,
                             const std::vector<Vec<D>>& start, double dt, double gas_density, const Vec<D>& gravity) {
  VentExchange exchange;
  if (c.vents.empty()) return exchange;
  exchange.gas_in_by_vent.assign(c.vents.size(), 0);
  exchange.gas_out_by_vent.assign(c.vents.size(), 0);
  exchange.liquid_out_by_vent.assign(c.vents.size(), 0);
  const double l0 = c.numerics.particle_spacing;
  const std::size_t n = start_vent.size();  // the particles that existed at the step's start
  std::vector<char> remove(p.size(), 0);
  std::vector<Vec<D>> created_at;
  std::vector<Vec<D>> created_velocity;
  for (std::size_t v = 0; v < c.vents.size(); ++v) {
    const Vent& vent = c.vents[v];
    const Columns<D> cols(c, vent);
    const int a = vent.axis;
    // u_n of each column: the mean outward velocity of the domain's gas within 2 l0 in front of the inner face.
    std::vector<double> sum(cols.total, 0.0);
    std::vector<int> count(cols.total, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (start_vent[i] >= 0 || p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Gas) continue;
      const double xi = vent.sign * p.position[i][a];
      if (xi >= cols.inner || xi < cols.inner - 2.0 * l0) continue;
      const int col = cols.of(p.position[i], vent, l0);
      if (col < 0) continue;
      sum[col] += vent.sign * p.velocity[i][a];
      ++count[col];
    }
    std::vector<double> un(cols.total, 0.0);
    for (int k = 0; k < cols.total; ++k)
      if (count[k] > 0) un[k] = sum[k] / count[k];
    if (c.numerics.vent_liquid_stop)
      exchange.liquid_stops += holdColumnsAtLiquid<D>(p, c, vent, cols, start_vent, start, v, dt, un);
    // Drive the vent's gas; then remove what passed the outer face, and find the outermost fluid particle of each
    // column (what entered the box in the step included).
    for (std::size_t i = 0; i < n; ++i) {
      if (start_vent[i] != static_cast<int>(v) || p.kind[i] != ParticleKind::Fluid || p.phase[i] != Phase::Gas)
        continue;
      const int col = cols.of(start[i], vent, l0);
      if (col < 0) continue;
      p.velocity[i] = Vec<D>::Zero();
      p.velocity[i][a] = vent.sign * un[col];
      p.position[i] = start[i] + dt * p.velocity[i];
    }
    const std::int64_t left =
        placeEnteringGas<D>(p, cols, vent, v, start_vent, un, l0, c.numerics.vent_crowding_at_mouth, remove);
    exchange.gas_out += left;
    exchange.gas_crowded_out += left;
    exchange.gas_out_by_vent[v] += left;
    std::vector<double> outermost(cols.total, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (remove[i]) continue;
      if (p.kind[i] != ParticleKind::Fluid) continue;
      const double xi = vent.sign * p.position[i][a];
      if (xi < cols.inner) continue;
      // With liquid_exit = "inner_face", liquid leaves as soon as it is in the box: spray does not stand in a column.
      if (vent.liquid_exit == Vent::LiquidExit::InnerFace && p.phase[i] == Phase::Liquid &&
          insideBox<D>(p.position[i], vent.box)) {
        remove[i] = 1;
        ++exchange.liquid_out;
        ++exchange.liquid_out_by_vent[v];
        continue;
      }
      // Only a vent's own particles leave by it, also one that crossed the outer face beside the box's edge (water
      // sliding out along a wall next to the vent: it was counted as escaped, waterfall_small at 4.32 s).
      if (xi >= cols.outer && i < n && start_vent[i] == static_cast<int>(v)) {
        remove[i] = 1;
        ++(p.phase[i] == Phase::Gas ? exchange.gas_out : exchange.liquid_out);
        ++(p.phase[i] == Phase::Gas ? exchange.gas_out_by_vent : exchange.liquid_out_by_vent)[v];
        continue;
      }
      const int col = cols.of(p.position[i], vent, l0);
      if (col >= 0 && xi < cols.outer) outermost[col] = std::max(outermost[col], xi);
    }
    // New layers behind each column's outermost particle, one l0 apart, while they lie inside the box (an empty
    // column restarts at its inner face).
    for (int k = 0; k < cols.total; ++k) {
      double xi = std::isfinite(outermost[k]) ? outermost[k] : cols.inner - 0.5 * l0;
      for (xi += l0; xi < cols.outer; xi += l0) {
        created_at.push_back(cols.point(k, xi, vent, l0));
        ++exchange.gas_in_by_vent[v];
        Vec<D> u = Vec<D>::Zero();
        u[a] = vent.sign * un[k];
        created_velocity.push_back(u);
      }
    }
  }
  if (exchange.gas_out + exchange.liquid_out > 0) p.erase(remove);  // gas_out holds the crowded-out gas too
  for (std::size_t k = 0; k < created_at.size(); ++k) {
    p.add(created_at[k], created_velocity[k], ParticleKind::Fluid, Phase::Gas);
    p.pressure.back() = ambientPressure<D>(created_at[k], gas_density, gravity);
  }
  exchange.gas_in = static_cast<std::int64_t>(created_at.size());
  return exchange;
}

template std::vector<int> ventOf<2>(const Particles<2>&, const CaseConfig&);
template std::vector<int> ventOf<3>(const Particles<3>&, const CaseConfig&);
template VentExchange exchangeVentGas<2>(Particles<2>&, const CaseConfig&, const std::vector<int>&,
                                         const std::vector<Vec<2>>&, double, double, const Vec<2>&);
template VentExchange exchangeVentGas<3>(Particles<3>&, const CaseConfig&, const std::vector<int>&,
                                         const std::vector<Vec<3>>&, double, double, const Vec<3>&);

}  // namespace mistfall
