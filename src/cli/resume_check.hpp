// The checks `simulate --resume` makes before it writes anything: the checkpoint was written for the case in
// RUN_DIR/case.toml (its fingerprint, case/case_fingerprint.hpp) and matches the frames the run lists.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mps/simulation_state.hpp"

namespace mistfall {

// Throws InputError naming every key of case.toml changed since the checkpoint that changes the simulation, or
// what of frames.pvd and the last frame disagrees with the checkpoint (its time, frame count, particle count).
// Returns notes for the user: changes that do not change the simulation, a checkpoint without a fingerprint.
// With `accepted` (--accept-case-change), the changes that change the simulation are not refused: they are listed
// in *accepted (one "\n  key = ... in the checkpoint, ... in case.toml" each) and in a note.
template <int D>
std::vector<std::string> checkResume(const std::filesystem::path& run, const SimulationState<D>& state,
                                     const std::string& checkpoint_fingerprint, const std::string& case_fingerprint,
                                     std::string* accepted = nullptr);

}  // namespace mistfall
