// diagnostics.csv: column table (the single place that lists the columns), writer with resume, reader.
#include "io/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/text_format.hpp"

namespace mistfall {

namespace {

struct Column {
  const char* name;
  std::string (*format)(const DiagnosticsRow&);
  bool (*parse)(DiagnosticsRow&, std::string_view);
};

template <auto Member>
using MemberType = std::remove_cvref_t<decltype(std::declval<DiagnosticsRow&>().*Member)>;

template <auto Member, int Digits>
std::string formatMember(const DiagnosticsRow& r) {
  using T = MemberType<Member>;
  if constexpr (std::is_floating_point_v<T>) return text::formatDouble(r.*Member, Digits);
  else return std::to_string(r.*Member);
}

template <auto Member>
bool parseMember(DiagnosticsRow& r, std::string_view s) {
  using T = MemberType<Member>;
  if constexpr (std::is_floating_point_v<T>) {
    auto v = text::parseDouble(s);
    if (!v) return false;
    r.*Member = *v;
  } else {
    auto v = text::parseInt(s);
    if (!v) return false;
    if constexpr (std::is_unsigned_v<T>) {
      if (*v < 0) return false;
    }
    r.*Member = static_cast<T>(*v);
  }
  return true;
}

template <auto Member, int Digits = 9>
constexpr Column column(const char* name) {
  return {name, &formatMember<Member, Digits>, &parseMember<Member>};
}

// To add a column: add a field to DiagnosticsRow and one line here.
const Column kColumns[] = {
    column<&DiagnosticsRow::time, 17>("time"),
    column<&DiagnosticsRow::step>("step"),
    column<&DiagnosticsRow::dt, 17>("dt"),
    column<&DiagnosticsRow::liquid>("liquid"),
    column<&DiagnosticsRow::gas>("gas"),
    column<&DiagnosticsRow::wall>("wall"),
    column<&DiagnosticsRow::dummy>("dummy"),
    column<&DiagnosticsRow::escaped>("escaped"),
    column<&DiagnosticsRow::max_speed>("max_speed"),
    column<&DiagnosticsRow::kinetic_energy>("kinetic_energy"),
    column<&DiagnosticsRow::ppe_iterations>("ppe_iterations"),
    column<&DiagnosticsRow::ppe_residual>("ppe_residual"),
    column<&DiagnosticsRow::wall_seconds>("wall_seconds"),
    column<&DiagnosticsRow::gas_ppe_iterations>("gas_ppe_iterations"),
    column<&DiagnosticsRow::bubbles>("bubbles"),
    column<&DiagnosticsRow::bubble_particles>("bubble_particles"),
    column<&DiagnosticsRow::bubble_pressure>("bubble_pressure"),
    column<&DiagnosticsRow::bubble_x>("bubble_x"),
    column<&DiagnosticsRow::bubble_y>("bubble_y"),
    column<&DiagnosticsRow::bubble_z>("bubble_z"),
    column<&DiagnosticsRow::bubble_size>("bubble_size"),
    column<&DiagnosticsRow::inflow>("inflow"),
    column<&DiagnosticsRow::created>("created"),
    column<&DiagnosticsRow::removed>("removed"),
    column<&DiagnosticsRow::inflow_rate, 9>("inflow_rate"),
    column<&DiagnosticsRow::outflow_rate, 9>("outflow_rate"),
    column<&DiagnosticsRow::gas_capped>("gas_capped"),
    column<&DiagnosticsRow::collisions>("collisions"),
    column<&DiagnosticsRow::gradient_fallbacks>("gradient_fallbacks"),
    column<&DiagnosticsRow::thin_support>("thin_support"),
    column<&DiagnosticsRow::liquid_volume, 10>("liquid_volume"),
    column<&DiagnosticsRow::gas_volume, 10>("gas_volume"),
    column<&DiagnosticsRow::gas_compression, 10>("gas_compression"),
    column<&DiagnosticsRow::gas_pressure, 10>("gas_pressure"),
    column<&DiagnosticsRow::dispersed_gas>("dispersed_gas"),
    column<&DiagnosticsRow::entrained_swaps>("entrained_swaps"),
    column<&DiagnosticsRow::regularised_rows>("regularised_rows"),
    column<&DiagnosticsRow::gas_set_dt>("gas_set_dt"),
    column<&DiagnosticsRow::liquid_dt_steps, 9>("liquid_dt_steps"),
    column<&DiagnosticsRow::entrained_gas>("entrained_gas"),
    column<&DiagnosticsRow::gas_correction_capped>("gas_correction_capped"),
    column<&DiagnosticsRow::gas_speed_capped>("gas_speed_capped"),
    column<&DiagnosticsRow::largest_shift, 6>("largest_shift"),
    column<&DiagnosticsRow::vented_in>("vented_in"),
    column<&DiagnosticsRow::vented_out>("vented_out"),
    column<&DiagnosticsRow::shift_cuts>("shift_cuts"),
    column<&DiagnosticsRow::bubble_points>("bubble_points"),
    column<&DiagnosticsRow::points_made>("points_made"),
    column<&DiagnosticsRow::points_released>("points_released"),
    column<&DiagnosticsRow::point_wall_stops>("point_wall_stops"),
    column<&DiagnosticsRow::points_unpaired>("points_unpaired"),
    column<&DiagnosticsRow::gap_water_floors>("gap_water_floors"),
    column<&DiagnosticsRow::vent_crowded_out>("vent_crowded_out"),
    column<&DiagnosticsRow::shift_wall_stops>("shift_wall_stops"),
    column<&DiagnosticsRow::respacing_wall_stops>("respacing_wall_stops"),
    column<&DiagnosticsRow::respacing_cuts>("respacing_cuts"),
    column<&DiagnosticsRow::collision_wall_limits>("collision_wall_limits"),
    column<&DiagnosticsRow::vent_liquid_stops>("vent_liquid_stops"),
    column<&DiagnosticsRow::neighbour_surfaces>("neighbour_surfaces"),
    column<&DiagnosticsRow::liquid_wall_collisions>("liquid_wall_collisions"),
    column<&DiagnosticsRow::points_coalesced>("points_coalesced"),
    column<&DiagnosticsRow::bubble_gas_wall_stops>("bubble_gas_wall_stops"),
    column<&DiagnosticsRow::curvature_unfitted>("curvature_unfitted"),
    column<&DiagnosticsRow::long_respacings>("long_respacings"),
    column<&DiagnosticsRow::respacing_fluid_stops>("respacing_fluid_stops"),
    column<&DiagnosticsRow::largest_shift_id>("largest_shift_id"),
    column<&DiagnosticsRow::largest_shift_time, 12>("largest_shift_time"),
    column<&DiagnosticsRow::shift_bounded>("shift_bounded"),
};

std::vector<std::string_view> splitCsv(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace

std::string DiagnosticsWriter::header() {
  std::string h;
  for (const auto& c : kColumns) {
    if (!h.empty()) h += ',';
    h += c.name;
  }
  return h;
}

std::string DiagnosticsWriter::formatRow(const DiagnosticsRow& row) {
  std::string line;
  for (const auto& c : kColumns) {
    if (!line.empty()) line += ',';
    line += c.format(row);
  }
  return line;
}

std::vector<DiagnosticsRow> DiagnosticsWriter::read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "diagnostics file");
  std::string line;
  if (!std::getline(in, line)) throw InputError("diagnostics file '" + file.string() + "' is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  // Map each file column to a known column (or none).
  std::vector<const Column*> mapping;
  for (auto name : splitCsv(line)) {
    const Column* found = nullptr;
    for (const auto& c : kColumns)
      if (name == c.name) found = &c;
    mapping.push_back(found);
  }
  if (mapping.empty() || mapping[0] == nullptr || std::string_view(mapping[0]->name) != "time") {
    throw InputError("diagnostics file '" + file.string() + "' has an unexpected header");
  }
  std::vector<DiagnosticsRow> rows;
  std::size_t line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    const bool complete = !in.eof();  // getline hit a '\n'
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto fields = splitCsv(line);
    DiagnosticsRow row;
    bool ok = fields.size() == mapping.size();
    for (std::size_t i = 0; ok && i < fields.size(); ++i) {
      if (mapping[i]) ok = mapping[i]->parse(row, fields[i]);
    }
    if (!ok) {
      if (!complete) break;  // torn final line from an interrupted append
      throw InputError("diagnostics file '" + file.string() + "': bad line " + std::to_string(line_no));
    }
    rows.push_back(row);
  }
  return rows;
}

DiagnosticsWriter::DiagnosticsWriter(const std::filesystem::path& file, std::optional<double> resume_time)
    : file_(file) {
  std::vector<DiagnosticsRow> kept;
  if (resume_time && std::filesystem::exists(file_)) {
    for (const auto& r : read(file_))
      if (r.time <= *resume_time + 1e-12) kept.push_back(r);
  }
  // The header and kept rows are rewritten atomically (rows re-formatted, so added columns stay aligned).
  writeFileAtomically(file_, [&](std::ostream& os) {
    os << header() << '\n';
    for (const auto& r : kept) os << formatRow(r) << '\n';
  });
  out_.open(file_, std::ios::binary | std::ios::app);
  if (!out_) throw std::runtime_error("cannot open diagnostics file '" + file_.string() + "' for appending");
}

void DiagnosticsWriter::append(const DiagnosticsRow& row) {
  out_ << formatRow(row) << '\n';
  out_.flush();
  if (!out_) throw std::runtime_error("error writing diagnostics file '" + file_.string() + "'");
}

template <int D>
void measureParticles(DiagnosticsRow& row, const Particles<D>& p, double liquid_particle_mass,
                      double gas_particle_mass) {
  row.liquid = row.gas = row.wall = row.dummy = row.escaped = row.inflow = row.bubble_points = 0;
  double max_speed2 = 0.0, energy = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    switch (p.kind[i]) {
      case ParticleKind::Wall: ++row.wall; break;
      case ParticleKind::Dummy: ++row.dummy; break;
      case ParticleKind::Escaped: ++row.escaped; break;
      case ParticleKind::Inflow: ++row.inflow; break;
      case ParticleKind::Point: ++row.bubble_points; break;
      case ParticleKind::Fluid: {
        const bool liquid = p.phase[i] == Phase::Liquid;
        ++(liquid ? row.liquid : row.gas);
        const double u2 = p.velocity[i].squaredNorm();
        max_speed2 = std::max(max_speed2, u2);
        energy += 0.5 * (liquid ? liquid_particle_mass : gas_particle_mass) * u2;
        break;
      }
    }
  }
  row.max_speed = std::sqrt(max_speed2);
  row.kinetic_energy = energy;
}

