// The .vti (VTK XML ImageData) writer and reader of the grid fields (declared in grid_fields.hpp): appended raw
// binary or ascii Float64 arrays, written atomically; the reader takes back what the writer writes.
#include <bit>
#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/grid_fields.hpp"
#include "io/text_format.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian host");

// ---- .vti writing ----

namespace {

void writeDataArray(std::ostream& os, const std::string& name, int components, const std::vector<double>& v,
                    bool ascii, std::string& blob, const std::string& indent, bool field_data) {
  os << indent << "<DataArray type=\"Float64\" Name=\"" << text::xmlEscape(name) << '"';
  if (field_data) os << " NumberOfTuples=\"" << v.size() << '"';
  if (components != 1) os << " NumberOfComponents=\"" << components << '"';
  if (ascii) {
    os << " format=\"ascii\">\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i % 6 == 0) os << (i ? "\n" : "") << indent << "  ";
      else os << ' ';
      os << text::formatDouble(v[i]);
    }
    if (!v.empty()) os << '\n';
    os << indent << "</DataArray>\n";
  } else {
    os << " format=\"appended\" offset=\"" << blob.size() << "\"/>\n";
    const std::uint64_t bytes = v.size() * sizeof(double);
    blob.append(reinterpret_cast<const char*>(&bytes), sizeof(bytes));
    if (bytes) blob.append(reinterpret_cast<const char*>(v.data()), bytes);
  }
}

std::string extentText(const std::array<std::int64_t, 3>& dims) {
  return "0 " + std::to_string(dims[0] - 1) + " 0 " + std::to_string(dims[1] - 1) + " 0 " +
         std::to_string(dims[2] - 1);
}

std::string tripleText(const std::array<double, 3>& v) {
  return text::formatDouble(v[0]) + " " + text::formatDouble(v[1]) + " " + text::formatDouble(v[2]);
}

}  // namespace

void writeVti(const std::filesystem::path& file, const ImageData& image, bool ascii) {
  for (int k = 0; k < 3; ++k)
    if (image.dims[k] < 1) throw std::invalid_argument("writeVti: grid dimensions must be at least 1");
  for (const auto& a : image.arrays)
    if (a.components < 1 || a.values.size() != image.nodeCount() * static_cast<std::size_t>(a.components))
      throw std::invalid_argument("writeVti: array '" + a.name + "' holds " + std::to_string(a.values.size()) +
                                  " values, expected " + std::to_string(image.nodeCount()) + " x " +
                                  std::to_string(a.components));
  const std::string extent = extentText(image.dims);
  writeFileAtomically(file, [&](std::ostream& os) {
    std::string blob;
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << tripleText(image.origin) << "\" Spacing=\""
       << tripleText(image.spacing) << "\">\n    <FieldData>\n";
    // Field data stays inline ascii (17 digits, exact) in both modes, as in the .vtp frames.
    writeDataArray(os, "TimeValue", 1, {image.time}, true, blob, "      ", true);
    os << "    </FieldData>\n    <Piece Extent=\"" << extent << "\">\n      <PointData>\n";
    for (const auto& a : image.arrays)
      writeDataArray(os, a.name, a.components, a.values, ascii, blob, "        ", false);
    os << "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n";
    text::writeVtkFileEnd(os, blob, ascii);
  });
}

// ---- .vti reading ----

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw InputError("malformed VTK ImageData file '" + file.string() + "': " + what);
}

// Whitespace-separated numbers of `s`, or nullopt-like failure reported through `ok`.
std::vector<double> parseNumbers(std::string_view s, bool& ok) {
  std::vector<double> out;
  ok = true;
  std::size_t pos = 0;
  while (true) {
    while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
    if (pos >= s.size()) return out;
    std::size_t end = pos;
    while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end]))) ++end;
    const auto v = text::parseDouble(s.substr(pos, end - pos));
    if (!v) {
      ok = false;
      return out;
    }
    out.push_back(*v);
    pos = end;
  }
}

}  // namespace

