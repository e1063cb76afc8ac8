// The contents of a run directory and the clearing of an old run (see run_directory.hpp).
#include "cli/run_directory.hpp"

#include <algorithm>

#include "cli/run_lock.hpp"
#include "io/errors.hpp"

namespace fs = std::filesystem;

namespace mistfall {

const std::vector<std::string>& runDirectoryEntries() {
  static const std::vector<std::string> entries{
      "case.toml", "checkpoint.bin", "diagnostics.csv", "frames.pvd", "bubbles.csv", "vents.csv", "diverged.txt",
      "frames",    "fields",         "categories.csv",  "texture",    "render",      "plots",
      "traces",    "case_changes.txt"};
  return entries;
}

void checkOutputPath(const fs::path& out) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw InputError("output path " + out.string() + " exists and is not a directory");
  for (fs::path p = out.parent_path(); !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, ec)) {
      if (!fs::is_directory(p, ec))
        throw InputError("output path " + out.string() + " lies under " + p.string() + ", which is not a directory");
      break;
    }
    if (p == p.parent_path()) break;
  }
}

bool isEmptyRunDirectory(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return true;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != kLockFileName) return false;
  return true;
}

std::vector<std::string> clearRunDirectory(const fs::path& dir) {
  const auto& ours = runDirectoryEntries();
  std::vector<std::string> kept;
  std::vector<fs::path> doomed;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name == kLockFileName) continue;
    const std::string base = name.size() > 4 && name.ends_with(".tmp") ? name.substr(0, name.size() - 4) : name;
    if (std::find(ours.begin(), ours.end(), base) != ours.end())
      doomed.push_back(e.path());
    else
      kept.push_back(name);
  }
  for (const fs::path& p : doomed) fs::remove_all(p);
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace mistfall
