// The 2D section mesh of a 2D run's water (src/render/section_mesh): the section encloses the particles' area
// (count * l0^2) within a few percent, keeps a sheet one particle thick, fills small air pockets; the extruded
// mesh is closed, faces out and holds area * width.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "render/section_mesh.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01;

std::vector<Vec<2>> block(int nx, int ny, double x0 = 0.0, double y0 = 0.0) {
  std::vector<Vec<2>> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) p.emplace_back(x0 + (i + 0.5) * kL0, y0 + (j + 0.5) * kL0);
  return p;
}

SectionMesh section(const std::vector<Vec<2>>& centres) {
  return marchingSquares(sectionField(centres, {kL0}));
}

// Closed loops of the outline (each vertex starts one segment and ends one).
int loops(const SectionMesh& s) {
  std::map<int, int> next;
  for (const auto& e : s.outline) next[e[0]] = e[1];
  int count = 0;
  std::map<int, bool> seen;
  for (const auto& [start, unused] : next) {
    if (seen[start]) continue;
    ++count;
    for (int v = start; !seen[v]; v = next.at(v)) seen[v] = true;
  }
  return count;
}

}  // namespace

TEST(RenderSection, BlockEnclosesItsParticlesArea) {
  const auto centres = block(30, 12);
  const SectionMesh s = section(centres);
  EXPECT_NEAR(sectionArea(s) / (centres.size() * kL0 * kL0), 1.0, 0.02);
  EXPECT_EQ(loops(s), 1);
}

TEST(RenderSection, JitteredDiscEnclosesItsParticlesArea) {
  // A disc of radius 12 l0 on the lattice, every particle moved by up to 0.2 l0: the area of a real frame's water.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0);
  std::vector<Vec<2>> centres;
  for (const auto& c : block(24, 24, -0.12, -0.12))
    if (c.norm() < 0.12) centres.emplace_back(c.x() + jitter(rng), c.y() + jitter(rng));
  const SectionMesh s = section(centres);
  EXPECT_NEAR(sectionArea(s) / (centres.size() * kL0 * kL0), 1.0, 0.03);
  EXPECT_EQ(loops(s), 1);
}

TEST(RenderSection, SheetOneParticleThickStaysOneSheet) {
  for (double spacing : {1.0, 1.25}) {  // a falling sheet's particles drift apart
    std::vector<Vec<2>> chain;
    for (int i = 0; i < 40; ++i) chain.emplace_back(0.3 * i * spacing * kL0, -0.95 * i * spacing * kL0);  // steep
    const SectionMesh s = section(chain);
    EXPECT_EQ(loops(s), 1) << "spacing " << spacing;
    // Not much thinner than a particle: area at least 0.6 of count * l0^2.
    EXPECT_GT(sectionArea(s), 0.6 * chain.size() * kL0 * kL0) << "spacing " << spacing;
  }
}

TEST(RenderSection, SmallAirPocketsAreFilledLargeOnesKept) {
  std::vector<Vec<2>> small, large;
  for (const auto& c : block(30, 30)) {
    const double x = c.x() / kL0, y = c.y() / kL0;
    if (!(x > 14 && x < 16 && y > 14 && y < 16)) small.push_back(c);  // 2 x 2 particles missing
    if (!(x > 8 && x < 22 && y > 8 && y < 22)) large.push_back(c);    // 14 x 14 missing
  }
  const SectionField f = sectionField(small, {kL0});
  EXPECT_EQ(loops(marchingSquares(f)), 1);
  int pocket_nodes = 0;
  for (auto v : f.pocket) pocket_nodes += v;
  EXPECT_GT(pocket_nodes, 0);
  const SectionMesh s = section(large);
  EXPECT_EQ(loops(s), 2);
  EXPECT_NEAR(sectionArea(s) / (large.size() * kL0 * kL0), 1.0, 0.03);
}

TEST(RenderSection, ExtrusionIsClosedFacesOutAndHoldsAreaTimesWidth) {
  const SectionMesh s = section(block(20, 10));
  for (double variation : {0.0, 0.3 * kL0}) {
    ExtrusionParameters e;
    e.width = 0.1;
    e.variation = variation;
    e.bevel = 0.25 * kL0;
    const TriangleMesh mesh = extrudeSection(s, e);
    EXPECT_EQ(openEdgeCount(mesh), 0u);
    EXPECT_NEAR(enclosedVolume(mesh) / (sectionArea(s) * 0.1), 1.0, 0.02) << "variation " << variation;
    const Vec<3> centre(0.1, 0.05, 0.0);
    int inward = 0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      inward += mesh.normals[i].dot(mesh.vertices[i] - centre) <= 0;
    EXPECT_EQ(inward, 0);
  }
}

TEST(RenderSection, NoiseIsSmoothAndBounded) {
  double lo = 1.0, hi = -1.0;
  for (int i = 0; i < 1000; ++i) {
    const double v = valueNoise(0.037 * i, 0.011 * i, -0.023 * i);
    lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_LT(std::abs(valueNoise(0.037 * i + 1e-4, 0.011 * i, -0.023 * i) - v), 1e-3);
  }
  EXPECT_GE(lo, -1.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_LT(lo, -0.3);
  EXPECT_GT(hi, 0.3);
}

TEST(RenderSection, JetLinksJoinAFallingFileOfParticlesIntoOneSheet) {
  // 12 particles 3 l0 apart on a steep line, falling along it at 2 m/s: too far apart for their discs to touch.
  std::vector<Vec<2>> x, u;
  const Vec<2> dir = Vec<2>(0.3, -1.0).normalized();
  for (int i = 0; i < 12; ++i) x.push_back(3.0 * kL0 * i * dir), u.push_back(2.0 * dir);
  JetLinkParameters p;
  p.spacing = kL0;
  const auto links = jetLinks(x, u, p);
  EXPECT_GE(links.size(), 11u);
  for (const auto& link : links) EXPECT_NEAR(link.radius, 0.35 * kL0, 1e-12);  // l0^2 / (2 * 3 l0) < 0.35 l0
  EXPECT_GT(loops(section(x)), 1);  // the discs alone: separate drops
  const SectionMesh sheet = marchingSquares(sectionField({}, {kL0}, links));
  EXPECT_EQ(loops(sheet), 1);
  // Moving across the line instead, or too slowly, they are not a jet.
  std::vector<Vec<2>> across(x.size(), 2.0 * Vec<2>(dir.y(), -dir.x())), slow(x.size(), 0.1 * dir);
  EXPECT_TRUE(jetLinks(x, across, p).empty());
  EXPECT_TRUE(jetLinks(x, slow, p).empty());
}
