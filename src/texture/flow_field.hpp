// The MPS flow as a texture particle sees it: mean velocity U, SPS turbulence energy k (eqs. (25)-(26)) and the
// local liquid fraction, for the phase that carries the particle (eqs. (21)-(22)). UniformFlow is a fixed field
// (tests, benchmarks); GridFlow samples the per-frame grids written by `simulate` (fields/fields_NNNNN.vti,
// io/grid_fields.hpp), linear in time between two frames and bilinear (2D) / trilinear (3D) in space:
//   U(x) = sum_n w_n C_n U_n / sum_n w_n C_n,   k(x) likewise,   C_n the phase's coverage at node n,
// so nodes the phase does not reach (C = 0, written with U = 0) do not drag the mean towards 0.
// liquid fraction = C_liquid / max(C_liquid + C_gas, C_full), the coverages interpolated the same way, with
// C_full the coverage of a filled neighbourhood, taken as the median of the nonzero total coverage over the
// earlier grid's nodes. Where both phases are simulated C_liquid + C_gas ~ C_full and this is the share of
// water; in a run without air (water alone) the empty space counts as air instead of 0/0.
// A 2D grid is extruded across the fall: z is ignored and U_z = 0.
#pragma once

#include <memory>

#include "io/grid_fields.hpp"
#include "texture/particle_motion.hpp"

namespace mistfall {

struct FlowSample {
  Vec3 mean_velocity = Vec3::Zero();  // U [m/s]
  double k = 0.0;                     // SPS turbulence energy [m^2/s^2]
  double liquid_fraction = 0.0;       // 0 in gas, 1 in water
  bool inside = true;                 // false outside the grid (the particle has left the domain)
};

class FlowField {
 public:
  virtual ~FlowField() = default;
  // The carrying fluid's field at x and time t: the liquid's (liquid = true) or the gas's.
  virtual FlowSample sample(bool liquid, const Vec3& x, double t) const = 0;
};

// The same sample everywhere, one per phase.
class UniformFlow final : public FlowField {
 public:
  UniformFlow(FlowSample gas, FlowSample liquid) : gas_(gas), liquid_(liquid) {}
  FlowSample sample(bool liquid, const Vec3&, double) const override { return liquid ? liquid_ : gas_; }

 private:
  FlowSample gas_, liquid_;
};

// Two frames' grids, earlier first (same grid). Throws std::runtime_error when an array is missing or the grids
// differ. `dimension` is the run's (2: z ignored).
class GridFlow final : public FlowField {
 public:
  GridFlow(std::shared_ptr<const ImageData> earlier, std::shared_ptr<const ImageData> later, int dimension);
  FlowSample sample(bool liquid, const Vec3& x, double t) const override;

 private:
  struct Weights;
  bool weights(const Vec3& x, Weights& w) const;
  // One phase's arrays of one frame: velocity (3 per node), k, own coverage, the other phase's coverage.
  struct PhaseArrays {
    const std::vector<double>*velocity, *k, *coverage, *other_coverage;
  };
  std::shared_ptr<const ImageData> frames_[2];
  PhaseArrays arrays_[2][2];  // [frame][liquid]
  double full_coverage_ = 0.0;  // C_full
  int dimension_;
};

}  // namespace mistfall
