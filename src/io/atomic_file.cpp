// Atomic file writing: write to "path.tmp", then std::filesystem::rename over the destination.
#include "io/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace mistfall {

std::filesystem::path temporaryPathFor(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  return tmp;
}

void writeFileAtomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& writer) {
  const std::filesystem::path tmp = temporaryPathFor(file);
  auto discard = [&tmp] {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
  };
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    writer(out);
    out.flush();
    if (!out) throw std::runtime_error("error while writing '" + tmp.string() + "'");
    out.close();
    if (out.fail()) throw std::runtime_error("error while closing '" + tmp.string() + "'");
  } catch (const std::exception& e) {
    discard();
    throw std::runtime_error("writing '" + file.string() + "' failed: " + e.what());
  } catch (...) {
    discard();
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    discard();
    throw std::runtime_error("cannot rename '" + tmp.string() + "' to '" + file.string() + "': " + ec.message());
  }
}

}  // namespace mistfall
