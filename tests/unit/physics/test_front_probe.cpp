// The surge-front probe (observe/probes.hpp): the furthest fluid particle along the floor.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/observe/probes.hpp"

namespace sloshsph {
namespace {

TEST(FrontProbe, FurthestFluidParticleInTheBandPlusHalfASpacing) {
  Particles p;
  p.resize(4);
  p.n_fluid = 3;
  p.position = {{0.105, 0.005}, {0.305, 0.015}, {0.905, 0.5}, {2.0, 0.0}};  // last: a wall particle
  const double dp = 0.01;
  // Band 0.02 m: the splash at y = 0.5 and the wall particle do not count.
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 0.02, true, dp), 0.31);
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 0.02, false, dp), 0.1);
  // A band that takes in the splash moves the front to it.
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 1.0, true, dp), 0.91);
  // No fluid in the band: NaN (written as such, not as a position).
  EXPECT_TRUE(std::isnan(front_position(p, 0.0, 0.001, true, dp)));
}

// 3D (issue 31): the height is z; y (across the breadth) plays no part, and the front is the
// furthest particle at any y.
TEST(FrontProbe, InThreeDimensionsTheHeightIsZ) {
  BasicParticles<3> p;
  p.resize(4);
  p.n_fluid = 3;
  // High in y but low in z (counts); low in y but high in z (does not, with the band 0.02 m).
  p.position = {{0.105, 0.9, 0.005}, {0.305, 0.5, 0.015}, {0.905, 0.005, 0.5}, {2.0, 0.0, 0.0}};
  const double dp = 0.01;
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 0.02, true, dp), 0.31);
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 0.02, false, dp), 0.1);
  EXPECT_DOUBLE_EQ(front_position(p, 0.0, 1.0, true, dp), 0.91);
}

}  // namespace
}  // namespace sloshsph