ImageData readVti(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "VTK ImageData file");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("error reading VTK ImageData file '" + file.string() + "'");
  try {
    // The XML header and the raw appended bytes (which may contain anything); a truncated file lacks the closing tag.
    const auto [header, appended] = text::splitVtkFile(doc);
    auto root = text::findTag(header, "VTKFile");
    if (!root || root->attr("type") != "ImageData") fail(file, "not a VTK ImageData file");
    if (!appended.empty() && (root->attr("byte_order") != "LittleEndian" || root->attr("header_type") != "UInt64"))
      fail(file, "unsupported byte order or header type");
    auto grid = text::findTag(header, "ImageData");
    if (!grid) fail(file, "no <ImageData>");

    ImageData image;
    bool ok = false;
    const auto extent = parseNumbers(grid->attr("WholeExtent"), ok);
    if (!ok || extent.size() != 6) fail(file, "bad WholeExtent");
    const auto origin = parseNumbers(grid->attr("Origin"), ok);
    if (!ok || origin.size() != 3) fail(file, "bad Origin");
    const auto spacing = parseNumbers(grid->attr("Spacing"), ok);
    if (!ok || spacing.size() != 3) fail(file, "bad Spacing");
    for (int k = 0; k < 3; ++k) {
      if (extent[2 * k] != 0.0 || !(extent[2 * k + 1] >= 0.0) || extent[2 * k + 1] > kMaxGridNodes ||
          extent[2 * k + 1] != std::floor(extent[2 * k + 1]))
        fail(file, "WholeExtent must be '0 nx-1 0 ny-1 0 nz-1'");
      image.dims[k] = static_cast<std::int64_t>(extent[2 * k + 1]) + 1;
      image.origin[k] = origin[k];
      image.spacing[k] = spacing[k];
    }
    if (static_cast<double>(image.dims[0]) * double(image.dims[1]) * double(image.dims[2]) > kMaxGridNodes)
      fail(file, "too many nodes");
    const std::size_t nodes = image.nodeCount();

    bool have_time = false;
    for (std::size_t pos = 0;;) {
      auto tag = text::findTag(header, "DataArray", pos);
      if (!tag) break;
      pos = tag->end;
      const std::string name = tag->attr("Name");
      if (tag->attr("type") != "Float64") fail(file, "array '" + name + "' is not Float64");
      int components = 1;
      if (auto c = tag->attr("NumberOfComponents"); !c.empty()) {
        auto v = text::parseInt(c);
        if (!v || *v < 1 || *v > 64) fail(file, "bad NumberOfComponents of array '" + name + "'");
        components = static_cast<int>(*v);
      }
      const bool is_time = name == "TimeValue" || name == "TIME";
      const std::size_t expected = is_time ? 1 : nodes * static_cast<std::size_t>(components);
      std::vector<double> values;
      const std::string format = tag->attr("format");
      if (format == "appended") {
        const auto off = text::parseInt(tag->attr("offset"));
        if (!off || *off < 0) fail(file, "bad offset of array '" + name + "'");
        const auto offset = static_cast<std::size_t>(*off);
        if (appended.empty() || offset + sizeof(std::uint64_t) > appended.size())
          fail(file, "array '" + name + "' lies past the end (truncated?)");
        std::uint64_t bytes = 0;
        std::memcpy(&bytes, appended.data() + offset, sizeof(bytes));
        if (bytes != expected * sizeof(double)) fail(file, "array '" + name + "' has the wrong size");
        if (offset + sizeof(bytes) + bytes > appended.size()) fail(file, "array '" + name + "' is truncated");
        values.resize(expected);
        if (bytes) std::memcpy(values.data(), appended.data() + offset + sizeof(bytes), bytes);
      } else if (format == "ascii") {
        if (!tag->self_closing) {
          const std::size_t close = header.find("</DataArray>", tag->end);
          if (close == std::string_view::npos) fail(file, "unterminated <DataArray> '" + name + "'");
          values = parseNumbers(header.substr(tag->end, close - tag->end), ok);
          if (!ok) fail(file, "bad number in array '" + name + "'");
          pos = close;
        }
        if (values.size() != expected)
          fail(file, "array '" + name + "' holds " + std::to_string(values.size()) + " values, expected " +
                         std::to_string(expected));
      } else {
        fail(file, "unsupported DataArray format '" + format + "'");
      }
      if (is_time) {
        if (!have_time) image.time = values[0];
        have_time = true;
      } else {
        if (image.find(name)) fail(file, "array '" + name + "' appears twice");
        image.arrays.push_back({name, components, std::move(values)});
      }
    }
    return image;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    if (msg.find(file.string()) != std::string::npos) throw;
    fail(file, msg);
  }
}

}  // namespace mistfall
