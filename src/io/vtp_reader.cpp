// The reader of the VTK XML PolyData (.vtp) files vtk_writer.cpp writes (declared in vtk_writer.hpp): the frames
// read back as particles, and single byte arrays (the categories). Every error names the file.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/errors.hpp"
#include "io/text_format.hpp"
#include "io/vtk_writer.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "the VTK reader assumes a little-endian host");

namespace {

struct ArrayInfo {
  std::string type;
  int components = 1;
  bool appended = false;
  std::size_t offset = 0;
  std::string_view ascii_text;
};

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw InputError("malformed VTK file '" + file.string() + "': " + what);
}

template <class T>
std::vector<T> decodeArray(const std::filesystem::path& file, const std::string& name, const ArrayInfo& info,
                           std::string_view appended, std::size_t expected_values) {
  const char* want = std::is_same_v<T, double> ? "Float64" : std::is_same_v<T, std::uint8_t> ? "UInt8" : "Int64";
  if (info.type != want) fail(file, "array '" + name + "' has type " + info.type + ", expected " + want);
  std::vector<T> out(expected_values);
  if (info.appended) {
    if (info.offset + sizeof(std::uint64_t) > appended.size()) fail(file, "array '" + name + "' lies past the end");
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, appended.data() + info.offset, sizeof(bytes));
    if (bytes != expected_values * sizeof(T)) fail(file, "array '" + name + "' has the wrong size");
    if (info.offset + sizeof(bytes) + bytes > appended.size()) fail(file, "array '" + name + "' is truncated");
    if (bytes) std::memcpy(out.data(), appended.data() + info.offset + sizeof(bytes), bytes);
    return out;
  }
  std::size_t n = 0, pos = 0;
  const std::string_view s = info.ascii_text;
  while (true) {
    while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
    if (pos >= s.size()) break;
    std::size_t end = pos;
    while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end]))) ++end;
    if (n >= expected_values) fail(file, "array '" + name + "' has too many values");
    const std::string_view token = s.substr(pos, end - pos);
    if constexpr (std::is_same_v<T, double>) {
      auto v = text::parseDouble(token);
      if (!v) fail(file, "bad number '" + std::string(token) + "' in array '" + name + "'");
      out[n++] = *v;
    } else {
      auto v = text::parseInt(token);
      if (!v || (std::is_same_v<T, std::uint8_t> && (*v < 0 || *v > 255)))
        fail(file, "bad value '" + std::string(token) + "' in array '" + name + "'");
      out[n++] = static_cast<T>(*v);
    }
    pos = end;
  }
  if (n != expected_values) fail(file, "array '" + name + "' has too few values");
  return out;
}

// Rethrows `e` as a "malformed VTK file" error unless its message already names `file`.
[[noreturn]] void rethrowNamingFile(const std::filesystem::path& file, const std::runtime_error& e) {
  const std::string msg = e.what();
  if (msg.find(file.string()) != std::string::npos) throw;  // (the exception being handled, of its own type)
  fail(file, msg);
}

// A .vtp file read into memory with its DataArray headers indexed by name.
struct VtpDocument {
  std::filesystem::path file;
  std::string doc;
  std::string_view appended;
  std::map<std::string, ArrayInfo> arrays;
  std::size_t n = 0;  // points

  const ArrayInfo& get(const std::string& name, int components) const {
    auto it = arrays.find(name);
    if (it == arrays.end()) fail(file, "missing array '" + name + "'");
    if (it->second.components != components) fail(file, "array '" + name + "' has the wrong component count");
    if (it->second.appended && appended.empty()) fail(file, "array '" + name + "' refers to missing appended data");
    return it->second;
  }
  template <class T>
  std::vector<T> decode(const std::string& name, int components, std::size_t values) const {
    return decodeArray<T>(file, name, get(name, components), appended, values);
  }
};

// Reads and indexes `file`; every error is a std::runtime_error naming the path.
void parseVtp(const std::filesystem::path& file, VtpDocument& d) {
  d.file = file;
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "VTK file");
  d.doc.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("error reading VTK file '" + file.string() + "'");

  const std::string& doc = d.doc;
  try {
    // The XML header and the raw appended bytes (which may contain anything, including '<'); a truncated file lacks
    // the closing tag.
    const auto [header, appended] = text::splitVtkFile(doc);
    auto root = text::findTag(header, "VTKFile");
    if (!root || root->attr("type") != "PolyData") fail(file, "not a VTK PolyData file");
    if (!appended.empty() || text::findTag(header, "AppendedData")) {
      if (root->attr("byte_order") != "LittleEndian" || root->attr("header_type") != "UInt64")
        fail(file, "unsupported byte order or header type");
    }
    auto piece = text::findTag(header, "Piece");
    if (!piece) fail(file, "no <Piece>");
    auto n_points = text::parseInt(piece->attr("NumberOfPoints"));
    if (!n_points || *n_points < 0) fail(file, "bad NumberOfPoints");
    const auto n = static_cast<std::size_t>(*n_points);

    std::map<std::string, ArrayInfo> arrays;
    for (std::size_t pos = 0;;) {
      auto tag = text::findTag(header, "DataArray", pos);
      if (!tag) break;
      ArrayInfo info;
      info.type = tag->attr("type");
      if (auto c = tag->attr("NumberOfComponents"); !c.empty()) {
        auto v = text::parseInt(c);
        if (!v || *v < 1) fail(file, "bad NumberOfComponents");
        info.components = static_cast<int>(*v);
      }
      const std::string format = tag->attr("format");
      pos = tag->end;
      if (format == "appended") {
        auto off = text::parseInt(tag->attr("offset"));
        if (!off || *off < 0) fail(file, "bad offset");
        info.appended = true;
        info.offset = static_cast<std::size_t>(*off);
      } else if (format == "ascii") {
        if (!tag->self_closing) {
          const std::size_t close = header.find("</DataArray>", tag->end);
          if (close == std::string_view::npos) fail(file, "unterminated <DataArray>");
          info.ascii_text = header.substr(tag->end, close - tag->end);
          pos = close;
        }
      } else {
        fail(file, "unsupported DataArray format '" + format + "'");
      }
      arrays[tag->attr("Name")] = info;
    }
    d.appended = appended;
    d.arrays = std::move(arrays);
    d.n = n;
  } catch (const std::runtime_error& e) {
    rethrowNamingFile(file, e);
  }
}

}  // namespace

