// Compaction of structure-of-arrays storage: removes the entries i with remove[i] != 0 from every array at once,
// keeping the order of the others (used by the particle arrays and the texture cloud).
#pragma once

#include <cstddef>
#include <vector>

namespace mistfall {

template <class... Arrays>
void eraseMarked(const std::vector<char>& remove, Arrays&... arrays) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < remove.size(); ++i) {
    if (remove[i]) continue;
    if (kept != i) ((arrays[kept] = arrays[i]), ...);
    ++kept;
  }
  (arrays.resize(kept), ...);
}

}  // namespace mistfall
