// Entrained gas below a bubble's resolution as points that rise through the water (Euler-Lagrange), with eq. (18)
// of Gotoh et al. for their motion and eq. (7)'s interaction force returned to the water: numerics.
// entrained_bubble_diameter > 0 (docs/two-phase.md). It replaces the phase swaps of entrained_gas_rise.hpp.
//
// A gas particle of an enclosed region smaller than numerics.bubble_min_particles (phase_coupling.hpp) that lies
// deep in the water (the liquid's number density around it at least kConvertFraction n0) leaves the MPS lattice and
// becomes a point (ParticleKind::Point, ignored by every MPS operator) standing for bubbles of diameter d that fill
// its volume V = l0^D. The particle itself stays in the lattice as water, so the water keeps the bubbles' volume (a
// gap left in the lattice would close at 0.2 m/s, measured) and carries their weight, which the point's reaction
// below takes off again. The point moves by eq. (18) with the liquid as the carrying fluid:
//   (rho_g + C_M rho_l) V du_b/dt = F_D + rho_l (1 + C_M) V Du_l/Dt + (rho_g - rho_l) V g
//   F_D = (rho_g + C_M rho_l) V (u_l - u_b) / tau,   tau = 4 (rho_g/rho_l + C_M) d / (3 C_D |u_l - u_b|)
// with C_M = 1/2 and the drag coefficient of Tomiyama, Kataoka, Zun & Sakaguchi (1998) for a bubble in slightly
// contaminated water (tap water; their purified-water form has 16/Re and 48/Re),
//   C_D = max( min(24/Re (1 + 0.15 Re^0.687), 72/Re), 8/3 Eo/(Eo + 4) ),
//   Re = |u_l - u_b| d / nu_l,  Eo = (rho_l - rho_g) |g| d^2 / sigma  (sigma: physics.surface_tension),
// whose first branch is eq. (19) and whose last holds for a bubble its rise deforms (d above ~2 mm in water): the
// terminal rise in still water, C_D U^2 = 4/3 (1 - rho_g/rho_l) |g| d, is 0.23 m/s at d = 5 mm, the measured rise of
// air bubbles of that size (Clift, Grace & Weber 1978), where eq. (19) alone gives a rigid sphere's 0.44 m/s.
// u_l and Du_l/Dt are weighted means over the liquid particles within re of the point (weight (1 - r/re)^2): their
// velocity at the step's end and their velocity change over the step divided by dt (the water's material
// acceleration). A step is integrated exactly for u_l, Du_l/Dt and tau held fixed (texture/particle_motion.hpp).
//
// The water feels the bubbles (two-way coupling): the drag and added-mass force the water exerts on the point,
// F = F_D + rho_l C_M V (Du_l/Dt - du_b/dt), goes back to the same liquid particles with the same weights, as the
// momentum -F dt w_j / sum w. In still water at the terminal speed it is the bubbles' buoyancy (rho_l - rho_g) V |g|,
// pushing the water up: the drive of a bubble plume, in the dilute Euler-Lagrange form (the force without the
// pressure's part; e.g. Darmana, Deen & Kuipers 2005, Chem. Eng. Sci. 60, 3383). With the water's own weight on the kept volume, the
// mixture's weight is right: the lattice carries rho_l V g where the bubbles are, the reaction takes rho_l V g off.
// Du_l/Dt is the undisturbed water's: the drag and added mass already hold the flow the bubbles make themselves.
// The water's velocity change over a step holds one such part, the self-induced disturbance of two-way point
// coupling: the push a point gave the water at the end of the last step, which the projection of this step takes
// back. A point adds that push, as it reads it, back to the acceleration it reads: F_last sum_j s_j^2 / m, with
// F_last its force on the water over its last step (SimulationState::point_forces, kept in the checkpoint), s_j its
// normalised weights and m a water particle's mass. In still water the slip was 10 % under the terminal speed
// without it and is 2.4 % over with it (the projection keeps a part of the push in the water's velocity;
// tests/test_entrained_bubbles.cpp). In steady motion the echo of its force then cancels in what it reads.
//
// A point whose liquid number density falls below kReleaseFraction n0 has reached the surface or left the water: the
// water particle nearest to it becomes gas with the point's velocity (the water gives the volume back where the
// bubbles leave it) and the point is removed. That particle's momentum leaves the water with it: handing it to the
// water around, as a trial build did, adds kinetic energy (u_j given to a neighbour moving like it doubles the pair's
// energy), and waterfall_small's fastest particle reached 15-20 m/s within 1 s with it (11 m/s at most over 8.5 s
// without). A trial build put the gas at the point's own place instead and removed that water particle: the new gas
// crowds the air's lattice there (its stiff rows, c = 340 m/s), and waterfall_small's gas_correction_limit fired
// 34,543 times over 8.5 s against 1,016. The nearest water particle is searched outwards ring by ring of cells: a
// point inside an air pocket wider than re (under a plunging jet) gives its volume back at the pocket's edge. When
// only the cells within re were searched, such a point became a gas particle at its own place (`points_unpaired`),
// and points that had drifted together made gas particles within 0.3 mm of each other: on cases/waterfall.toml
// without the correction limit five did at 0.714 s, their rows read a number density of 28 against n0 = 7, and the
// pocket's gas went to 770 m/s the next step (5 escaped). Water particles less points is the water's count
// throughout, and gas particles plus points the gas's (a point with no water within kReleaseRings cells still
// becomes a gas particle at its own place, counted in `points_unpaired`).
// Coalescence: a point stands for the gas of one lattice place (l0^D), so two points closer than l0/2 hold more gas
// than the place they share; nothing else keeps points apart. Without this rule they gathered where the water
// carried them together (vortex cores, the valleys between wall particles) and stayed there as one: on
// cases/waterfall.toml (5 mm) 35 points sat within l0/2 of each other at 4-5 s, 956 pairs of them at the same
// place to 1e-4 l0; their reactions, all on the same few water particles, fed back through the acceleration they
// read until a water particle under 20 such points reached 150 m/s at 5.388 s and the step fell under dt_min.
// After the points move, in index order, a point closer than l0/2 to a point kept before it gives its gas back to
// the lattice as at the surface (the nearest water particle becomes gas): a cluster becomes gas that the lattice
// resolves, a bubble once it has bubble_min_particles particles. Gas does not leave the lattice as a point within
// l0/2 of a point (counted in EntrainedBubbleCounts::coalesced).
// A point is not moved closer than l0/2 to a wall or dummy particle (the part of its step towards one is taken
// away). Every point reads the water before any point pushes it, and the releases run serially in index order:
// the result does not depend on the order of the points or on the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "mps/particles.hpp"
#include "mps/phase_coupling.hpp"
#include "mps/weight.hpp"
#include "texture/particle_motion.hpp"

