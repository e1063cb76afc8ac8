// Test helper: two particle sets are bit-for-bit equal (positions, velocities, pressures, densities, kinds, ids).
#pragma once

#include <gtest/gtest.h>

#include <cstring>

#include "mps/particles.hpp"

namespace mistfall::test_support {

template <int D>
void expectSameParticles(const Particles<D>& a, const Particles<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  const std::size_t n = a.size();
  EXPECT_EQ(0, std::memcmp(a.position.data(), b.position.data(), n * sizeof(Vec<D>)));
  EXPECT_EQ(0, std::memcmp(a.velocity.data(), b.velocity.data(), n * sizeof(Vec<D>)));
  EXPECT_EQ(0, std::memcmp(a.pressure.data(), b.pressure.data(), n * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(a.number_density.data(), b.number_density.data(), n * sizeof(double)));
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.phase, b.phase);
  EXPECT_EQ(a.enclosed, b.enclosed);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.next_id, b.next_id);
}

}  // namespace mistfall::test_support