template <int D>
Particles<D> readVtp(const std::filesystem::path& file, double* time) {
  VtpFrameInfo info;
  Particles<D> p = readVtp<D>(file, info);
  if (time) *time = info.time;
  return p;
}

template <int D>
Particles<D> readVtp(const std::filesystem::path& file, VtpFrameInfo& frame) {
  VtpDocument d;
  parseVtp(file, d);
  const std::size_t n = d.n;
  try {
    const auto pos3 = d.decode<double>("Points", 3, 3 * n);
    const auto vel3 = d.decode<double>("velocity", 3, 3 * n);
    const auto pressure = d.decode<double>("pressure", 1, n);
    const auto density = d.decode<double>("number_density", 1, n);
    const auto kind = d.decode<std::uint8_t>("kind", 1, n);
    const auto phase = d.decode<std::uint8_t>("phase", 1, n);
    // "enclosed" (delta_gl) is absent from frames written before it existed: read as 0.
    const auto enclosed = d.arrays.count("enclosed")
                              ? d.decode<std::uint8_t>("enclosed", 1, n)
                              : std::vector<std::uint8_t>(n, 0);
    frame.category = d.arrays.count("category") ? d.decode<std::uint8_t>("category", 1, n)
                                                 : std::vector<std::uint8_t>();
    // "id" is absent from frames written before it existed: numbered 0, 1, ... in the frame's order.
    std::vector<std::int64_t> ids;
    frame.has_id = d.arrays.count("id") > 0;
    if (frame.has_id) ids = d.decode<std::int64_t>("id", 1, n);
    d.decode<std::int64_t>("connectivity", 1, n);
    d.decode<std::int64_t>("offsets", 1, n);

    Particles<D> p;
    p.position.resize(n);
    p.velocity.resize(n);
    p.pressure = pressure;
    p.number_density = density;
    p.kind.resize(n);
    p.phase.resize(n);
    p.enclosed.assign(enclosed.begin(), enclosed.end());
    p.id.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!ids.empty() && ids[i] < 0) fail(file, "invalid particle id");
      p.id[i] = ids.empty() ? i : static_cast<std::uint64_t>(ids[i]);
      p.next_id = std::max(p.next_id, p.id[i] + 1);
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < D; ++k) {
        p.position[i][k] = pos3[3 * i + k];
        p.velocity[i][k] = vel3[3 * i + k];
      }
      if (kind[i] > static_cast<std::uint8_t>(ParticleKind::Point)) fail(file, "invalid particle kind");
      if (phase[i] > static_cast<std::uint8_t>(Phase::Gas)) fail(file, "invalid particle phase");
      p.kind[i] = static_cast<ParticleKind>(kind[i]);
      p.phase[i] = static_cast<Phase>(phase[i]);
    }
    frame.ascii = d.appended.empty();
    frame.time = 0.0;
    for (const char* name : {"TIME", "TimeValue"}) {
      if (d.arrays.count(name)) {
        frame.time = d.decode<double>(name, 1, 1)[0];
        break;
      }
    }
    return p;
  } catch (const std::runtime_error& e) {
    rethrowNamingFile(file, e);
  }
}

std::optional<std::vector<std::uint8_t>> readVtpByteArray(const std::filesystem::path& file, const std::string& name) {
  VtpDocument d;
  parseVtp(file, d);
  const auto it = d.arrays.find(name);
  if (it == d.arrays.end()) return std::nullopt;
  if (it->second.type != "Int64") return d.decode<std::uint8_t>(name, 1, d.n);
  // An Int64 array of small values is accepted too.
  std::vector<std::uint8_t> out(d.n);
  const auto wide = d.decode<std::int64_t>(name, 1, d.n);
  for (std::size_t i = 0; i < d.n; ++i) {
    if (wide[i] < 0 || wide[i] > 255) fail(file, "array '" + name + "' has a value outside [0, 255]");
    out[i] = static_cast<std::uint8_t>(wide[i]);
  }
  return out;
}

template Particles<2> readVtp<2>(const std::filesystem::path&, double*);
template Particles<3> readVtp<3>(const std::filesystem::path&, double*);
template Particles<2> readVtp<2>(const std::filesystem::path&, VtpFrameInfo&);
template Particles<3> readVtp<3>(const std::filesystem::path&, VtpFrameInfo&);

}  // namespace mistfall