namespace mistfall {

// The liquid number density (/ n0) around a gas particle at which it leaves the lattice as a point, and below which
// a point returns to it. Their gap keeps a point that reaches the surface from turning back at once.
inline constexpr double kConvertFraction = 0.8;
inline constexpr double kReleaseFraction = 0.5;
// How many cells of edge re around a released point are searched for the water particle that turns into its gas.
inline constexpr int kReleaseRings = 16;

struct EntrainedBubbleModel {
  double diameter = 0.0;         // d [m]
  double liquid_density = 1000.0, gas_density = 1.2;
  double liquid_viscosity = 1e-6;  // nu_l [m^2/s]
  double surface_tension = 0.0728;  // sigma [N/m]
  double added_mass = 0.5;       // C_M
  double gravity = 9.81;         // |g| [m/s^2]

  double densityRatio() const { return gas_density / liquid_density; }
  double eotvos() const {
    return (liquid_density - gas_density) * gravity * diameter * diameter / surface_tension;
  }
  // C_D Re of Tomiyama et al. (1998), pure water: finite as Re -> 0 (24).
  double dragTimesReynolds(double reynolds) const {
    const double viscous = std::min(24.0 * dragCorrection(reynolds), 72.0);  // eq. (19)'s branch
    const double eo = eotvos();
    return std::max(viscous, 8.0 / 3.0 * eo / (eo + 4.0) * reynolds);
  }
  // tau of the header at relative speed `slip`.
  double relaxationTime(double slip) const {
    const double re = slip * diameter / liquid_viscosity;
    return 4.0 * (densityRatio() + added_mass) * diameter * diameter /
           (3.0 * liquid_viscosity * dragTimesReynolds(re));
  }
  // The terminal rise speed in still water, C_D U^2 = 4/3 (1 - rho_g/rho_l) |g| d (bisection).
  double terminalSpeed() const {
    double lo = 0.0, hi = 10.0;
    for (int k = 0; k < 200; ++k) {
      const double u = 0.5 * (lo + hi);
      const double cd = dragTimesReynolds(u * diameter / liquid_viscosity) * liquid_viscosity / (u * diameter);
      (cd * u * u < 4.0 / 3.0 * (1.0 - densityRatio()) * gravity * diameter ? lo : hi) = u;
    }
    return 0.5 * (lo + hi);
  }
};

struct EntrainedBubbleCounts {
  std::size_t made = 0;      // gas particles that became points in the step
  std::size_t released = 0;  // points that returned to the gas at the surface
  std::size_t unpaired = 0;  // ... of which became gas particles themselves (no water particle to give the volume)
  std::size_t wall_stops = 0;  // point steps shortened next to a wall
  std::size_t coalesced = 0;   // points that came within l0/2 of another and gave their gas back to the lattice
  std::vector<std::uint64_t> released_ids;  // the points to remove (their gas is now a surface particle's)
};

template <int D>
class EntrainedBubbles {
 public:
  EntrainedBubbles(const EntrainedBubbleModel& model, double l0, double re, double n0, const Vec<D>& gravity)
      : model_(model), l0_(l0), re_(re), n0_(n0), gravity_(gravity), cell_(re) {}

