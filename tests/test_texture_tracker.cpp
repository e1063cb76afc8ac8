// Birth of texture sources (texture/source_tracker.hpp): a particle spawns a source when it becomes isolated
// (category 3 droplet, 6 bubble), once however many frames it stays isolated. Frames with particle ids follow a
// particle by its id; frames without by proximity (match radius). The cases where the two disagree are those
// proximity cannot see: a fast particle that moved farther than its velocity says, and one particle taking
// another's place.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "texture/source_tracker.hpp"

using namespace mistfall;

namespace {

struct Frame {
  std::vector<Vec3> position, velocity;
  std::vector<std::uint8_t> category;
  std::vector<std::uint64_t> id;
};

// One particle per entry: (id, x, category), at rest, y = z = 0.
Frame frameOf(std::initializer_list<std::tuple<std::uint64_t, double, std::uint8_t>> particles) {
  Frame f;
  for (const auto& [id, x, category] : particles) {
    f.position.emplace_back(x, 0.0, 0.0);
    f.velocity.emplace_back(Vec3::Zero());
    f.category.push_back(category);
    f.id.push_back(id);
  }
  return f;
}

constexpr std::uint8_t kBulk = 1;
constexpr double kMatchRadius = 0.01;

struct Case {
  const char* what;
  std::vector<Frame> frames;
  int births_with_ids, births_by_proximity;
};

}  // namespace

TEST(TextureTracker, SourcesAreBornWhenAParticleBecomesIsolated) {
  const std::vector<Case> cases = {
      {"a droplet that stays isolated over three frames: one source",
       {frameOf({{7, 0.0, kCategoryDroplet}}), frameOf({{7, 0.001, kCategoryDroplet}}),
        frameOf({{7, 0.002, kCategoryDroplet}})},
       1, 1},
      {"two isolated particles, a droplet and a bubble at the same place: two sources",
       {frameOf({{1, 0.0, kCategoryDroplet}, {2, 0.0, kCategoryBubble}})}, 2, 2},
      {"isolated, back in the water, isolated again: two sources",
       {frameOf({{3, 0.0, kCategoryDroplet}}), frameOf({{3, 0.0, kBulk}}), frameOf({{3, 0.0, kCategoryDroplet}})},
       2, 2},
      {"a droplet thrown 5 match radii in one frame (a splash the velocity did not show): ids see one",
       {frameOf({{4, 0.0, kCategoryDroplet}}), frameOf({{4, 5 * kMatchRadius, kCategoryDroplet}})}, 1, 2},
      {"droplet 5 rejoins the water as droplet 6 detaches where 5 was: ids see two",
       {frameOf({{5, 0.0, kCategoryDroplet}, {6, 0.5, kBulk}}),
        frameOf({{5, 0.5, kBulk}, {6, 0.0, kCategoryDroplet}})},
       2, 1},
      {"particles erased and others appended between frames (outflow, inflow): ids, not array places, count",
       {frameOf({{8, 0.0, kCategoryDroplet}, {9, 0.2, kCategoryDroplet}}),
        frameOf({{9, 0.2, kCategoryDroplet}, {10, 0.4, kBulk}})},
       2, 2},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    for (const bool with_ids : {true, false}) {
      IsolatedParticleTracker tracker(kMatchRadius);
      int births = 0;
      double time = 0.0;
      for (const Frame& f : c.frames) {
        births += static_cast<int>(
            tracker.update(f.position, f.velocity, f.category, time, with_ids ? &f.id : nullptr).size());
        time += 0.02;
      }
      EXPECT_EQ(births, with_ids ? c.births_with_ids : c.births_by_proximity) << (with_ids ? "by id" : "by proximity");
    }
  }
}
