// VTK XML PolyData (.vtp) writer (appended raw binary or ascii); the reader of the files it writes is vtp_reader.cpp.
#include "io/vtk_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/text_format.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian host");

namespace {

using ArrayData = VtpArrayData;
using Array = VtpArray;

const char* vtkTypeName(const ArrayData& d) {
  switch (d.index()) {
    case 0: return "Float64";
    case 1: return "UInt8";
    default: return "Int64";
  }
}

// Appends one appended-data block (UInt64 byte count + raw bytes) to `blob`.
void appendBlock(std::string& blob, const ArrayData& d) {
  std::visit(
      [&blob](const auto& v) {
        const std::uint64_t bytes = v.size() * sizeof(v[0]);
        blob.append(reinterpret_cast<const char*>(&bytes), sizeof(bytes));
        if (bytes) blob.append(reinterpret_cast<const char*>(v.data()), bytes);
      },
      d);
}

void writeAsciiValues(std::ostream& os, const ArrayData& d, const std::string& indent) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v[0])>;
        const std::size_t per_line = std::is_same_v<T, double> ? 6 : 20;
        for (std::size_t i = 0; i < v.size(); ++i) {
          if (i % per_line == 0) os << (i ? "\n" : "") << indent;
          else os << ' ';
          if constexpr (std::is_same_v<T, double>) os << text::formatDouble(v[i]);
          else os << static_cast<std::int64_t>(v[i]);
        }
        if (!v.empty()) os << '\n';
      },
      d);
}

// Writes one <DataArray>; in binary mode, appends its block to `blob` and references it by offset.
void writeArray(std::ostream& os, const Array& a, bool ascii, std::string& blob, const std::string& indent,
                bool field_data) {
  os << indent << "<DataArray type=\"" << vtkTypeName(a.data) << "\" Name=\"" << a.name << '"';
  if (field_data) {
    os << " NumberOfTuples=\"" << std::visit([](const auto& v) { return v.size(); }, a.data) << '"';
  }
  if (a.components != 1) os << " NumberOfComponents=\"" << a.components << '"';
  if (ascii) {
    os << " format=\"ascii\">\n";
    writeAsciiValues(os, a.data, indent + "  ");
    os << indent << "</DataArray>\n";
  } else {
    os << " format=\"appended\" offset=\"" << blob.size() << "\"/>\n";
    appendBlock(blob, a.data);
  }
}

template <int D>
std::vector<double> padTo3(const std::vector<Vec<D>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < D; ++k) out[3 * i + k] = v[i][k];
  return out;
}

template <class E>
std::vector<std::uint8_t> asBytes(const std::vector<E>& v) {
  std::vector<std::uint8_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = static_cast<std::uint8_t>(v[i]);
  return out;
}

}  // namespace

template <int D>
void writeVtp(const std::filesystem::path& file, const Particles<D>& p, double time, bool ascii,
              const std::vector<std::uint8_t>* category) {
  if (category && category->size() != p.size())
    throw std::invalid_argument("writeVtp: " + std::to_string(category->size()) + " categories for " +
                                std::to_string(p.size()) + " particles (" + file.string() + ")");
  std::vector<VtpArray> point_data = {
      {"phase", 1, asBytes(p.phase)},
      {"kind", 1, asBytes(p.kind)},
      {"enclosed", 1, asBytes(p.enclosed)},
      {"id", 1, std::vector<std::int64_t>(p.id.begin(), p.id.end())},
      {"velocity", 3, padTo3<D>(p.velocity)},
      {"pressure", 1, p.pressure},
      {"number_density", 1, p.number_density},
  };
  if (category) point_data.push_back({"category", 1, *category});
  writePointsVtp(file, padTo3<D>(p.position), point_data, time, ascii, "pressure");
}

void writePointsVtp(const std::filesystem::path& file, const std::vector<double>& points,
                    const std::vector<VtpArray>& point_data, double time, bool ascii, const std::string& scalars) {
  const std::size_t n = points.size() / 3;
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  // "TIME" as asked for by the pipeline; "TimeValue" is the name VTK/ParaView readers recognise as time.
  // Field data stays inline ascii (17 digits, exact) in both modes.
  const std::vector<VtpArray> field_data = {{"TIME", 1, std::vector<double>{time}},
                                            {"TimeValue", 1, std::vector<double>{time}}};

  writeFileAtomically(file, [&](std::ostream& os) {
    std::string blob;
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <PolyData>\n    <FieldData>\n";
    for (const auto& a : field_data) writeArray(os, a, true, blob, "      ", true);
    os << "    </FieldData>\n"
       << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
       << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
       << "      <PointData Scalars=\"" << scalars << "\" Vectors=\"velocity\">\n";
    for (const auto& a : point_data) writeArray(os, a, ascii, blob, "        ", false);
    os << "      </PointData>\n      <Points>\n";
    writeArray(os, {"Points", 3, points}, ascii, blob, "        ", false);
    os << "      </Points>\n      <Verts>\n";
    writeArray(os, {"connectivity", 1, std::move(connectivity)}, ascii, blob, "        ", false);
    writeArray(os, {"offsets", 1, std::move(offsets)}, ascii, blob, "        ", false);
    os << "      </Verts>\n    </Piece>\n  </PolyData>\n";
    text::writeVtkFileEnd(os, blob, ascii);
  });
}

template void writeVtp<2>(const std::filesystem::path&, const Particles<2>&, double, bool,
                          const std::vector<std::uint8_t>*);
template void writeVtp<3>(const std::filesystem::path&, const Particles<3>&, double, bool,
                          const std::vector<std::uint8_t>*);

}  // namespace mistfall