  // One step of length dt after the pressure corrections. `start_velocity` holds each particle's velocity at the
  // step's start (particles made since take their velocity now); `candidate[i]` marks the gas the step may turn into
  // points (enclosed, below a bubble's size, not a vent's).
  // `last_force` holds each point's force on the water over its last step, by id (SimulationState::point_forces);
  // the step replaces it.
  EntrainedBubbleCounts advance(Particles<D>& p, const std::vector<Vec<D>>& start_velocity,
                                const std::vector<char>& candidate, double dt,
                                std::map<std::uint64_t, Vec<D>>& last_force) {
    EntrainedBubbleCounts counts;
    bool any = false;
    for (std::size_t i = 0; i < p.size() && !any; ++i)
      any = p.kind[i] == ParticleKind::Point || (i < candidate.size() && candidate[i]);
    if (!any) {
      last_force.clear();
      return counts;
    }
    bin(p);
    const double mass = model_.liquid_density * std::pow(l0_, D);  // of a liquid particle
    std::vector<std::int32_t> near;
    std::vector<double> share;
    // At the surface: the water gives back the volume (serially, in index order).
    std::vector<char> leaving(p.size(), 0);
    for (std::size_t b = 0; b < p.size(); ++b) {
      if (p.kind[b] != ParticleKind::Point) continue;
      if (liquidAround(p, start_velocity, p.position[b], dt, near, share).number_density >= kReleaseFraction * n0_)
        continue;
      giveVolumeBack(p, b, leaving, counts);
      ++counts.released;
    }
    // Every point reads the water before any point pushes it, so that the result does not depend on their order.
    std::vector<Reading> readings;
    for (std::size_t b = 0; b < p.size(); ++b) {
      if (p.kind[b] != ParticleKind::Point || leaving[b]) continue;
      Reading r;
      r.point = b;
      r.liquid = liquidAround(p, start_velocity, p.position[b], dt, r.near, r.share);
      readings.push_back(std::move(r));
    }
    // The water's acceleration a point reads holds the projection's answer to the point's own push of the last step
    // (header): that push, as the point reads it, is added back.
    std::map<std::uint64_t, Vec<D>> pushed;
    for (Reading& r : readings) {
      Vec<D> al = r.liquid.acceleration;
      if (const auto it = last_force.find(p.id[r.point]); it != last_force.end()) {
        double self = 0.0;
        for (double s : r.share) self += s * s;
        al += it->second * (self / mass);
      }
      r.force = pointStep(p.velocity[r.point], r.liquid, al, dt, r.motion);
      pushed[p.id[r.point]] = r.force;
    }
    last_force = std::move(pushed);
    for (const Reading& r : readings) {
      for (std::size_t k = 0; k < r.near.size(); ++k) p.velocity[r.near[k]] += r.force * (dt * r.share[k] / mass);
      const std::size_t b = r.point;
      Vec<D> step = r.motion.displacement.template head<D>(), velocity = r.motion.velocity.template head<D>();
      counts.wall_stops += keepOffWalls(p, p.position[b], step, velocity);
      p.position[b] += step;
      p.velocity[b] = velocity;
      p.pressure[b] = r.liquid.pressure;
      p.number_density[b] = r.liquid.number_density;
    }
    coalesce(p, leaving, counts);
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n && i < candidate.size(); ++i) {
      if (!candidate[i] || !isGas(p.kind[i], p.phase[i])) continue;
      if (liquidAround(p, start_velocity, p.position[i], dt, near, share).number_density < kConvertFraction * n0_)
        continue;
      if (pointWithin(p.position[i])) continue;  // that place holds a point's gas already: the gas stays in the lattice
      points_[key(cellOf(p.position[i]))].push_back(p.position[i]);
      p.add(p.position[i], p.velocity[i], ParticleKind::Point, Phase::Gas);
      p.phase[i] = Phase::Liquid;  // the water keeps the volume: the particle stays in the lattice as water
      p.enclosed[i] = 0;
      ++counts.made;
    }
    return counts;
  }

