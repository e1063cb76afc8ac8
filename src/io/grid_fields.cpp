// Particle fields on a uniform grid (weighted means with the MPS weight, eq. (14)) and the .vti writer/reader.
#include "io/grid_fields.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/text_format.hpp"
#include "mps/weight.hpp"

namespace mistfall {

static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian host");

namespace {

// More nodes than this is taken as a mistake in the cell size (it would need tens of GB).
constexpr double kMaxNodes = 1e9;
// The distance in the weight is floored at this fraction of R (see grid_fields.hpp).
constexpr double kWeightCoreRatio = 0.25;

using Cell = std::array<std::int64_t, 3>;

}  // namespace

template <int D>
std::array<std::int64_t, 3> gridNodeCounts(const GridSpec<D>& grid) {
  if (!(grid.cell_size > 0.0) || !std::isfinite(grid.cell_size))
    throw std::invalid_argument("grid cell size must be positive, got " + text::formatDouble(grid.cell_size, 6));
  if (!(grid.radius > 0.0) || !std::isfinite(grid.radius))
    throw std::invalid_argument("grid sampling radius must be positive, got " + text::formatDouble(grid.radius, 6));
  std::array<std::int64_t, 3> n{1, 1, 1};
  double total = 1.0;
  for (int k = 0; k < D; ++k) {
    const double extent = grid.upper[k] - grid.lower[k];
    if (!std::isfinite(grid.lower[k]) || !std::isfinite(extent) || extent < 0.0)
      throw std::invalid_argument("grid box: upper corner must not lie below the lower corner (axis " +
                                  std::to_string(k) + ")");
    // The small allowance keeps a node on `upper` when extent / h is a whole number up to rounding.
    const double cells = std::floor(extent / grid.cell_size + 1e-9);
    total *= cells + 1.0;
    if (total > kMaxNodes)
      throw std::invalid_argument("grid of more than 1e9 nodes: cell size " + text::formatDouble(grid.cell_size, 6) +
                                  " m is too small for the box");
    n[k] = static_cast<std::int64_t>(cells) + 1;
  }
  return n;
}

template <int D>
GridSamples sampleOnGrid(const GridSpec<D>& grid, const std::vector<Vec<D>>& position,
                         const std::vector<char>& selected, const std::vector<double>& values, int components) {
  const auto nodes = gridNodeCounts<D>(grid);
  if (components < 1) throw std::invalid_argument("grid sampling: components must be at least 1");
  const std::size_t np = position.size();
  const auto comp = static_cast<std::size_t>(components);
  if (selected.size() != np || values.size() != np * comp)
    throw std::invalid_argument("grid sampling: " + std::to_string(np) + " particles but " +
                                std::to_string(selected.size()) + " selection flags and " +
                                std::to_string(values.size()) + " values (" + std::to_string(components) +
                                " per particle)");
  const double radius = grid.radius;
  const double r_core = kWeightCoreRatio * radius;

  // Bins of edge R over the box grown by R: every particle within R of a node lies in one of them.
  const Vec<D> bin_lower = grid.lower.array() - radius;
  Cell bins{1, 1, 1};
  for (int k = 0; k < D; ++k)
    bins[k] = static_cast<std::int64_t>(std::floor((grid.upper[k] - grid.lower[k] + 2.0 * radius) / radius)) + 1;
  const std::int64_t nbins = bins[0] * bins[1] * bins[2];
  auto binOf = [&](const Vec<D>& x, Cell& c) {
    c = {0, 0, 0};
    for (int k = 0; k < D; ++k) {
      const double f = std::floor((x[k] - bin_lower[k]) / radius);
      if (!(f >= 0.0) || f >= static_cast<double>(bins[k])) return false;  // also false for NaN
      c[k] = static_cast<std::int64_t>(f);
    }
    return true;
  };
  auto binIndex = [&](const Cell& c) { return (c[2] * bins[1] + c[1]) * bins[0] + c[0]; };

  // Counting sort of the selected particles into bins (index order inside a bin: thread-count independent).
  std::vector<std::int64_t> bin_of(np, -1);
  std::vector<std::int64_t> start(static_cast<std::size_t>(nbins) + 1, 0);
  for (std::size_t j = 0; j < np; ++j) {
    Cell c;
    if (selected[j] && binOf(position[j], c)) {
      bin_of[j] = binIndex(c);
      ++start[static_cast<std::size_t>(bin_of[j]) + 1];
    }
  }
  for (std::int64_t b = 0; b < nbins; ++b) start[b + 1] += start[b];
  std::vector<std::int32_t> sorted(static_cast<std::size_t>(start[nbins]));
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t j = 0; j < np; ++j)
      if (bin_of[j] >= 0) sorted[fill[bin_of[j]]++] = static_cast<std::int32_t>(j);
  }

  const std::int64_t total = nodes[0] * nodes[1] * nodes[2];
  GridSamples out;
  out.mean.assign(static_cast<std::size_t>(total) * comp, 0.0);
  out.coverage.assign(static_cast<std::size_t>(total), 0.0);
