// TextureCloud: storage, motion, shedding and removal of the texture particles (see texture_cloud.hpp).
#include "texture/texture_cloud.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mps/erase_marked.hpp"

namespace mistfall {

namespace {

const Vec3 kNoMean = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());

enum class Fate : char { Stays = 0, Spent, Surfaced, Absorbed, LeftDomain };

}  // namespace

std::array<std::int64_t, kTextureKinds> TextureCloud::counts() const {
  std::array<std::int64_t, kTextureKinds> c{};
  for (auto k : kind) ++c[static_cast<int>(k)];
  return c;
}

void TextureCloud::append(TextureKind k, const Vec3& x, const Vec3& u, double d, double t, double v0) {
  const std::uint64_t new_id = next_id_++;
  position.push_back(x);
  velocity.push_back(u);
  CounterRng rng(params_.seed, new_id, 0, RandomStream::Birth);
  fluctuation.push_back(standardNormal3(rng));  // the stationary distribution of the Langevin state
  previous_mean.push_back(kNoMean);
  diameter.push_back(d);
  kind.push_back(k);
  id.push_back(new_id);
  birth_time.push_back(t);
  initial_volume.push_back(v0);
  shed.push_back(0);
  armed.push_back(0);
}

std::uint64_t TextureCloud::addParticle(TextureKind k, const Vec3& x, const Vec3& u, double d, double t) {
  append(k, x, u, d, t, isSource(k) ? sphereVolume(d) : representativeVolume(params_.shedding));
  return id.back();
}

std::uint64_t TextureCloud::addSource(TextureKind k, const Vec3& x, const Vec3& u, double t) {
  return addParticle(k, x, u, params_.source_diameter, t);
}

double TextureCloud::acrossPosition(std::uint64_t source_id) const {
  CounterRng rng(params_.seed, source_id, 0, RandomStream::Across);
  return (rng.uniform() - 0.5) * params_.width;
}

void TextureCloud::step(const FlowField& flow, double t, double dt) {
  ++step_;
  const auto n = static_cast<std::int64_t>(size());
  std::vector<char> fate(size(), static_cast<char>(Fate::Stays));
  const double ratio_in_gas = params_.liquid_density / params_.gas_density;
  const double ratio_in_liquid = params_.gas_density / params_.liquid_density;
#pragma omp parallel for schedule(static)
  for (std::int64_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const bool in_liquid = carriedByLiquid(kind[i]);
    const FlowSample f = flow.sample(in_liquid, position[i], t);
    if (!f.inside) {
      fate[i] = static_cast<char>(Fate::LeftDomain);
      continue;
    }
    // In its carrier (water for bubbles, air for droplets) a particle is armed; out of it, an armed particle (or
    // one past the birth grace) has surfaced or been absorbed. See texture_cloud.hpp.
    const bool in_carrier = in_liquid ? f.liquid_fraction >= 0.5 : f.liquid_fraction <= 0.5;
    if (in_carrier) {
      armed[i] = 1;
    } else if (armed[i] || t - birth_time[i] >= params_.birth_grace) {
      fate[i] = static_cast<char>(in_liquid ? Fate::Surfaced : Fate::Absorbed);
      continue;
    }
    CounterRng rng(params_.seed, id[i], static_cast<std::uint64_t>(step_), RandomStream::Fluctuation);
    fluctuation[i] = advanceFluctuation(params_.fluctuation, fluctuation[i], f.k, dt, rng);
    const Vec3 fluid_velocity = f.mean_velocity + fluctuationIntensity(f.k) * fluctuation[i];
    const Vec3 fluid_acceleration =
        std::isnan(previous_mean[i][0]) ? Vec3::Zero() : Vec3((f.mean_velocity - previous_mean[i]) / dt);
    previous_mean[i] = f.mean_velocity;
    DragParticle p;
    p.diameter = diameter[i];
    p.density_ratio = in_liquid ? ratio_in_liquid : ratio_in_gas;
    p.viscosity = in_liquid ? params_.liquid_viscosity : params_.gas_viscosity;
    p.added_mass = params_.added_mass;
    const MotionResult m = advanceParticle(p, velocity[i], fluid_velocity,
                                           forcingAcceleration(p, params_.gravity, fluid_acceleration), dt);
    velocity[i] = m.velocity;
    position[i] += m.displacement;
  }
  std::vector<char> remove(size(), 0);
  for (std::size_t i = 0; i < fate.size(); ++i) {
    switch (static_cast<Fate>(fate[i])) {
      case Fate::Stays: continue;
      case Fate::Surfaced: ++tally_.surfaced; break;
      case Fate::Absorbed: ++tally_.absorbed; break;
      default: ++tally_.left_domain; break;
    }
    remove[i] = 1;
    if (isSource(kind[i])) tally_.residual_volume += sourceVolume(i);
  }
  shedFromSources(t + dt, remove);
  erase(remove);
}

void TextureCloud::shedFromSources(double t_end, std::vector<char>& remove) {
  const SheddingParameters& sp = params_.shedding;
  const double v_rep = representativeVolume(sp);
  const std::size_t sources_end = size();  // representatives appended below are not sources
  for (std::size_t i = 0; i < sources_end; ++i) {
    if (remove[i] || !isSource(kind[i])) continue;
    const std::int32_t total = representativesOf(sp, initial_volume[i]);
    const std::int32_t due = std::min(total, representativesDue(sp, birth_time[i], t_end));
    for (std::int32_t j = shed[i] + 1; j <= due; ++j) {
      // Copies: append() may reallocate the arrays.
      const Vec3 x = position[i], u = velocity[i];
      append(shedKind(kind[i]), x, u, sp.fine_diameter, emissionTime(sp, birth_time[i], j), v_rep);
      armed.back() = armed[i];  // born where its source is: in the carrier if the source has been
      remove.push_back(0);
      tally_.shed_volume += v_rep;
    }
    shed[i] = std::max(shed[i], due);
    diameter[i] = sphereDiameter(sourceVolume(i));
    if (shed[i] >= total) {
      remove[i] = 1;
      ++tally_.spent;
      tally_.residual_volume += sourceVolume(i);
    }
  }
}

void TextureCloud::erase(const std::vector<char>& remove) {
  eraseMarked(remove, position, velocity, fluctuation, previous_mean, diameter, kind, id, birth_time, initial_volume,
              shed, armed);
}

}  // namespace mistfall
