// ParaView collection (.pvd) file: load for resume, truncate, append and atomic rewrite.
#include "io/pvd_collection.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/text_format.hpp"

namespace mistfall {

PvdCollection::PvdCollection(std::filesystem::path pvd_file) : file_(std::move(pvd_file)) {}

void PvdCollection::load() {
  entries_.clear();
  if (!std::filesystem::exists(file_)) return;
  std::ifstream in(file_, std::ios::binary);
  if (!in) throwCannotOpen(file_, "collection file");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    auto root = text::findTag(doc, "VTKFile");
    if (!root || root->attr("type") != "Collection") throw std::runtime_error("not a VTK Collection file");
    for (std::size_t pos = root->end;;) {
      auto tag = text::findTag(doc, "DataSet", pos);
      if (!tag) break;
      pos = tag->end;
      auto t = text::parseDouble(tag->attr("timestep"));
      if (!t) throw std::runtime_error("bad timestep '" + tag->attr("timestep") + "'");
      const std::string f = tag->attr("file");
      if (f.empty()) throw std::runtime_error("DataSet without file");
      entries_.push_back({*t, f});
    }
  } catch (const std::runtime_error& e) {
    entries_.clear();
    throw InputError("malformed collection file '" + file_.string() + "': " + e.what());
  }
}

void PvdCollection::truncateAfter(double t) {
  std::erase_if(entries_, [t](const Entry& e) { return e.time > t + 1e-12; });
}

void PvdCollection::add(double time, const std::string& relative_file) { entries_.push_back({time, relative_file}); }

void PvdCollection::write() const {
  writeFileAtomically(file_, [this](std::ostream& os) {
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <Collection>\n";
    for (const auto& e : entries_) {
      os << "    <DataSet timestep=\"" << text::formatDouble(e.time, 17) << "\" group=\"\" part=\"0\" file=\""
         << text::xmlEscape(e.file) << "\"/>\n";
    }
    os << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace mistfall
