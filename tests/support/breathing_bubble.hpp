// The breathing bubble of issue 16, item 1 (tests/test_bubble_breathing.cpp, tests/test_one_equation.cpp): a
// cylindrical bubble of air, radius a = 2 cm, in a ring of water to b = 8 cm with a free surface, no gravity, the water
// started with the inward radial velocity U0 a / r of a bubble whose wall moves in at U0 (the gas squeezed
// uniformly). Linear theory of the 2D (cylindrical) Rayleigh-Plesset equation: rho_l a a'' ln(b/a) = P_B and
// P_B = -2 K da/a, so the bubble breathes at omega^2 = 2 K / (rho_l a^2 ln(b/a)) (the 2D analogue of Minnaert's
// frequency), with pressure amplitude 2 K U0 / (a omega), K the gas's bulk modulus.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "run_case.hpp"

namespace mistfall::test_support {

constexpr double kBreathingRadius = 0.02, kBreathingRing = 0.08, kBreathingGasDensity = 1.2,
                 kBreathingSoundSpeed = 340.0, kBreathingWallSpeed = 0.05;

// The case text at spacing l0 and time step dt, with `numerics` (lines) added to [numerics].
inline std::string breathingBubbleCase(double l0, double dt, const std::string& numerics) {
  char head[512];
  std::snprintf(head, sizeof head,
                "[case]\nname = \"breathing_bubble\"\ndimension = 2\n[domain]\nmin = [-0.1, -0.1]\nmax = [0.1, 0.1]\n"
                "[physics]\ngravity = [0.0, 0.0]\n[physics.gas]\nsound_speed = %g\ndensity = %g\n"
                "[numerics]\nparticle_spacing = %g\ndt_max = %g\n",
                kBreathingSoundSpeed, kBreathingGasDensity, l0, dt);
  char regions[512];
  std::snprintf(regions, sizeof regions,
                "[output]\nend_time = 1.0\n[[region]]\nname = \"ring\"\nmaterial = \"water\"\nshape = \"circle\"\n"
                "center = [0.0, 0.0]\nradius = %g\n[[region]]\nname = \"bubble\"\nmaterial = \"gas\"\n"
                "shape = \"circle\"\ncenter = [0.0, 0.0]\nradius = %g\n",
                kBreathingRing, kBreathingRadius);
  return std::string(head) + numerics + regions;
}

// The start: the water's u = -U0 a / r, the gas squeezed uniformly (u = -U0 r / a).
inline void startBreathing(Particles<2>& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = std::hypot(p.position[i][0], p.position[i][1]);
    if (r < 1e-12) continue;
    const double speed = p.phase[i] == Phase::Liquid ? kBreathingWallSpeed * kBreathingRadius / r
                                                     : kBreathingWallSpeed * r / kBreathingRadius;
    p.velocity[i] = Vec<2>{-speed * p.position[i][0] / r, -speed * p.position[i][1] / r};
  }
}

// The bubbles' mean pressure now (particle-weighted) and how many particles they hold.
inline double bubbleMeanPressure(MpsSolver<2>& solver, std::size_t* particles = nullptr) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& s : solver.currentBubbles()) sum += s.mean_pressure * s.particles, count += s.particles;
  if (particles) *particles = count;
  return count ? sum / count : 0.0;
}

}  // namespace mistfall::test_support
