// The texture cloud: droplets, mist, bubbles and micro-bubbles as a structure of arrays, and its time step.
// Each step (TextureCloud::step):
//   1. every particle (OpenMP-parallel, each with its own counter-based random stream): sample the carrying
//      fluid (flow_field.hpp), advance the fluctuation state (turbulent_fluctuation.hpp), move by eq. (18)-(19)
//      (particle_motion.hpp); a particle that left the grid is removed, and so is a droplet or mist particle that
//      entered the water (liquid fraction above 1/2) or a bubble or micro-bubble that reached the water surface
//      (below 1/2) -- once it is *armed*: it has been in its carrying phase at least once, or is older than the
//      birth grace. A source is born where the MPS particle was classified isolated, and the coarse grids still
//      carry that particle's own footprint and its neighbours' (in the dam-break smoke run of docs/texture.md,
//      32 of 78 isolated particles read as water at their own position), so the classifier's judgement is
//      trusted until the particle has left that footprint; fine particles inherit their source's state;
//   2. the sources shed the representatives now due (source_shedding.hpp), in particle order, and a spent source
//      is removed.
// Ids are handed out in a fixed order (sources as spawned, representatives in shedding order), and the random
// numbers depend only on (seed, id, step), so the cloud is the same on any thread count.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "texture/flow_field.hpp"
#include "texture/source_shedding.hpp"
#include "texture/texture_kind.hpp"
#include "texture/turbulent_fluctuation.hpp"

namespace mistfall {

struct TextureParameters {
  std::uint64_t seed = 1;
  SheddingParameters shedding;
  FluctuationParameters fluctuation;
  double added_mass = 0.5;      // C_M of eq. (18)
  double source_diameter = 0.0; // d_0 [m] of a new source (the MPS particle size)
  double birth_grace = 0.02;    // [s] a particle never yet in its carrying phase is not removed before this age
  double width = 0.1;           // extent across the fall [m]: a 2D run's sources start at z in [-width/2, width/2]
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);
  double liquid_density = 1000.0, gas_density = 1.2;                 // [kg/m^3]
  double liquid_viscosity = 1.0e-6, gas_viscosity = 1.5e-5;         // [m^2/s]
};

// Why particles left the cloud, and the volume ledger of the sources.
struct TextureTally {
  std::int64_t spent = 0;        // sources that shed all they could
  std::int64_t surfaced = 0;     // bubbles / micro-bubbles that reached the water surface
  std::int64_t absorbed = 0;     // droplets / mist that entered the water
  std::int64_t left_domain = 0;  // left the flow grid
  double shed_volume = 0.0;      // volume taken from sources by representatives [m^3]
  double residual_volume = 0.0;  // volume sources still held when they disappeared [m^3]
};

class TextureCloud {
 public:
  explicit TextureCloud(TextureParameters params) : params_(std::move(params)) {}

  // SoA: index i is particle i in every array.
  std::vector<Vec3> position, velocity;
  std::vector<Vec3> fluctuation;    // unit-variance state eta (turbulent_fluctuation.hpp)
  std::vector<Vec3> previous_mean;  // U seen at the previous step (NaN before the first): du_f/dt of eq. (18)
  std::vector<double> diameter;     // [m]
  std::vector<TextureKind> kind;
  std::vector<std::uint64_t> id;
  std::vector<double> birth_time;      // [s]
  std::vector<double> initial_volume;  // V_0 of a source [m^3] (a fine particle: its representative volume)
  std::vector<std::int32_t> shed;      // representatives shed so far (sources)
  std::vector<char> armed;             // has been in its carrying phase (or is past the birth grace)

  std::size_t size() const { return position.size(); }
  std::array<std::int64_t, kTextureKinds> counts() const;
  const TextureParameters& parameters() const { return params_; }
  const TextureTally& tally() const { return tally_; }
  std::int64_t step_index() const { return step_; }

  // A new droplet or bubble source at x with velocity u (kind Droplet or Bubble), born at time t, diameter
  // params.source_diameter. Returns its id.
  std::uint64_t addSource(TextureKind kind, const Vec3& x, const Vec3& u, double t);
  // Any particle of diameter d (a source's V_0 is its volume, a fine particle's its representative volume).
  std::uint64_t addParticle(TextureKind kind, const Vec3& x, const Vec3& u, double d, double t);
  // z across the fall for a source of a 2D run: uniform in [-width/2, width/2] from the seeded stream of `id`.
  double acrossPosition(std::uint64_t id) const;

  // Volume a source holds now (initial minus shed).
  double sourceVolume(std::size_t i) const { return remainingVolume(params_.shedding, initial_volume[i], shed[i]); }

  // Advances every particle from t to t + dt through `flow`, then sheds and removes (see the header).
  void step(const FlowField& flow, double t, double dt);

 private:
  void append(TextureKind kind, const Vec3& x, const Vec3& u, double d, double t, double v0);
  void shedFromSources(double t_end, std::vector<char>& remove);
  void erase(const std::vector<char>& remove);

  TextureParameters params_;
  TextureTally tally_;
  std::uint64_t next_id_ = 0;
  std::int64_t step_ = 0;
};

}  // namespace mistfall
