// What a step reports of the particles and how a run stops (MpsSolver, solver.hpp): the fastest liquid and gas
// speeds, the fastest particle's role and place for the message of a divergence, the table of the last steps that
// diverged.txt ends with, the particles that left the domain, and the health check after each step.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "mps/solver.hpp"

namespace mistfall {

template <int D>
double MpsSolver<D>::maxFluidSpeed() const {
  const auto [liquid, gas] = maxPhaseSpeeds();
  return std::max(liquid, gas);
}

template <int D>
const char* MpsSolver<D>::roleOf(std::size_t i) const {
  const auto& p = state_.particles;
  return p.phase[i] != Phase::Gas ? "liquid" : (p.enclosed[i] ? "bubble gas" : "open gas");
}

// Which particle is the fastest, for a divergence's message: its id, role and place.
template <int D>
std::string MpsSolver<D>::fastestParticle() const {
  const auto& p = state_.particles;
  const std::size_t fastest = fluidSpeeds().fastest;
  if (fastest == p.size()) return "no fluid particle";
  return describeParticle(fastest);
}

template <int D>
std::string MpsSolver<D>::describeParticle(std::size_t i) const {
  const auto& p = state_.particles;
  std::ostringstream out;
  out << "particle id " << p.id[i] << ", " << roleOf(i) << ", at (";
  for (int d = 0; d < D; ++d) out << (d ? ", " : "") << p.position[i][d];
  out << ") m, pressure " << p.pressure[i] << " Pa";
  return out.str();
}

// The step about to be taken, for recentStepsCsv: its dt and the fastest fluid particle now.
template <int D>
void MpsSolver<D>::recordStep(double dt, std::size_t fastest) {
  const auto& p = state_.particles;
  RecentStep r;
  r.time = state_.time;
  r.step = state_.step;
  r.dt = dt;
  if (const std::size_t i = fastest; i < p.size()) {
    r.id = p.id[i];
    r.role = roleOf(i);
    r.position = p.position[i];
    r.speed = p.velocity[i].norm();
    r.pressure = p.pressure[i];
  }
  if (recent_steps_.size() == kRecentSteps) recent_steps_.pop_front();
  recent_steps_.push_back(r);
}

template <int D>
std::string MpsSolver<D>::recentStepsCsv() const {
  std::ostringstream out;
  out << std::setprecision(9) << "time,step,dt,id,role";
  for (int d = 0; d < D; ++d) out << "," << "xyz"[d];
  out << ",speed,pressure\n";
  for (const RecentStep& r : recent_steps_) {
    out << r.time << "," << r.step << "," << r.dt << "," << r.id << "," << r.role;
    for (int d = 0; d < D; ++d) out << "," << r.position[d];
    out << "," << r.speed << "," << r.pressure << "\n";
  }
  return out.str();
}

template <int D>
std::pair<double, double> MpsSolver<D>::maxPhaseSpeeds() const {
  const FluidSpeeds s = fluidSpeeds();
  return {s.liquid, s.gas};
}

// Each thread keeps its own fastest of each phase and its fastest particle; they are merged under a lock, and the
// first index wins a tie, so the answer does not depend on the number of threads.
template <int D>
typename MpsSolver<D>::FluidSpeeds MpsSolver<D>::fluidSpeeds() const {
  const auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  FluidSpeeds all;
  all.fastest = p.size();
  double top = -1.0;
#pragma omp parallel
  {
    FluidSpeeds mine;
    mine.fastest = p.size();
    double my_top = -1.0;
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < n; ++i) {
      if (p.kind[i] != ParticleKind::Fluid) continue;
      const double speed = p.velocity[i].norm();
      double& phase_top = p.phase[i] == Phase::Gas ? mine.gas : mine.liquid;
      phase_top = std::max(phase_top, speed);
      if (speed > my_top) my_top = speed, mine.fastest = static_cast<std::size_t>(i);
    }
#pragma omp critical(mistfall_fluid_speeds)
    {
      all.liquid = std::max(all.liquid, mine.liquid);
      all.gas = std::max(all.gas, mine.gas);
      if (my_top > top || (my_top == top && mine.fastest < all.fastest)) top = my_top, all.fastest = mine.fastest;
    }
  }
  return all;
}

template <int D>
void MpsSolver<D>::markEscaped() {
  auto& p = state_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid && p.kind[i] != ParticleKind::Point) continue;
    const auto& x = p.position[i];
    const bool inside = (x.array() >= domain_lower_.array()).all() && (x.array() <= domain_upper_.array()).all();
    if (!inside && x.allFinite()) {
      p.kind[i] = ParticleKind::Escaped;
      p.velocity[i].setZero();
      p.pressure[i] = 0.0;
    }
  }
}

template <int D>
void MpsSolver<D>::checkHealth(double) const {
  const auto& p = state_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !std::isfinite(p.pressure[i])) {
      std::ostringstream msg;
      msg << "particle " << i << " has a non-finite position, velocity or pressure";
      throw DivergenceError(msg.str(), state_.time, state_.step);
    }
  }
  // Every fluid particle that has existed: in the domain, driven in an inflow, escaped, or removed by an outflow.
  const std::size_t escaped = p.count(ParticleKind::Escaped);
  const std::size_t total = p.count(ParticleKind::Fluid) + p.count(ParticleKind::Inflow) +
                            p.count(ParticleKind::Point) + escaped + static_cast<std::size_t>(state_.removed);
  if (total > 0 && static_cast<double>(escaped) > config_.numerics.max_escaped_fraction * static_cast<double>(total)) {
    std::ostringstream msg;
    msg << escaped << " of " << total << " fluid particles have left the domain (more than "
        << "numerics.max_escaped_fraction = " << config_.numerics.max_escaped_fraction << ")";
    throw DivergenceError(msg.str(), state_.time, state_.step);
  }
}

#define MISTFALL_INSTANTIATE(D) \
  template double MpsSolver<D>::maxFluidSpeed() const; \
  template const char* MpsSolver<D>::roleOf(std::size_t) const; \
  template std::string MpsSolver<D>::describeParticle(std::size_t) const; \
  template std::string MpsSolver<D>::fastestParticle() const; \
  template void MpsSolver<D>::recordStep(double, std::size_t); \
  template std::string MpsSolver<D>::recentStepsCsv() const; \
  template std::pair<double, double> MpsSolver<D>::maxPhaseSpeeds() const; \
  template typename MpsSolver<D>::FluidSpeeds MpsSolver<D>::fluidSpeeds() const; \
  template void MpsSolver<D>::markEscaped(); \
  template void MpsSolver<D>::checkHealth(double) const;
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall
