#include "mps/pressure_poisson.hpp"

#include <algorithm>
#include <cmath>

#include "mps/divergence.hpp"
#include "mps/weight.hpp"

namespace mistfall {

template <int D>
void assemblePressureSystem(const Particles<D>& p, const NeighborList& nl, const MpsConstants& c,
                            const std::array<PhaseProperties, 2>& phases, const std::vector<char>& surface,
                            PressureSourceTerm source, double dt, PressureSystem& sys) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  auto takesPart = [&](std::int64_t j) { return p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Wall; };

  sys.row_of.assign(n, -1);
  sys.particle_of.clear();
  for (std::int64_t i = 0; i < n; ++i)
    if (takesPart(i) && !surface[i]) {
      sys.row_of[i] = static_cast<std::int32_t>(sys.particle_of.size());
      sys.particle_of.push_back(static_cast<std::int32_t>(i));
    }
  const std::int64_t rows = static_cast<std::int64_t>(sys.particle_of.size());

  // Row lengths (diagonal + unknown neighbours inside re), then fill CSR directly.
  std::vector<std::int64_t> start(rows + 1, 0);
  const double re = c.re_laplacian;
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < rows; ++r) {
    const auto i = sys.particle_of[r];
    std::int64_t count = 1;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (sys.row_of[j] >= 0 && weight((p.position[j] - p.position[i]).norm(), re) > 0.0) ++count;
    }
    start[r + 1] = count;
  }
  for (std::int64_t r = 0; r < rows; ++r) start[r + 1] += start[r];

  sys.matrix.resize(rows, rows);
  sys.matrix.resizeNonZeros(start[rows]);
  auto* outer = sys.matrix.outerIndexPtr();
  auto* inner = sys.matrix.innerIndexPtr();
  auto* value = sys.matrix.valuePtr();
  for (std::int64_t r = 0; r <= rows; ++r) outer[r] = static_cast<int>(start[r]);
  sys.rhs.resize(rows);

  const double factor = c.laplacianFactor();
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < rows; ++r) {
    const auto i = sys.particle_of[r];
    const PhaseProperties& phase = phases[static_cast<int>(p.phase[i])];
    std::int64_t at = start[r];
    const std::int64_t diagonal_at = at++;
    double diagonal = 0.0;
    // Neighbour lists are sorted by cell, not by index: insert keeping the row's columns ascending.
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (!takesPart(j)) continue;
      const double w = weight((p.position[j] - p.position[i]).norm(), re);
      if (w <= 0.0) continue;
      diagonal += factor * w;
      if (sys.row_of[j] >= 0) {
        inner[at] = sys.row_of[j];
        value[at] = -factor * w;
        ++at;
      }
    }
    if (std::isfinite(phase.sound_speed)) diagonal += 1.0 / (dt * dt * phase.sound_speed * phase.sound_speed);
    inner[diagonal_at] = static_cast<int>(r);
    value[diagonal_at] = diagonal;
    // Sort the row's entries by column (Eigen requires ordered inner indices).
    std::vector<std::pair<int, double>> entries;
    entries.reserve(at - start[r]);
    for (std::int64_t k = start[r]; k < at; ++k) entries.emplace_back(inner[k], value[k]);
    std::sort(entries.begin(), entries.end());
    for (std::int64_t k = start[r]; k < at; ++k) {
      inner[k] = entries[k - start[r]].first;
      value[k] = entries[k - start[r]].second;
    }
    const double compression = (p.number_density[i] - c.n0) / c.n0;
    if (source.kind == PressureSource::Standard) {
      sys.rhs[r] = phase.density / (dt * dt) * compression;
    } else {
      auto carriesVelocity = [&](std::int32_t j) { return isActive(p.kind[j]); };
      const double divergence = divergenceAt<D>(i, p.position, p.velocity, nl, c, carriesVelocity);
      sys.rhs[r] = -phase.density / dt * divergence + source.relaxation * phase.density / (dt * dt) * compression;
    }
  }
}

template void assemblePressureSystem<2>(const Particles<2>&, const NeighborList&, const MpsConstants&,
                                        const std::array<PhaseProperties, 2>&, const std::vector<char>&,
                                        PressureSourceTerm, double, PressureSystem&);
template void assemblePressureSystem<3>(const Particles<3>&, const NeighborList&, const MpsConstants&,
                                        const std::array<PhaseProperties, 2>&, const std::vector<char>&,
                                        PressureSourceTerm, double, PressureSystem&);

}  // namespace mistfall