 private:
  struct Liquid {
    double number_density = 0.0;  // sum of the MPS weight over the liquid within re
    double pressure = 0.0;
    Vec<D> velocity = Vec<D>::Zero(), acceleration = Vec<D>::Zero();
  };
  struct Reading {  // a point, the water around it, and its step
    std::size_t point = 0;
    Liquid liquid;
    std::vector<std::int32_t> near;
    std::vector<double> share;
    Vec<D> force = Vec<D>::Zero();  // on the water over the step (drag and added mass)
    MotionResult motion;
  };

  // Eq. (18) over one step for a point of velocity `u` in water `l` accelerating at `al`: its motion, and the force
  // the drag and the added mass put on the water (the reaction of the force the point feels).
  Vec<D> pointStep(const Vec<D>& u, const Liquid& l, const Vec<D>& al, double dt, MotionResult& motion) const {
    const double volume = std::pow(l0_, D);
    const double effective = (model_.gas_density + model_.added_mass * model_.liquid_density) * volume;
    const Vec3 ub = padded<D>(u), ul = padded<D>(l.velocity), a = padded<D>(al), g = padded<D>(gravity_);
    const double r = model_.densityRatio(), cm = model_.added_mass;
    const Vec3 forcing = ((1.0 + cm) * a + (r - 1.0) * g) / (r + cm);
    motion = advanceRelaxing(ub, ul, forcing, dt, [&](double s) { return model_.relaxationTime(s); });
    // F_D from eq. (18) with the step's du_b/dt, then the added-mass force; their reaction goes to the water.
    const Vec3 dub = (motion.velocity - ub) / dt;
    const Vec3 drag = effective * dub - model_.liquid_density * (1.0 + cm) * volume * a -
                      (model_.gas_density - model_.liquid_density) * volume * g;
    return (-(drag + model_.liquid_density * cm * volume * (a - dub))).template head<D>();
  }

  std::int64_t key(const Eigen::Matrix<std::int64_t, D, 1>& c) const {
    std::int64_t k = 0;
    for (int d = 0; d < D; ++d) k = k * 2000003 + c[d];
    return k;
  }
  Eigen::Matrix<std::int64_t, D, 1> cellOf(const Vec<D>& x) const {
    Eigen::Matrix<std::int64_t, D, 1> c;
    for (int d = 0; d < D; ++d) c[d] = static_cast<std::int64_t>(std::floor(x[d] / cell_));
    return c;
  }
  // The liquid (fluid and inflow particles of the liquid phase) and the walls and dummies, by cell of edge re.
  void bin(const Particles<D>& p) {
    cells_.clear();
    for (std::size_t j = 0; j < p.size(); ++j) {
      const bool liquid = (p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Inflow) &&
                          p.phase[j] == Phase::Liquid;
      const bool wall = p.kind[j] == ParticleKind::Wall || p.kind[j] == ParticleKind::Dummy;
      if ((liquid || wall) && p.position[j].allFinite())
        cells_[key(cellOf(p.position[j]))].push_back(static_cast<std::int32_t>(j));
    }
  }
  // Visits what `cells` (cells_ or points_) holds in the cells whose offset o from cell c has max |o_d| == ring
  // (ring < 0: every cell of the box within |ring|), the first axis fastest.
  template <class Cells, class Visit>
  void forEachInCells(const Cells& cells, const Eigen::Matrix<std::int64_t, D, 1>& c, int ring, Visit&& visit) const {
    const int reach = std::abs(ring);
    Eigen::Matrix<std::int64_t, D, 1> o = Eigen::Matrix<std::int64_t, D, 1>::Constant(-reach);
    while (true) {
      if (ring < 0 || o.cwiseAbs().maxCoeff() == ring)
        if (const auto it = cells.find(key(c + o)); it != cells.end())
          for (const auto& j : it->second) visit(j);
      int d = 0;
      while (d < D && o[d] == reach) o[d++] = -reach;
      if (d == D) break;
      ++o[d];
    }
  }
  // The particles binned in the cell of x and the cells around it (within re at least).
  template <class Visit>
  void forEachNear(const Vec<D>& x, Visit&& visit) const {
    forEachInCells(cells_, cellOf(x), -1, visit);
  }
  Liquid liquidAround(const Particles<D>& p, const std::vector<Vec<D>>& start_velocity, const Vec<D>& x, double dt,
                      std::vector<std::int32_t>& near, std::vector<double>& share) const {
    Liquid l;
    near.clear();
    share.clear();
    double total = 0.0;
    forEachNear(x, [&](std::int32_t j) {
      if (p.phase[j] != Phase::Liquid || !(p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Inflow))
        return;
      const double r = (p.position[j] - x).norm();
      if (r >= re_) return;
      l.number_density += weight(r, re_);
      const double w = (1.0 - r / re_) * (1.0 - r / re_);
      const Vec<D> before = static_cast<std::size_t>(j) < start_velocity.size() ? start_velocity[j] : p.velocity[j];
      l.velocity += w * p.velocity[j];
      l.acceleration += w * (p.velocity[j] - before) / dt;
      l.pressure += w * p.pressure[j];
      near.push_back(j);
      share.push_back(w);
      total += w;
    });
    if (total > 0.0) {
      l.velocity /= total;
      l.acceleration /= total;
      l.pressure /= total;
      for (double& s : share) s /= total;
    }
    return l;
  }
  // A point's gas goes back to the lattice: the water particle nearest to it becomes gas with the point's velocity
  // and the point is marked to leave; with no water particle near, the point itself becomes a gas particle.
  void giveVolumeBack(Particles<D>& p, std::size_t b, std::vector<char>& leaving, EntrainedBubbleCounts& counts) const {
    const std::int32_t nearest = nearestWater(p, p.position[b]);
    if (nearest >= 0) {
      p.phase[nearest] = Phase::Gas;
      p.enclosed[nearest] = 0;
      p.velocity[nearest] = p.velocity[b];  // the gas leaves with the bubbles' velocity
      counts.released_ids.push_back(p.id[b]);
      leaving[b] = 1;
    } else {
      p.kind[b] = ParticleKind::Fluid;
      ++counts.unpaired;
    }
  }
  // Coalescence (header): in index order, a point closer than l0/2 to a point kept before it gives its volume back
  // to the lattice; the points kept are binned in points_ for pointWithin.
  void coalesce(Particles<D>& p, std::vector<char>& leaving, EntrainedBubbleCounts& counts) {
    points_.clear();
    for (std::size_t b = 0; b < p.size(); ++b) {
      if (p.kind[b] != ParticleKind::Point || leaving[b]) continue;
      if (!pointWithin(p.position[b])) {
        points_[key(cellOf(p.position[b]))].push_back(p.position[b]);
        continue;
      }
      giveVolumeBack(p, b, leaving, counts);
      ++counts.coalesced;
    }
  }
  // Whether a point binned in points_ lies closer than l0/2 to x (the cells are re >= l0/2 wide).
  bool pointWithin(const Vec<D>& x) const {
    bool within = false;
    forEachInCells(points_, cellOf(x), -1,
                   [&](const Vec<D>& y) { within = within || (y - x).squaredNorm() < 0.25 * l0_ * l0_; });
    return within;
  }
  // The water particle nearest to x, searched ring by ring of cells outwards (up to kReleaseRings cells away): a
  // point in an air pocket wider than re gives its volume back at the pocket's edge. -1 if there is none that near.
  std::int32_t nearestWater(const Particles<D>& p, const Vec<D>& x) const {
    std::int32_t nearest = -1;
    double closest = 0.0;
    const auto c = cellOf(x);
    for (int ring = 0; ring <= kReleaseRings; ++ring) {
      // every cell of this ring is at least (ring - 1) cells away from x: stop when that is beyond the nearest found
      if (nearest >= 0 && (ring - 1) * cell_ > std::sqrt(closest)) break;
      forEachInCells(cells_, c, ring, [&](std::int32_t j) {
        if (p.kind[j] != ParticleKind::Fluid || p.phase[j] != Phase::Liquid) return;
        const double r = (p.position[j] - x).squaredNorm();
        if (nearest < 0 || r < closest) nearest = j, closest = r;
      });
    }
    return nearest;
  }
  // Takes away the part of `step` (and of `velocity`) that brings x closer than l0/2 to a wall or dummy particle.
  bool keepOffWalls(const Particles<D>& p, const Vec<D>& x, Vec<D>& step, Vec<D>& velocity) const {
    bool stopped = false;
    forEachNear(x + step, [&](std::int32_t j) {
      if (p.kind[j] != ParticleKind::Wall && p.kind[j] != ParticleKind::Dummy) return;
      const Vec<D> away = x + step - p.position[j];
      const double r = away.norm();
      if (r >= 0.5 * l0_ || r == 0.0) return;
      const Vec<D> n = away / r;
      const double in = step.dot(n);
      if (in < 0.0) step -= in * n, stopped = true;
      const double vin = velocity.dot(n);
      if (vin < 0.0) velocity -= vin * n;
    });
    return stopped;
  }

  EntrainedBubbleModel model_;
  double l0_, re_, n0_;
  Vec<D> gravity_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> cells_;
  std::unordered_map<std::int64_t, std::vector<Vec<D>>> points_;  // the points kept in the step, by cell
};

}  // namespace mistfall