#pragma omp parallel
  {
    std::vector<double> acc(comp);
#pragma omp for schedule(static)
    for (std::int64_t node = 0; node < total; ++node) {
      const Cell idx{node % nodes[0], (node / nodes[0]) % nodes[1], node / (nodes[0] * nodes[1])};
      Vec<D> x;
      for (int k = 0; k < D; ++k) x[k] = grid.lower[k] + grid.cell_size * static_cast<double>(idx[k]);
      Cell c, lo{0, 0, 0}, hi{0, 0, 0};
      binOf(x, c);  // nodes lie inside the grown box
      for (int k = 0; k < D; ++k) {
        lo[k] = std::max<std::int64_t>(c[k] - 1, 0);
        hi[k] = std::min<std::int64_t>(c[k] + 1, bins[k] - 1);
      }
      std::fill(acc.begin(), acc.end(), 0.0);
      double wsum = 0.0;
      for (std::int64_t bz = lo[2]; bz <= hi[2]; ++bz)
        for (std::int64_t by = lo[1]; by <= hi[1]; ++by)
          for (std::int64_t bx = lo[0]; bx <= hi[0]; ++bx) {
            const std::int64_t b = binIndex({bx, by, bz});
            for (std::int64_t s = start[b]; s < start[b + 1]; ++s) {
              const auto j = static_cast<std::size_t>(sorted[s]);
              const double w = weight(std::max((position[j] - x).norm(), r_core), radius);
              if (w <= 0.0) continue;
              wsum += w;
              for (std::size_t a = 0; a < comp; ++a) acc[a] += w * values[j * comp + a];
            }
          }
      const auto n = static_cast<std::size_t>(node);
      out.coverage[n] = wsum;
      if (wsum > 0.0)
        for (std::size_t a = 0; a < comp; ++a) out.mean[n * comp + a] = acc[a] / wsum;
    }
  }
  return out;
}

