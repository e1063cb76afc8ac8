// A falling sheet in a coarse 2D run is a single file of particles drawn apart by gravity (the waterfall_small
// sheet: 2-5 l0 between neighbours below the brink, classified as droplets). To mesh it as the continuous sheet it
// stands for, consecutive particles of a jet are linked (docs/render.md, "Water"): particle i links to the
// `per_particle` nearest liquid particles j with
//   * |x_j - x_i| <= max_length l0 and i moving at >= min_speed,
//   * x_j ahead of i along its velocity: the angle between x_j - x_i and u_i at most max_angle,
//   * j moving the same way: the angle between u_i and u_j at most max_angle.
// A link is drawn as a capsule of half-thickness l0^2 / (2 |x_j - x_i|), clamped to [min_radius, max_radius] l0:
// a particle's area l0^2 spread along the link (the sheet thins as it stretches), never thinner than the mesh can
// resolve.
#pragma once

#include <vector>

#include "mps/vector.hpp"

namespace mistfall {

struct JetLinkParameters {
  double spacing = 0.0;      // l0 [m]
  double max_length = 6.0;   // [l0]
  double min_speed = 0.3;    // [m/s]
  double max_angle = 35.0;   // [deg]
  int per_particle = 2;      // links from each particle to the nearest ones ahead
  double min_radius = 0.35;  // [l0]
  double max_radius = 0.75;  // [l0]
};

struct SectionLink {
  Vec<2> a, b;
  double radius = 0.0;  // [m]
  int from = -1, to = -1;  // indices into the particles given
};

std::vector<SectionLink> jetLinks(const std::vector<Vec<2>>& position, const std::vector<Vec<2>>& velocity,
                                  const JetLinkParameters& parameters);

}  // namespace mistfall
