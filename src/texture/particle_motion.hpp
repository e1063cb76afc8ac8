// Motion of a texture particle (droplet, mist, bubble, micro-bubble), eq. (18) of Gotoh et al. with drag (19):
//   rho_f (rho_p/rho_f + C_M) A3 d^3 du_p/dt = 1/2 rho_f A2 d^2 C_D |u_f - u_p| (u_f - u_p)
//                                            + rho_f (1 + C_M) A3 d^3 du_f/dt + rho_f (rho_p/rho_f - 1) A3 d^3 g
//   C_D = 24/Re (1 + 0.15 Re^0.687),  Re = |u_f - u_p| d / nu_f,  A2 = pi/4, A3 = pi/6, C_M = 0.5.     (19)
// With A2 / (2 A3) = 3/4 the drag term is (u_f - u_p) / tau with the relaxation time
//   tau = (rho_p/rho_f + C_M) d^2 / (18 nu_f f(Re)),   f(Re) = 1 + 0.15 Re^0.687,
// so  du_p/dt = (u_f - u_p) / tau + a,  a = [(1 + C_M) du_f/dt + (rho_p/rho_f - 1) g] / (rho_p/rho_f + C_M).
// The drag is stiff (a 0.075 mm micro-bubble in water relaxes in tau ~ 1.6e-4 s, a mist droplet in air in
// ~ 1.7e-2 s), so a step of length h is integrated exactly for u_f, a and tau held fixed over the step:
//   u_p(h) = u_f + a tau + (u_p(0) - u_f - a tau) e^{-h/tau}
//   x_p(h) = x_p(0) + (u_f + a tau) h + (u_p(0) - u_f - a tau) tau (1 - e^{-h/tau}),
// stable for any h; tau is re-evaluated twice (Picard) from the mean relative speed over the step, and the fixed
// point u_p = u_f + a tau(|a tau|) is exactly the terminal velocity of eq. (18) at du_p/dt = 0.
// du_f/dt is the rate of change of the mean fluid velocity U seen along the particle's path (the caller's
// finite difference); the random fluctuation of eqs. (23)-(24) is left out of it (it has no derivative when
// redrawn every step).
#pragma once

#include <algorithm>
#include <cmath>

#include "mps/vector.hpp"

namespace mistfall {

using Vec3 = Vec<3>;

// The particle and the fluid around it.
struct DragParticle {
  double diameter = 0.0;        // d [m]
  double density_ratio = 1.0;   // rho_p / rho_f
  double viscosity = 0.0;       // nu_f [m^2/s] of the carrying fluid
  double added_mass = 0.5;      // C_M
};

// Schiller-Naumann correction of eq. (19): C_D Re / 24.
inline double dragCorrection(double reynolds) { return 1.0 + 0.15 * std::pow(reynolds, 0.687); }

// tau of the header at relative speed |u_f - u_p|.
inline double relaxationTime(const DragParticle& p, double relative_speed) {
  const double re = relative_speed * p.diameter / p.viscosity;
  return (p.density_ratio + p.added_mass) * p.diameter * p.diameter / (18.0 * p.viscosity * dragCorrection(re));
}

// a of the header: added-mass and buoyancy acceleration.
inline Vec3 forcingAcceleration(const DragParticle& p, const Vec3& gravity, const Vec3& fluid_acceleration) {
  return ((1.0 + p.added_mass) * fluid_acceleration + (p.density_ratio - 1.0) * gravity) /
         (p.density_ratio + p.added_mass);
}

struct MotionResult {
  Vec3 velocity;
  Vec3 displacement;
};

// One step of length h of du_p/dt = (u_f - u_p) / tau(|u_f - u_p|) + a by the exponential integrator of the header,
// for any drag law given as its relaxation time at a relative speed (also mps/entrained_bubbles.hpp).
template <class RelaxationTime>
MotionResult advanceRelaxing(const Vec3& velocity, const Vec3& fluid_velocity, const Vec3& forcing, double h,
                             RelaxationTime&& tau_at) {
  double tau = tau_at((fluid_velocity - velocity).norm());
  MotionResult r;
  for (int pass = 0; pass < 3; ++pass) {
    const Vec3 drift = fluid_velocity + forcing * tau;  // the velocity the particle relaxes to
    const double decay = std::exp(-h / tau);
    r.velocity = drift + (velocity - drift) * decay;
    r.displacement = drift * h + (velocity - drift) * (tau * (1.0 - decay));
    if (pass == 2) break;
    const double mean_slip = 0.5 * ((fluid_velocity - velocity).norm() + (fluid_velocity - r.velocity).norm());
    tau = tau_at(mean_slip);
  }
  return r;
}

// One step of length h of eq. (18) with the drag (19).
inline MotionResult advanceParticle(const DragParticle& p, const Vec3& velocity, const Vec3& fluid_velocity,
                                    const Vec3& forcing, double h) {
  return advanceRelaxing(velocity, fluid_velocity, forcing, h,
                         [&](double slip) { return relaxationTime(p, slip); });
}

}  // namespace mistfall
