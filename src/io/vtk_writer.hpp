// VTK XML PolyData (.vtp) output of the particles (one vertex cell per particle), readable by ParaView,
// and a reader for exactly the files this writer produces (used by tests and post-processing stages).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

// Writes all particles (escaped ones included; the `kind` array tells them apart) atomically.
//  Points: Float64 x3 (z = 0 in 2D). Verts: Int64 connectivity/offsets.
//  PointData: phase (UInt8), kind (UInt8), enclosed (UInt8), velocity (Float64 x3, padded), pressure,
//  number_density (Float64), and, when `category` is given, category (UInt8: the six-category classification of
//  src/classify, 0 for non-fluid particles; one value per particle).
//  FieldData: TIME (Float64, 1 value).
// ascii = false: appended raw little-endian data with UInt64 block headers; ascii = true: inline text.
template <int D>
void writeVtp(const std::filesystem::path& file, const Particles<D>& p, double time, bool ascii = false,
              const std::vector<std::uint8_t>* category = nullptr);

// What a frame holds besides the particles.
struct VtpFrameInfo {
  double time = 0.0;                   // the TIME field (0 if absent)
  bool ascii = false;                  // written with ascii = true (no appended data)
  std::vector<std::uint8_t> category;  // the category array; empty when the frame has none
  bool has_id = false;                 // the frame has the id array (else ids are 0, 1, ... in its order)
};

// Reads a file written by writeVtp (binary or ascii). Optionally returns the TIME field (0 if absent).
// Throws std::runtime_error naming the path on malformed input.
template <int D>
Particles<D> readVtp(const std::filesystem::path& file, double* time = nullptr);

// The same, also returning the format and the category array.
template <int D>
Particles<D> readVtp(const std::filesystem::path& file, VtpFrameInfo& info);
// One point-data array of a .vtp: `components` values per point (Float64, UInt8 or Int64).
using VtpArrayData = std::variant<std::vector<double>, std::vector<std::uint8_t>, std::vector<std::int64_t>>;
struct VtpArray {
  std::string name;
  int components = 1;
  VtpArrayData data;
};

// Any point cloud as a .vtp like writeVtp's (atomically): `points` x, y, z per point, the arrays as point data
// (`scalars` names the default one), the time as FieldData TIME / TimeValue.
void writePointsVtp(const std::filesystem::path& file, const std::vector<double>& points,
                    const std::vector<VtpArray>& point_data, double time, bool ascii, const std::string& scalars);

// The UInt8 (or Int64, values in [0, 255]) point array `name` of a .vtp (e.g. the classifier's "category"), or
// nullopt when the file has no such array. Throws std::runtime_error naming the path on malformed input.
std::optional<std::vector<std::uint8_t>> readVtpByteArray(const std::filesystem::path& file, const std::string& name);

}  // namespace mistfall
