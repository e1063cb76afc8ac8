// What of a case must not change across a resume. A checkpoint carries the fingerprint of the case it was
// written for (every key of the case file as a line "key = value", numbers in shortest round-trip form, so that
// 1 and 1.0 or 0.10 and 0.1 are the same); `simulate --resume` compares it with the run's case.toml and refuses
// a change of any key that changes the simulation, naming each, and notes a change of the harmless ones.
//
// Harmless (they change no particle of the simulation from the checkpoint on): output.end_time; the [classify],
// [texture] and [render] tables (later stages; `mistfall classify`, `texture --overwrite` and `render` redo
// them for the whole run); case.name and the names of regions, inflows and outflows (labels); numerics.dt_min
// and numerics.max_escaped_fraction (they only decide when a run is declared diverged).
// Every other key changes the simulation: [case] dimension, [domain], [physics], every other [numerics] key (a new
// one included), output.interval (the output times bound the time steps) and output.field_spacing (the flow
// grids of one run must match), the regions, inflows and outflows. A key added or removed counts as changed
// even when its value is the default.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mistfall {

// The fingerprint of a case file's text (throws CaseError on a TOML syntax error, prefixed with `source_name`).
std::string caseFingerprint(std::string_view toml_text, const std::string& source_name);

// Whether a change of `key` ("numerics.particle_spacing", "region[2].name") changes the simulation.
bool changesTheSimulation(std::string_view key);

struct CaseChange {
  std::string key;
  std::string before, after;  // the values; "(absent)" for a key on one side only
  bool harmless = false;
};

// The keys whose values differ between two fingerprints, in key order.
std::vector<CaseChange> compareFingerprints(const std::string& before, const std::string& after);

// "numerics.particle_spacing = 0.01 in the checkpoint, 0.005 in case.toml"
std::string describe(const CaseChange& change);

}  // namespace mistfall
