// Output of the texture stage, one pair of files per frame plus a counts table:
//   texture_NNNNN.bin  little-endian binary, for renderers and tests (read back by readTextureBinary):
//       char[8]  magic "MFTEXTR1"
//       uint32   version (1)          uint32  reserved (0)
//       float64  time [s]             uint64  n (particles)
//       float64  position[n][3]  (x, y, z [m]; z across the fall in a 2D run)
//       float64  velocity[n][3]  [m/s]
//       float64  diameter[n]     [m]
//       uint8    kind[n]         (0 droplet, 1 mist, 2 bubble, 3 micro-bubble: TextureKind)
//       uint64   id[n]           (unique within the run; a fine particle's id is larger than its source's)
//   texture_NNNNN.vtp  the same as VTK PolyData for ParaView (point arrays velocity, diameter, kind, id).
//   texture.csv        one row per frame: time and the number of each kind, the sources spawned so far and why
//                      particles left (TextureTally), the volume shed and the volume sources took with them.
// Every file is written atomically (io/atomic_file.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "texture/texture_stage.hpp"

namespace mistfall {

struct TextureSnapshot {
  double time = 0.0;
  std::vector<Vec3> position, velocity;
  std::vector<double> diameter;
  std::vector<TextureKind> kind;
  std::vector<std::uint64_t> id;
};

void writeTextureBinary(const std::filesystem::path& file, const TextureCloud& cloud, double time);
// Throws std::runtime_error naming the path on a missing, truncated or foreign file.
TextureSnapshot readTextureBinary(const std::filesystem::path& file);

void writeTextureVtp(const std::filesystem::path& file, const TextureCloud& cloud, double time, bool ascii);

// Rewrites texture.csv atomically with all `rows`.
void writeTextureCsv(const std::filesystem::path& file, const std::vector<TextureCountsRow>& rows);

}  // namespace mistfall
