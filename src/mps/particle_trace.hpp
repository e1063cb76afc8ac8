// A developer's trace of one particle through the stages of its steps (`mistfall simulate --trace ID`): after each
// stage of MpsSolver::step, one CSV row for the particle and one for every particle within `reach` of it, so that a
// particle lost or thrown at speed can be followed to the stage and the pair that moved it (docs/waterfall.md used
// it for each traced loss). Rows: the step's start time and index, the stage just done, `self` or `near`, the
// particle's id, kind, phase, enclosed flag (delta_gl), whether it is in the gas system, its place, velocity,
// pressure (the liquid system's, and the gas system's where it has one), number density, and its distance from the
// traced particle in l0. Costs nothing when off (one pointer test a stage); when on, one pass over the particles a
// stage.
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

template <int D>
class ParticleTrace {
 public:
  // Writes to `path` (replaced) the stages of the steps that start at `from` or later.
  ParticleTrace(std::uint64_t id, double from, double reach, const std::string& path)
      : id_(id), from_(from), reach_(reach), out_(path) {
    out_ << "time,step,stage,row,id,kind,phase,enclosed,gas_system";
    const char* axes[] = {"x", "y", "z"};
    for (int d = 0; d < D; ++d) out_ << "," << axes[d];
    for (int d = 0; d < D; ++d) out_ << ",u" << axes[d];
    out_ << ",pressure,gas_pressure,number_density,distance_l0\n";
    out_.precision(10);
  }
  bool open() const { return static_cast<bool>(out_); }
  bool active(double step_time) const { return step_time >= from_; }

  // `gas_system(i)` says whether i is in the gas system; `gas_pressure` may be empty (no gas system this step).
  template <class InGas>
  void record(double time, std::int64_t step, const char* stage, const Particles<D>& p,
              const std::vector<double>& gas_pressure, double l0, InGas&& gas_system) {
    std::size_t self = p.size();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] == id_) self = i;
    if (self == p.size()) return;  // not made yet, or removed
    const double reach2 = reach_ * reach_;
    row(time, step, stage, "self", p, self, self, gas_pressure, l0, gas_system);
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != self && (p.position[j] - p.position[self]).squaredNorm() < reach2)
        row(time, step, stage, "near", p, j, self, gas_pressure, l0, gas_system);
    out_.flush();
  }

 private:
  template <class InGas>
  void row(double time, std::int64_t step, const char* stage, const char* what, const Particles<D>& p, std::size_t i,
           std::size_t self, const std::vector<double>& gas_pressure, double l0, InGas&& gas_system) {
    const double gas = i < gas_pressure.size() ? gas_pressure[i] : std::numeric_limits<double>::quiet_NaN();
    out_ << time << "," << step << "," << stage << "," << what << "," << p.id[i] << "," << int(p.kind[i]) << ","
         << int(p.phase[i]) << "," << int(p.enclosed[i]) << "," << int(gas_system(i));
    for (int d = 0; d < D; ++d) out_ << "," << p.position[i][d];
    for (int d = 0; d < D; ++d) out_ << "," << p.velocity[i][d];
    out_ << "," << p.pressure[i] << "," << gas << "," << p.number_density[i] << ","
         << (p.position[i] - p.position[self]).norm() / l0 << "\n";
  }

  std::uint64_t id_;
  double from_;
  double reach_;
  std::ofstream out_;
};

}  // namespace mistfall
