// Binary restart checkpoints: writer, header probe and validating reader.
#include "io/checkpoint.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "checkpoints assume a little-endian host");
static_assert(sizeof(Vec<2>) == 2 * sizeof(double) && sizeof(Vec<3>) == 3 * sizeof(double));
static_assert(sizeof(ParticleKind) == 1 && sizeof(Phase) == 1);

namespace {

constexpr char kMagic[12] = {'M', 'I', 'S', 'T', 'F', 'A', 'L', 'L', 'C', 'K', 'P', 'T'};
constexpr char kEndMarker[12] = {'M', 'I', 'S', 'T', 'F', 'A', 'L', 'L', 'E', 'N', 'D', '!'};
constexpr std::uint32_t kVersion = 7;  // 2 added the enclosed flags, 3 the case fingerprint, 4 the particle ids,
                                       // 5 the vents' counts, 6 the entrained points' last forces, 7 the bubble
                                       // gas's reference pressures
constexpr std::uint32_t kOldestVersion = 2;  // still read (no fingerprint)
constexpr std::uint64_t kMaxFingerprint = 1 << 24;

struct Header {
  std::uint32_t version = kVersion;
  std::uint32_t dimension = 0;
  std::uint64_t count = 0;
  double time = 0.0;
  std::int64_t step = 0;
  double dt = 0.0;
  std::int64_t next_frame = 0;
  std::int64_t created = 0;
  std::int64_t removed = 0;
  std::string fingerprint;  // version 3: the case fingerprint (case/case_fingerprint.hpp)
  std::uint64_t next_id = 0;  // version 4: the id of the next particle made (older files: the particle count)
  std::int64_t vented_in = 0, vented_out = 0;  // version 5: the vents' gas created and removed (older files: 0)
};
// (Serialized field by field, so struct padding never reaches the file.)

// FNV-1a, 64 bit.
struct Checksum {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void add(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ULL;
  }
};

class Writer {
 public:
  explicit Writer(std::ostream& os) : os_(os) {}
  void raw(const void* data, std::size_t n) {
    sum_.add(data, n);
    os_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
  }
  template <class T>
  void value(const T& v) { raw(&v, sizeof(T)); }
  std::uint64_t checksum() const { return sum_.h; }

 private:
  std::ostream& os_;
  Checksum sum_;
};

// A checkpoint whose content is wrong is bad input (exit code 1), like any malformed file mistfall reads.
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw InputError("checkpoint '" + file.string() + "': " + what);
}

class Reader {
 public:
  explicit Reader(const std::filesystem::path& file) : file_(file), in_(file, std::ios::binary) {
    if (!in_) throwCannotOpen(file, "checkpoint");
    std::error_code ec;
    size_ = std::filesystem::file_size(file, ec);
    if (ec) throw std::runtime_error("checkpoint '" + file.string() + "': cannot determine its size");
  }
  void raw(void* data, std::size_t n) {
    if (n > remaining()) fail(file_, "file is truncated");
    in_.read(static_cast<char*>(data), static_cast<std::streamsize>(n));
    if (!in_) fail(file_, "file is truncated");
    pos_ += n;
    sum_.add(data, n);
  }
  template <class T>
  T value() {
    T v{};
    raw(&v, sizeof(T));
    return v;
  }
  std::uint64_t remaining() const { return size_ - pos_; }
  std::uint64_t checksum() const { return sum_.h; }
  void resetChecksum() { sum_ = Checksum{}; }

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  std::uint64_t size_ = 0, pos_ = 0;
  Checksum sum_;
};

