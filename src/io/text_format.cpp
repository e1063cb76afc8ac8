// Locale-independent number formatting/parsing and a minimal XML start-tag scanner.
#include "io/text_format.hpp"

#include <charconv>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace mistfall::text {

std::string formatDouble(double value, int digits) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::general, digits);
  if (res.ec != std::errc()) throw std::runtime_error("formatDouble: buffer too small");
  return std::string(buf, res.ptr);
}

static std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r' || s.front() == '\n'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

std::optional<double> parseDouble(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  auto res = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::general);
  if (res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    // from_chars does not accept "inf"/"nan" spellings from every producer; try the common ones.
    if (s == "inf" || s == "Infinity") return std::numeric_limits<double>::infinity();
    if (s == "-inf" || s == "-Infinity") return -std::numeric_limits<double>::infinity();
    if (s == "nan" || s == "NaN" || s == "-nan") return std::numeric_limits<double>::quiet_NaN();
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> parseInt(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  std::int64_t v = 0;
  auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (res.ec != std::errc() || res.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string XmlTag::attr(const std::string& key) const {
  auto it = attrs.find(key);
  return it == attrs.end() ? std::string() : it->second;
}

static std::string xmlUnescape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    static const std::pair<std::string_view, char> entities[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    bool matched = false;
    for (const auto& [name, ch] : entities) {
      if (s.substr(i, name.size()) == name) {
        out += ch;
        i += name.size() - 1;
        matched = true;
        break;
      }
    }
    if (!matched) out += '&';
  }
  return out;
}

static bool isNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == ':' || c == '.';
}

VtkXmlParts splitVtkFile(std::string_view doc) {
  constexpr std::string_view kClose = "</VTKFile>";
  const std::size_t last = doc.find_last_not_of(" \t\r\n");
  if (last == std::string_view::npos || last + 1 < kClose.size() ||
      doc.substr(last + 1 - kClose.size(), kClose.size()) != kClose)
    throw std::runtime_error("missing </VTKFile> (truncated?)");
  VtkXmlParts parts{doc, {}};
  if (auto ad = findTag(doc, "AppendedData")) {
    if (ad->attr("encoding") != "raw") throw std::runtime_error("only raw appended data is supported");
    const std::size_t underscore = doc.find('_', ad->end);
    if (underscore == std::string_view::npos) throw std::runtime_error("appended data has no '_' marker");
    parts.header = doc.substr(0, ad->begin);
    parts.appended = doc.substr(underscore + 1);
  }
  return parts;
}

void writeVtkFileEnd(std::ostream& os, std::string_view appended, bool ascii) {
  if (!ascii) {
    os << "  <AppendedData encoding=\"raw\">\n   _";
    os.write(appended.data(), static_cast<std::streamsize>(appended.size()));
    os << "\n  </AppendedData>\n";
  }
  os << "</VTKFile>\n";
}

std::optional<XmlTag> findTag(std::string_view doc, std::string_view element, std::size_t from) {
  std::size_t pos = from;
  while (true) {
    pos = doc.find('<', pos);
    if (pos == std::string_view::npos) return std::nullopt;
    const std::size_t name_begin = pos + 1;
    std::size_t name_end = name_begin;
    while (name_end < doc.size() && isNameChar(doc[name_end])) ++name_end;
    if (doc.substr(name_begin, name_end - name_begin) != element) {
      pos = name_begin;
      continue;
    }
    XmlTag tag;
    tag.name = std::string(element);
    tag.begin = pos;
    std::size_t i = name_end;
    while (true) {
      while (i < doc.size() && (doc[i] == ' ' || doc[i] == '\t' || doc[i] == '\r' || doc[i] == '\n')) ++i;
      if (i >= doc.size()) throw std::runtime_error("unterminated <" + tag.name + "> tag");
      if (doc[i] == '>') {
        tag.end = i + 1;
        return tag;
      }
      if (doc[i] == '/' && i + 1 < doc.size() && doc[i + 1] == '>') {
        tag.self_closing = true;
        tag.end = i + 2;
        return tag;
      }
      const std::size_t key_begin = i;
      while (i < doc.size() && isNameChar(doc[i])) ++i;
      if (i == key_begin) throw std::runtime_error("malformed attribute in <" + tag.name + "> tag");
      std::string key(doc.substr(key_begin, i - key_begin));
      while (i < doc.size() && (doc[i] == ' ' || doc[i] == '\t')) ++i;
      if (i >= doc.size() || doc[i] != '=') throw std::runtime_error("attribute '" + key + "' without value");
      ++i;
      while (i < doc.size() && (doc[i] == ' ' || doc[i] == '\t')) ++i;
      if (i >= doc.size() || (doc[i] != '"' && doc[i] != '\'')) {
        throw std::runtime_error("attribute '" + key + "' value is not quoted");
      }
      const char quote = doc[i++];
      const std::size_t value_end = doc.find(quote, i);
      if (value_end == std::string_view::npos) throw std::runtime_error("unterminated attribute '" + key + "'");
      tag.attrs[key] = xmlUnescape(doc.substr(i, value_end - i));
      i = value_end + 1;
    }
  }
}

std::string xmlEscape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace mistfall::text
