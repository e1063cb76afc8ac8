// Where an installed mistfall's data files are (see data_files.hpp).
#include "io/data_files.hpp"

#include <cstdlib>

namespace fs = std::filesystem;

namespace mistfall {

std::optional<fs::path> dataDirectory() {
  if (const char* env = std::getenv("MISTFALL_DATA_DIR"); env && *env) return fs::path(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  const fs::path share = (exe.parent_path().parent_path() / "share" / "mistfall").lexically_normal();
  if (fs::is_directory(share / "render", ec)) return share;
  return std::nullopt;
}

}  // namespace mistfall