Header readHeader(Reader& r, const std::filesystem::path& file) {
  char magic[sizeof(kMagic)];
  r.raw(magic, sizeof(magic));
  if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) fail(file, "not a mistfall checkpoint (wrong magic)");
  r.resetChecksum();
  Header h;
  h.version = r.value<std::uint32_t>();
  if (h.version < kOldestVersion || h.version > kVersion) {
    fail(file, "unsupported format version " + std::to_string(h.version) + " (this build reads versions " +
                   std::to_string(kOldestVersion) + " to " + std::to_string(kVersion) + ")");
  }
  h.dimension = r.value<std::uint32_t>();
  if (h.dimension != 2 && h.dimension != 3) fail(file, "invalid dimension " + std::to_string(h.dimension));
  h.count = r.value<std::uint64_t>();
  h.time = r.value<double>();
  h.step = r.value<std::int64_t>();
  h.dt = r.value<double>();
  h.next_frame = r.value<std::int64_t>();
  h.created = r.value<std::int64_t>();
  h.removed = r.value<std::int64_t>();
  if (h.version >= 3) {
    const auto length = r.value<std::uint64_t>();
    if (length > kMaxFingerprint || length > r.remaining()) fail(file, "file is truncated (bad fingerprint length)");
    h.fingerprint.resize(length);
    if (length) r.raw(h.fingerprint.data(), length);
  }
  h.next_id = h.version >= 4 ? r.value<std::uint64_t>() : h.count;
  if (h.version >= 5) {
    h.vented_in = r.value<std::int64_t>();
    h.vented_out = r.value<std::int64_t>();
  }
  return h;
}

template <class T>
void readVector(Reader& r, std::vector<T>& v, std::size_t n) {
  v.resize(n);
  if (n) r.raw(v.data(), n * sizeof(T));
}

}  // namespace

template <int D>
void writeCheckpoint(const std::filesystem::path& file, const SimulationState<D>& s, const std::string& fingerprint) {
  const Particles<D>& p = s.particles;
  const std::size_t n = p.size();
  if (p.velocity.size() != n || p.pressure.size() != n || p.number_density.size() != n || p.kind.size() != n ||
      p.phase.size() != n || p.enclosed.size() != n || p.id.size() != n) {
    throw std::runtime_error("writeCheckpoint '" + file.string() + "': particle arrays have different lengths");
  }
  writeFileAtomically(file, [&](std::ostream& os) {
    os.write(kMagic, sizeof(kMagic));
    Writer w(os);
    Header h;
    h.dimension = D;
    h.count = n;
    h.time = s.time;
    h.step = s.step;
    h.dt = s.dt;
    h.next_frame = s.next_frame;
    h.created = s.created;
    h.removed = s.removed;
    w.value(h.version);
    w.value(h.dimension);
    w.value(h.count);
    w.value(h.time);
    w.value(h.step);
    w.value(h.dt);
    w.value(h.next_frame);
    w.value(h.created);
    w.value(h.removed);
    const auto length = static_cast<std::uint64_t>(fingerprint.size());
    w.value(length);
    if (length) w.raw(fingerprint.data(), fingerprint.size());
    w.value(p.next_id);
    w.value(s.vented_in);
    w.value(s.vented_out);
    if (n) {
      w.raw(p.position.data(), n * sizeof(Vec<D>));
      w.raw(p.velocity.data(), n * sizeof(Vec<D>));
      w.raw(p.pressure.data(), n * sizeof(double));
      w.raw(p.number_density.data(), n * sizeof(double));
      w.raw(p.kind.data(), n);
      w.raw(p.phase.data(), n);
      w.raw(p.enclosed.data(), n);
      w.raw(p.id.data(), n * sizeof(std::uint64_t));
    }
    w.value(static_cast<std::uint64_t>(s.point_forces.size()));
    for (const auto& [id, force] : s.point_forces) {
      w.value(id);
      w.raw(force.data(), sizeof(Vec<D>));
    }
    w.value(static_cast<std::uint64_t>(s.gas_reference_pressure.size()));
    for (const auto& [id, reference] : s.gas_reference_pressure) {
      w.value(id);
      w.value(reference);
    }
    const std::uint64_t sum = w.checksum();
    os.write(reinterpret_cast<const char*>(&sum), sizeof(sum));
    os.write(kEndMarker, sizeof(kEndMarker));
  });
}

int checkpointDimension(const std::filesystem::path& file) {
  Reader r(file);
  return static_cast<int>(readHeader(r, file).dimension);
}

