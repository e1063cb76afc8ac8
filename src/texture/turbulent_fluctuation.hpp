// Fluid velocity seen by a texture particle, eqs. (23)-(24) of Gotoh et al.:
//   u_f = (U + xi_x sqrt(u'^2), V + xi_y sqrt(v'^2), xi_z sqrt(w'^2)),  sqrt(u'^2) = sqrt(v'^2) = sqrt(w'^2)
//       = sqrt(2k/3)                                                                                    (23)-(24)
// with U, V the MPS mean field, k the SPS turbulence energy of eqs. (25)-(26), and the component across the fall
// (z in a 2D run) fluctuation only. The paper prints the same deviate for the x and z components; that would
// tie the two together, so each component here gets its own standard normal deviate.
// The fluctuation is carried as a unit-variance state eta per particle, u' = sqrt(2k/3) eta, evolved by one of:
//   redrawn  (the paper): eta is a fresh standard normal vector every step. The fluctuation is white noise of
//            correlation time dt, so a tracer's spread grows as sigma^2 = (2k/3) dt t: it depends on dt.
//   langevin (beyond the paper): eta is an Ornstein-Uhlenbeck process with the Lagrangian time scale T_L,
//            advanced exactly over a step:  eta' = eta e^{-dt/T_L} + sqrt(1 - e^{-2 dt/T_L}) xi.
//            A tracer's spread then grows as sigma^2 = 2 (2k/3) T_L [t - T_L (1 - e^{-t/T_L})], independent of dt.
// T_L from k: T_L = C_L k / eps with the dissipation of the one-equation SPS closure behind eqs. (25)-(26),
// eps = Ce k^{3/2} / Ds (Yoshizawa & Horiuti 1985), so T_L = C_L Ds / (Ce sqrt(k)). The default
// C_L = 1 / (1/2 + 3 C0 / 4) = 0.48 with C0 = 2.1 is the time scale of Pope's simplified Langevin model
// (Pope, Turbulent Flows, 2000, sec. 12.3).
#pragma once

#include <cmath>
#include <limits>

#include "texture/counter_rng.hpp"
#include "texture/fluctuation_model.hpp"
#include "texture/particle_motion.hpp"

namespace mistfall {

struct FluctuationParameters {
  FluctuationModel model = FluctuationModel::Redrawn;
  double time_scale_constant = 0.48;  // C_L
  double ce = 1.0;                    // Ce of eq. (26)
  double ds = 0.0;                    // Ds: the MPS particle size [m]
};

// Standard deviation of each fluctuation component, eq. (24).
inline double fluctuationIntensity(double k) { return k > 0.0 ? std::sqrt(2.0 * k / 3.0) : 0.0; }

// T_L = C_L Ds / (Ce sqrt(k)); infinite where k = 0 (no turbulence: the state is then frozen, and unused).
inline double lagrangianTimeScale(const FluctuationParameters& f, double k) {
  if (!(k > 0.0)) return std::numeric_limits<double>::infinity();
  return f.time_scale_constant * f.ds / (f.ce * std::sqrt(k));
}

inline Vec3 standardNormal3(CounterRng& rng) { return Vec3(rng.normal(), rng.normal(), rng.normal()); }

// Advances the unit state eta over a step dt at turbulence energy k.
inline Vec3 advanceFluctuation(const FluctuationParameters& f, const Vec3& eta, double k, double dt, CounterRng& rng) {
  const Vec3 xi = standardNormal3(rng);
  if (f.model == FluctuationModel::Redrawn) return xi;
  const double t_l = lagrangianTimeScale(f, k);
  if (!std::isfinite(t_l)) return eta;
  const double memory = std::exp(-dt / t_l);
  return eta * memory + xi * std::sqrt(std::max(0.0, 1.0 - memory * memory));
}

}  // namespace mistfall
