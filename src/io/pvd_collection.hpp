// ParaView collection (.pvd) file: the list of (time, frame file) pairs that makes the frames a time series.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mistfall {

class PvdCollection {
 public:
  struct Entry {
    double time = 0.0;
    std::string file;  // relative to the .pvd's directory, e.g. "frames/frame_00003.vtp"
  };

  explicit PvdCollection(std::filesystem::path pvd_file);

  // Replaces the entries with those of the existing .pvd (for resume). A missing file gives no entries;
  // a malformed one throws std::runtime_error naming the path.
  void load();
  // Drops every entry with time > t (+1e-12).
  void truncateAfter(double t);
  void add(double time, const std::string& relative_file);
  // Rewrites the whole .pvd atomically.
  void write() const;

  const std::vector<Entry>& entries() const { return entries_; }
  const std::filesystem::path& path() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace mistfall
