// Shedding and shrinking of a texture source (droplet -> mist, bubble -> micro-bubble), eq. (20) of Gotoh et al.
// as volume bookkeeping. The printed eq. (20),
//   d(t) = d_0 - gamma_rm A2 d_m^3 / 3 (t - t_0),
// is dimensionally garbled (a volume times a time subtracted from a length); what it says is that the source
// shrinks, linearly in time, by the volume of the fine particles it sheds. Implemented as:
//   * a source is born with the diameter d_0 (default the MPS particle size) and volume V_0 = A3 d_0^3;
//   * it sheds N representatives (representatives_per_source, 500 in the paper) at the even rate N / T_life
//     (source_lifetime): the j-th (j = 1..N) at t_0 + j T_life / N;
//   * each representative stands for 1/gamma_rm real fine particles (representative_ratio gamma_rm = 1/250), so
//     it takes the volume V_rep = A3 d_m^3 / gamma_rm from the source: V(t) = V_0 - n(t) V_rep, linear in time
//     on average, and the diameter follows d = (V / A3)^{1/3};
//   * the source is spent, and disappears, after its N-th representative or when less than V_rep is left.
// With the paper's numbers (d_0 = 5 mm, d_m = 0.075 mm, 500 x 250 fine particles) a source sheds 42 % of its
// volume; the rest leaves with it when it is spent (counted as "residual" in texture.csv).
// shed volume + remaining volume = V_0 holds exactly at every time (n V_rep + (V_0 - n V_rep)).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace mistfall {

struct SheddingParameters {
  double fine_diameter = 7.5e-5;            // d_m = d_b [m]
  int representatives_per_source = 500;     // N
  double representative_ratio = 1.0 / 250;  // gamma_rm: representatives per real fine particle
  double source_lifetime = 0.5;             // T_life [s]
};

inline double sphereVolume(double diameter) { return std::numbers::pi / 6.0 * diameter * diameter * diameter; }
inline double sphereDiameter(double volume) { return std::cbrt(6.0 * std::max(volume, 0.0) / std::numbers::pi); }

// Volume one representative takes from its source.
inline double representativeVolume(const SheddingParameters& s) {
  return sphereVolume(s.fine_diameter) / s.representative_ratio;
}

// How many representatives a source of initial volume v0 sheds before it is spent.
inline std::int32_t representativesOf(const SheddingParameters& s, double v0) {
  const double by_volume = std::floor(v0 / representativeVolume(s));
  return static_cast<std::int32_t>(std::min<double>(s.representatives_per_source, by_volume));
}

// Representatives due by time t from a source born at t0 (not capped by the source's volume).
inline std::int32_t representativesDue(const SheddingParameters& s, double t0, double t) {
  const double fraction = (t - t0) / s.source_lifetime;
  const double due = std::floor(fraction * s.representatives_per_source * (1.0 + 1e-12));
  return static_cast<std::int32_t>(std::clamp(due, 0.0, double(s.representatives_per_source)));
}

// Emission time of the j-th representative (j = 1..N).
inline double emissionTime(const SheddingParameters& s, double t0, std::int32_t j) {
  return t0 + s.source_lifetime * j / s.representatives_per_source;
}

// Volume left in a source of initial volume v0 after shedding n representatives.
inline double remainingVolume(const SheddingParameters& s, double v0, std::int32_t n) {
  return v0 - n * representativeVolume(s);
}

}  // namespace mistfall