template <int D>
void measurePhaseVolumes(DiagnosticsRow& row, const Particles<D>& p, double l0, double n0, double interior_fraction) {
  const double cell = std::pow(l0, D);
  double volume[2] = {0.0, 0.0}, compression = 0.0, pressure = 0.0;
  std::size_t interior_gas = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const bool gas = p.phase[i] == Phase::Gas;
    const double n = p.number_density[i];
    const bool interior = n >= interior_fraction * n0 && n > 0.0;
    volume[gas] += interior ? cell * n0 / n : cell;
    if (gas && interior) {
      compression += (n - n0) / n0;
      pressure += p.pressure[i];
      ++interior_gas;
    }
  }
  row.liquid_volume = volume[0];
  row.gas_volume = volume[1];
  row.gas_compression = interior_gas ? compression / static_cast<double>(interior_gas) : 0.0;
  row.gas_pressure = interior_gas ? pressure / static_cast<double>(interior_gas) : 0.0;
}

template void measurePhaseVolumes<2>(DiagnosticsRow&, const Particles<2>&, double, double, double);
template void measurePhaseVolumes<3>(DiagnosticsRow&, const Particles<3>&, double, double, double);
template void measureParticles<2>(DiagnosticsRow&, const Particles<2>&, double, double);
template void measureParticles<3>(DiagnosticsRow&, const Particles<3>&, double, double);

}  // namespace mistfall
