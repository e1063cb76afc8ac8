#include <gtest/gtest.h>
#include "mps/particles.hpp"
TEST(Particles, AddKeepsArraysAligned) {
  mistfall::Particles<2> p;
  p.add({0, 0}, {1, 0}, mistfall::ParticleKind::Fluid, mistfall::Phase::Liquid);
  EXPECT_EQ(p.size(), 1u);
  EXPECT_EQ(p.pressure.size(), 1u);
}