template <int D>
SimulationState<D> readCheckpoint(const std::filesystem::path& file, std::string* fingerprint) {
  Reader r(file);
  const Header h = readHeader(r, file);
  if (fingerprint) *fingerprint = h.fingerprint;
  if (h.dimension != D) {
    fail(file, "checkpoint is " + std::to_string(h.dimension) + "D, case is " + std::to_string(D) + "D");
  }
  // Check the size before allocating, so a corrupt count cannot ask for absurd memory.
  const std::uint64_t per_particle = 2 * sizeof(Vec<D>) + 2 * sizeof(double) + 3 + (h.version >= 4 ? 8 : 0);
  const std::uint64_t trailer = sizeof(std::uint64_t) + sizeof(kEndMarker);
  if (r.remaining() < trailer || h.count > (r.remaining() - trailer) / per_particle) {
    fail(file, "file is truncated (header says " + std::to_string(h.count) + " particles)");
  }
  SimulationState<D> s;
  s.time = h.time;
  s.step = h.step;
  s.dt = h.dt;
  s.next_frame = static_cast<int>(h.next_frame);
  s.created = h.created;
  s.removed = h.removed;
  s.vented_in = h.vented_in;
  s.vented_out = h.vented_out;
  const std::size_t n = h.count;
  Particles<D>& p = s.particles;
  readVector(r, p.position, n);
  readVector(r, p.velocity, n);
  readVector(r, p.pressure, n);
  readVector(r, p.number_density, n);
  readVector(r, p.kind, n);
  readVector(r, p.phase, n);
  readVector(r, p.enclosed, n);
  if (h.version >= 4) {
    readVector(r, p.id, n);
  } else {  // before ids: numbered in the checkpoint's order
    p.id.resize(n);
    for (std::size_t i = 0; i < n; ++i) p.id[i] = i;
  }
  p.next_id = h.next_id;
  if (h.version >= 6) {
    const auto forces = r.value<std::uint64_t>();
    if (forces > r.remaining() / (sizeof(std::uint64_t) + sizeof(Vec<D>)))
      fail(file, "file is truncated (bad count of point forces)");
    for (std::uint64_t k = 0; k < forces; ++k) {
      const auto id = r.value<std::uint64_t>();
      Vec<D> force;
      r.raw(force.data(), sizeof(Vec<D>));
      if (id >= p.next_id || !force.allFinite()) fail(file, "invalid point force");
      s.point_forces[id] = force;
    }
  }
  if (h.version >= 7) {
    const auto references = r.value<std::uint64_t>();
    if (references > r.remaining() / (sizeof(std::uint64_t) + sizeof(double)))
      fail(file, "file is truncated (bad count of reference pressures)");
    for (std::uint64_t k = 0; k < references; ++k) {
      const auto id = r.value<std::uint64_t>();
      const auto reference = r.value<double>();
      if (id >= p.next_id || !std::isfinite(reference)) fail(file, "invalid reference pressure");
      s.gas_reference_pressure[id] = reference;
    }
  }
  const std::uint64_t expected = r.checksum();
  const auto stored = r.value<std::uint64_t>();
  char end[sizeof(kEndMarker)];
  r.raw(end, sizeof(end));
  if (std::memcmp(end, kEndMarker, sizeof(kEndMarker)) != 0) fail(file, "missing end marker (truncated?)");
  if (stored != expected) fail(file, "checksum mismatch (file corrupted)");
  if (r.remaining() != 0) fail(file, "unexpected trailing bytes");
  for (std::size_t i = 0; i < n; ++i) {
    if (static_cast<std::uint8_t>(p.kind[i]) > static_cast<std::uint8_t>(ParticleKind::Point) ||
        static_cast<std::uint8_t>(p.phase[i]) > static_cast<std::uint8_t>(Phase::Gas) ||
        (p.enclosed[i] != 0 && p.enclosed[i] != 1) || p.id[i] >= p.next_id) {
      fail(file, "invalid particle kind/phase/enclosed value or id");
    }
  }
  return s;
}

template void writeCheckpoint<2>(const std::filesystem::path&, const SimulationState<2>&, const std::string&);
template void writeCheckpoint<3>(const std::filesystem::path&, const SimulationState<3>&, const std::string&);
template SimulationState<2> readCheckpoint<2>(const std::filesystem::path&, std::string*);
template SimulationState<3> readCheckpoint<3>(const std::filesystem::path&, std::string*);

}  // namespace mistfall
