// Locale-independent number formatting/parsing and a minimal XML tag-attribute scanner shared by the
// VTK, PVD and CSV writers/readers (they only need to read back the files this project writes).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace mistfall::text {

// Shortest-of-%g style formatting with `digits` significant digits (17 round-trips a double exactly).
std::string formatDouble(double value, int digits = 17);

// Parses the whole of `s` (surrounding blanks allowed) or returns nullopt.
std::optional<double> parseDouble(std::string_view s);
std::optional<std::int64_t> parseInt(std::string_view s);

// Attributes of one XML start tag, e.g. `<DataArray type="Float64" Name="pressure" format="ascii">`.
struct XmlTag {
  std::string name;                           // element name, e.g. "DataArray"
  std::map<std::string, std::string> attrs;   // attribute values, unescaped
  bool self_closing = false;                  // ends in "/>"
  std::size_t begin = 0;                      // index of '<' in the document
  std::size_t end = 0;                        // index just past '>'
  std::string attr(const std::string& key) const;   // "" when absent
};

// Finds the next start tag named `element` at or after `from` in `doc`; nullopt if there is none.
// Throws std::runtime_error on an unterminated tag.
std::optional<XmlTag> findTag(std::string_view doc, std::string_view element, std::size_t from = 0);

// A VTK XML file read whole, split where its raw <AppendedData> starts: only the part before it is XML (the bytes
// after its '_' marker may contain anything, '<' included). No appended data: `appended` is empty. Throws
// std::runtime_error for a file that does not end in </VTKFile> (truncated: the appended bytes come before it) and
// for appended data that is not raw or has no '_' marker; the readers add the file's name.
struct VtkXmlParts {
  std::string_view header, appended;
};
VtkXmlParts splitVtkFile(std::string_view doc);
// The end of a VTK XML file as splitVtkFile reads it: the raw <AppendedData> block holding `appended` (binary
// files, `ascii` false), then </VTKFile>.
void writeVtkFileEnd(std::ostream& os, std::string_view appended, bool ascii);

// Escapes &, <, >, " for use in an attribute value.
std::string xmlEscape(std::string_view s);

}  // namespace mistfall::text