template <int D>
ImageData sampleFlowFieldsMasked(const GridSpec<D>& grid, const Particles<D>& p, const std::vector<double>& sps_k,
                                 const std::vector<char>& selected, double time) {
  const auto nodes = gridNodeCounts<D>(grid);
  if (sps_k.size() != p.size())
    throw std::invalid_argument("flow fields: " + std::to_string(sps_k.size()) + " SPS k values for " +
                                std::to_string(p.size()) + " particles");
  if (selected.size() != p.size())
    throw std::invalid_argument("flow fields: " + std::to_string(selected.size()) + " selection flags for " +
                                std::to_string(p.size()) + " particles");
  ImageData image;
  image.dims = nodes;
  image.time = time;
  for (int k = 0; k < 3; ++k) {
    image.origin[k] = k < D ? grid.lower[k] : 0.0;
    image.spacing[k] = grid.cell_size;
  }
  // Velocity (D components) and k packed per particle, so each phase is sampled in one pass.
  constexpr int kComp = D + 1;
  std::vector<double> packed(p.size() * kComp);
  for (std::size_t j = 0; j < p.size(); ++j) {
    for (int a = 0; a < D; ++a) packed[j * kComp + a] = p.velocity[j][a];
    packed[j * kComp + D] = sps_k[j];
  }
  const std::size_t total = image.nodeCount();
  std::vector<GridArray> velocities, energies, coverages;
  for (const auto& [phase, name] : {std::pair{Phase::Gas, "gas"}, std::pair{Phase::Liquid, "liquid"}}) {
    std::vector<char> mask(p.size());
    for (std::size_t j = 0; j < p.size(); ++j) mask[j] = selected[j] && p.phase[j] == phase;
    GridSamples s = sampleOnGrid<D>(grid, p.position, mask, packed, kComp);
    GridArray u{std::string(name) + "_velocity", 3, std::vector<double>(3 * total, 0.0)};
    GridArray k{std::string(name) + "_sps_k", 1, std::vector<double>(total)};
    for (std::size_t n = 0; n < total; ++n) {
      for (int a = 0; a < D; ++a) u.values[3 * n + a] = s.mean[n * kComp + a];
      k.values[n] = s.mean[n * kComp + D];
    }
    velocities.push_back(std::move(u));
    energies.push_back(std::move(k));
    coverages.push_back({std::string(name) + "_coverage", 1, std::move(s.coverage)});
  }
  for (auto* group : {&velocities, &energies, &coverages})
    for (auto& a : *group) image.arrays.push_back(std::move(a));
  return image;
}

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
    if (!ascii) {
      os << "  <AppendedData encoding=\"raw\">\n   _";
      os.write(blob.data(), static_cast<std::streamsize>(blob.size()));
      os << "\n  </AppendedData>\n";
    }
    os << "</VTKFile>\n";
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
    // A truncated file lacks the closing tag (the appended bytes come before it).
    constexpr std::string_view kClose = "</VTKFile>";
    const std::size_t last = doc.find_last_not_of(" \t\r\n");
    if (last == std::string::npos || last + 1 < kClose.size() ||
        std::string_view(doc).substr(last + 1 - kClose.size(), kClose.size()) != kClose)
      fail(file, "missing </VTKFile> (truncated?)");
    // Only the part before <AppendedData> is XML; the raw bytes after '_' may contain anything.
    std::string_view header(doc), appended;
    if (auto ad = text::findTag(header, "AppendedData")) {
      if (ad->attr("encoding") != "raw") fail(file, "only raw appended data is supported");
      const std::size_t underscore = doc.find('_', ad->end);
      if (underscore == std::string::npos) fail(file, "appended data has no '_' marker");
      header = std::string_view(doc).substr(0, ad->begin);
      appended = std::string_view(doc).substr(underscore + 1);
    }
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
      if (extent[2 * k] != 0.0 || !(extent[2 * k + 1] >= 0.0) || extent[2 * k + 1] > kMaxNodes ||
          extent[2 * k + 1] != std::floor(extent[2 * k + 1]))
        fail(file, "WholeExtent must be '0 nx-1 0 ny-1 0 nz-1'");
      image.dims[k] = static_cast<std::int64_t>(extent[2 * k + 1]) + 1;
      image.origin[k] = origin[k];
      image.spacing[k] = spacing[k];
    }
    if (static_cast<double>(image.dims[0]) * double(image.dims[1]) * double(image.dims[2]) > kMaxNodes)
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

template std::array<std::int64_t, 3> gridNodeCounts<2>(const GridSpec<2>&);
template std::array<std::int64_t, 3> gridNodeCounts<3>(const GridSpec<3>&);
template GridSamples sampleOnGrid<2>(const GridSpec<2>&, const std::vector<Vec<2>>&, const std::vector<char>&,
                                     const std::vector<double>&, int);
template GridSamples sampleOnGrid<3>(const GridSpec<3>&, const std::vector<Vec<3>>&, const std::vector<char>&,
                                     const std::vector<double>&, int);
template ImageData sampleFlowFieldsMasked<2>(const GridSpec<2>&, const Particles<2>&, const std::vector<double>&,
                                             const std::vector<char>&, double);
template ImageData sampleFlowFieldsMasked<3>(const GridSpec<3>&, const Particles<3>&, const std::vector<double>&,
                                             const std::vector<char>&, double);

}  // namespace mistfall
