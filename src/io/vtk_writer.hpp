// VTK XML PolyData (.vtp) output of the particles (one vertex cell per particle), readable by ParaView,
// and a reader for exactly the files this writer produces (used by tests and post-processing stages).
#pragma once

#include <filesystem>

#include "mps/particles.hpp"

namespace mistfall {

// Writes all particles (escaped ones included; the `kind` array tells them apart) atomically.
//  Points: Float64 x3 (z = 0 in 2D). Verts: Int64 connectivity/offsets.
//  PointData: phase (UInt8), kind (UInt8), velocity (Float64 x3, padded), pressure, number_density (Float64).
//  FieldData: TIME (Float64, 1 value).
// ascii = false: appended raw little-endian data with UInt64 block headers; ascii = true: inline text.
template <int D>
void writeVtp(const std::filesystem::path& file, const Particles<D>& p, double time, bool ascii = false);

// Reads a file written by writeVtp (binary or ascii). Optionally returns the TIME field (0 if absent).
// Throws std::runtime_error naming the path on malformed input.
template <int D>
Particles<D> readVtp(const std::filesystem::path& file, double* time = nullptr);

}  // namespace mistfall
