// Binary restart checkpoints: the exact SimulationState (raw doubles, so a resume is bit-identical).
#pragma once

#include <filesystem>
#include <string>

#include "mps/simulation_state.hpp"

namespace mistfall {

// Layout (little-endian), version 6: "MISTFALLCKPT", uint32 version, uint32 dimension, uint64 particle count,
// float64 time, int64 step, float64 dt, int64 next_frame, int64 created, int64 removed (open boundaries), uint64
// length and the bytes of the case fingerprint (version 3; case/case_fingerprint.hpp: what a resume must not
// change), uint64 next_id (version 4), int64 vented_in, int64 vented_out (version 5), then position (N*D float64),
// velocity (N*D), pressure (N), number_density (N), kind (N uint8), phase (N uint8), enclosed (N uint8: delta_gl,
// the flag bubbles keep from step to step), id (N uint64; version 4), uint64 M and M pairs of uint64 id and D
// float64 (the entrained points' last forces, SimulationState::point_forces; version 6), uint64 FNV-1a checksum of
// every byte after the magic, and the end marker "MISTFALLEND!". Written atomically.
template <int D>
void writeCheckpoint(const std::filesystem::path& file, const SimulationState<D>& s,
                     const std::string& fingerprint = {});

// Throws InputError naming the path on: missing file, wrong magic, unsupported version, dimension mismatch
// ("checkpoint is 3D, case is 2D"), truncated or corrupted file; std::runtime_error when it cannot be read.
// Reads versions 2 (no fingerprint: *fingerprint is empty) to 6; what an older version lacks reads as its default.
template <int D>
SimulationState<D> readCheckpoint(const std::filesystem::path& file, std::string* fingerprint = nullptr);

// The dimension stored in the checkpoint header (2 or 3); same errors as readCheckpoint for the header.
int checkpointDimension(const std::filesystem::path& file);

}  // namespace mistfall
