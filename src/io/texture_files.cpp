// Writers and the binary reader of the texture stage's files (formats in texture_files.hpp).
#include "io/texture_files.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/vtk_writer.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "the texture files assume a little-endian host");

namespace {

constexpr char kMagic[8] = {'M', 'F', 'T', 'E', 'X', 'T', 'R', '1'};
constexpr std::uint32_t kVersion = 1;

template <class T>
void put(std::ostream& os, const T& v) {
  os.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <class T>
void putArray(std::ostream& os, const std::vector<T>& v) {
  if (!v.empty()) os.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int a = 0; a < 3; ++a) out[3 * i + a] = v[i][a];
  return out;
}

// Sequential reads from a byte buffer with a bounds check that names the file.
struct ByteReader {
  const std::filesystem::path& file;
  const std::string& bytes;
  std::size_t pos = 0;
  void read(void* out, std::size_t size) {
    if (pos + size > bytes.size())
      throw InputError("texture file '" + file.string() + "' is truncated");
    std::memcpy(out, bytes.data() + pos, size);
    pos += size;
  }
  template <class T>
  T get() {
    T v;
    read(&v, sizeof v);
    return v;
  }
};

}  // namespace

void writeTextureBinary(const std::filesystem::path& file, const TextureCloud& cloud, double time) {
  writeFileAtomically(file, [&](std::ostream& os) {
    os.write(kMagic, sizeof kMagic);
    put(os, kVersion);
    put(os, std::uint32_t{0});
    put(os, time);
    put(os, static_cast<std::uint64_t>(cloud.size()));
    putArray(os, flatten(cloud.position));
    putArray(os, flatten(cloud.velocity));
    putArray(os, cloud.diameter);
    putArray(os, cloud.kind);
    putArray(os, cloud.id);
  });
}

TextureSnapshot readTextureBinary(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "texture file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ByteReader r{file, bytes};
  char magic[8];
  r.read(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof magic) != 0)
    throw InputError("'" + file.string() + "' is not a mistfall texture file");
  if (const auto version = r.get<std::uint32_t>(); version != kVersion)
    throw InputError("texture file '" + file.string() + "' has version " + std::to_string(version) +
                             ", expected " + std::to_string(kVersion));
  r.get<std::uint32_t>();
  TextureSnapshot s;
  s.time = r.get<double>();
  const auto n = r.get<std::uint64_t>();
  if (n > bytes.size()) throw InputError("texture file '" + file.string() + "' is truncated");
  std::vector<double> pos(3 * n), vel(3 * n);
  r.read(pos.data(), pos.size() * sizeof(double));
  r.read(vel.data(), vel.size() * sizeof(double));
  s.diameter.resize(n);
  r.read(s.diameter.data(), n * sizeof(double));
  std::vector<std::uint8_t> kind(n);
  r.read(kind.data(), n);
  s.id.resize(n);
  r.read(s.id.data(), n * sizeof(std::uint64_t));
  if (r.pos != bytes.size()) throw InputError("texture file '" + file.string() + "' has trailing bytes");
  s.position.resize(n);
  s.velocity.resize(n);
  s.kind.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.position[i] = Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
    s.velocity[i] = Vec3(vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]);
    if (kind[i] >= kTextureKinds) throw InputError("texture file '" + file.string() + "' has a bad kind");
    s.kind[i] = static_cast<TextureKind>(kind[i]);
  }
  return s;
}

void writeTextureVtp(const std::filesystem::path& file, const TextureCloud& cloud, double time, bool ascii) {
  std::vector<std::uint8_t> kind(cloud.size());
  std::vector<std::int64_t> id(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    kind[i] = static_cast<std::uint8_t>(cloud.kind[i]);
    id[i] = static_cast<std::int64_t>(cloud.id[i]);
  }
  const std::vector<VtpArray> arrays = {{"velocity", 3, flatten(cloud.velocity)},
                                        {"diameter", 1, cloud.diameter},
                                        {"kind", 1, std::move(kind)},
                                        {"id", 1, std::move(id)}};
  writePointsVtp(file, flatten(cloud.position), arrays, time, ascii, "diameter");
}

void writeTextureCsv(const std::filesystem::path& file, const std::vector<TextureCountsRow>& rows) {
  writeFileAtomically(file, [&](std::ostream& os) {
    os << "time,droplets,mist,bubbles,micro_bubbles,spawned_droplets,spawned_bubbles,spent,surfaced,absorbed,"
          "left_domain,shed_volume,residual_volume\n";
    os << std::setprecision(10);
    for (const auto& r : rows) {
      os << r.time;
      for (auto c : r.counts) os << ',' << c;
      os << ',' << r.spawned_droplets << ',' << r.spawned_bubbles << ',' << r.tally.spent << ',' << r.tally.surfaced
         << ',' << r.tally.absorbed << ',' << r.tally.left_domain << ',' << r.tally.shed_volume << ','
         << r.tally.residual_volume << '\n';
    }
  });
}

}  // namespace mistfall
