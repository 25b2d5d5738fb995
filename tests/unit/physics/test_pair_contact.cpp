// The pair-contact step (physics/pair_contact.hpp): two fluid particles closer than dp/4 that
// approach lose their relative normal velocity (momentum kept), two closer than dp/8 are parted
// to dp/8, two at one point are parted too; pairs at the lattice spacing, pairs that separate and
// wall particles are untouched.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sloshsph/physics/pair_contact.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.01;

// Fluid particles at `x` with velocities `v`, then `walls` wall particles far away; the neighbour
// list of all of them (support 2.8 dp, as at h = 1.4 dp).
struct Cloud {
  Particles p;
  NeighbourList list{2.8 * kDp, 0.56 * kDp};
  Cloud(const std::vector<Vec2>& x, const std::vector<Vec2>& v, const std::vector<Vec2>& walls = {}) {
    p.resize(x.size() + walls.size());
    p.n_fluid = x.size();
    p.mass = 0.1;
    for (std::size_t i = 0; i < x.size(); ++i) {
      p.position[i] = x[i];
      p.velocity[i] = v[i];
    }
    for (std::size_t k = 0; k < walls.size(); ++k) p.position[x.size() + k] = walls[k];
    list.build(p.position, p.n_fluid);
  }
  PairContactStep step{kDp};
  std::size_t contact() { return step.apply(p, list); }
  Vec2 momentum() const {
    Vec2 m;
    for (std::size_t i = 0; i < p.n_fluid; ++i) m += p.velocity[i] * p.mass;
    return m;
  }
};

TEST(PairContact, LatticeSpacingIsUntouched) {
  Cloud c({{0.0, 0.0}, {kDp, 0.0}, {0.0, kDp}}, {{0.3, 0.0}, {-0.3, 0.0}, {0.0, -1.0}});
  EXPECT_EQ(c.contact(), 0u);
  EXPECT_EQ(c.p.velocity[0].x, 0.3);
  EXPECT_EQ(c.p.velocity[1].x, -0.3);
  EXPECT_EQ(c.p.position[1].x, kDp);
}

TEST(PairContact, CloseApproachingPairLosesOnlyItsRelativeNormalVelocity) {
  // 0.2 dp apart along x (inside dp/4, outside dp/8): velocities only.
  Cloud c({{0.0, 0.0}, {0.2 * kDp, 0.0}}, {{0.5, 0.1}, {-0.3, -0.2}});
  const Vec2 before = c.momentum();
  EXPECT_EQ(c.contact(), 1u);
  EXPECT_NEAR(c.p.velocity[0].x, 0.1, 1e-15);  // the mean normal velocity, (0.5 - 0.3) / 2
  EXPECT_NEAR(c.p.velocity[1].x, 0.1, 1e-15);
  EXPECT_EQ(c.p.velocity[0].y, 0.1);  // tangential velocities kept
  EXPECT_EQ(c.p.velocity[1].y, -0.2);
  EXPECT_NEAR(c.momentum().x, before.x, 1e-15);
  EXPECT_NEAR(c.momentum().y, before.y, 1e-15);
  EXPECT_EQ(c.p.position[0].x, 0.0);  // not moved
  EXPECT_EQ(c.p.position[1].x, 0.2 * kDp);
}

TEST(PairContact, CloseSeparatingPairIsUntouched) {
  Cloud c({{0.0, 0.0}, {0.0, 0.2 * kDp}}, {{0.0, -0.1}, {0.0, 0.1}});
  EXPECT_EQ(c.contact(), 0u);
  EXPECT_EQ(c.p.velocity[0].y, -0.1);
  EXPECT_EQ(c.p.velocity[1].y, 0.1);
}

TEST(PairContact, PairCloserThanAnEighthIsPartedSymmetrically) {
  const Vec2 a{0.3, 0.2}, b = a + Vec2{0.03 * kDp, 0.04 * kDp};  // 0.05 dp apart, along (3, 4)/5
  Cloud c({a, b}, {{0.0, 0.0}, {0.0, 0.0}});
  EXPECT_EQ(c.contact(), 1u);
  const Vec2 d = c.p.position[1] - c.p.position[0];
  EXPECT_NEAR(norm(d), 0.125 * kDp, 1e-15);
  EXPECT_NEAR(d.x / norm(d), 0.6, 1e-12);  // along the line of the pair
  const Vec2 centre = (c.p.position[0] + c.p.position[1]) * 0.5;
  EXPECT_NEAR(centre.x, (0.5 * (a + b)).x, 1e-15);
  EXPECT_NEAR(centre.y, (0.5 * (a + b)).y, 1e-15);
}

TEST(PairContact, TwoParticlesAtOnePointArePartedAlongTheirRelativeVelocity) {
  Cloud c({{0.1, 0.1}, {0.1, 0.1}}, {{0.0, 0.2}, {0.0, -0.2}});
  const Vec2 before = c.momentum();
  EXPECT_EQ(c.contact(), 1u);
  // n = (u_j - u_i) / |u_j - u_i| = -y: j moves down, i up; they approach no longer.
  EXPECT_NEAR(c.p.position[1].y - c.p.position[0].y, -0.125 * kDp, 1e-15);
  EXPECT_EQ(c.p.position[0].x, c.p.position[1].x);
  EXPECT_NEAR(c.momentum().y, before.y, 1e-15);
}

TEST(PairContact, TwoParticlesAtOnePointWithOneVelocityArePartedAlongX) {
  Cloud c({{0.1, 0.1}, {0.1, 0.1}}, {{0.3, 0.4}, {0.3, 0.4}});
  EXPECT_EQ(c.contact(), 1u);
  EXPECT_NEAR(c.p.position[1].x - c.p.position[0].x, 0.125 * kDp, 1e-15);  // the first towards -x
  EXPECT_EQ(c.p.position[0].y, c.p.position[1].y);
  EXPECT_EQ(c.p.velocity[0].x, 0.3);  // nothing to remove: they do not approach
  EXPECT_EQ(c.p.velocity[1].y, 0.4);
}

TEST(PairContact, WallParticlesAreNotPartners) {
  // A wall particle at the fluid particle's position: the walls have their own contact step.
  Cloud c({{0.2, 0.2}}, {{0.0, -1.0}}, {{0.2, 0.2}});
  EXPECT_EQ(c.contact(), 0u);
  EXPECT_EQ(c.p.position[0].y, 0.2);
  EXPECT_EQ(c.p.velocity[0].y, -1.0);
}

TEST(PairContact, ThreeInALineAreCorrectedInTheFluidOrderRepeatably) {
  // Three particles in a line, each 0.05 dp from the next: the two pairs are corrected in the
  // fluid order (i = 0 first), the middle particle by both; the result is the same every time.
  Cloud c({{0.0, 0.0}, {0.05 * kDp, 0.0}, {0.1 * kDp, 0.0}}, {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  const std::size_t n = c.contact();
  EXPECT_GE(n, 2u);
  Cloud again({{0.0, 0.0}, {0.05 * kDp, 0.0}, {0.1 * kDp, 0.0}}, {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  EXPECT_EQ(again.contact(), n);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(again.p.position[i].x, c.p.position[i].x);
}

// The candidates are kept between steps: a pair that was far apart when they were collected is
// found once its particles have moved far enough for the candidates to be collected again.
TEST(PairContactStep, PairThatWasFarIsFoundAfterTheParticlesMoved) {
  Cloud c({{0.0, 0.0}, {0.9 * kDp, 0.0}}, {{0.1, 0.0}, {-0.1, 0.0}});
  EXPECT_EQ(c.contact(), 0u);  // 0.9 dp: not even a candidate
  c.p.position[0].x += 0.35 * kDp;  // 0.2 dp apart now, each moved more than (3/4 - 1/4) dp / 2
  c.p.position[1].x -= 0.35 * kDp;
  EXPECT_EQ(c.contact(), 1u);
  EXPECT_NEAR(c.p.velocity[0].x, 0.0, 1e-15);
  EXPECT_NEAR(c.p.velocity[1].x, 0.0, 1e-15);
}

TEST(PairContactStep, CandidateWithinReachIsFollowedWithoutCollectingAgain) {
  // 0.7 dp apart (a candidate); moved 0.24 dp each towards the other (not enough to collect
  // again): 0.22 dp apart and approaching, so corrected from the kept candidates.
  Cloud c({{0.0, 0.0}, {0.7 * kDp, 0.0}}, {{0.1, 0.0}, {-0.1, 0.0}});
  EXPECT_EQ(c.contact(), 0u);
  c.p.position[0].x += 0.24 * kDp;
  c.p.position[1].x -= 0.24 * kDp;
  EXPECT_EQ(c.contact(), 1u);
}

// Many close pairs at once (a jittered lattice squeezed to 0.2 dp): the result on 2 threads is the
// result on 1, bit for bit (the pairs are found in parallel but corrected serially in order).
TEST(PairContact, TwoThreadsGiveTheBitsOfOne) {
  std::vector<Vec2> x, v;
  std::uint32_t seed = 12345;
  auto jitter = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 0.1 * kDp;
  };
  for (int a = 0; a < 40; ++a)
    for (int b = 0; b < 40; ++b) {
      x.push_back({0.2 * kDp * a + jitter(), 0.2 * kDp * b + jitter()});
      v.push_back({jitter() * 100.0, jitter() * 100.0});
    }
  auto run = [&](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    Cloud c(x, v);
    const std::size_t n = c.contact();
    omp_set_num_threads(before);
    EXPECT_GT(n, 1000u);
    return c.p;
  };
  const Particles one = run(1), two = run(2);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(one.position[i].x, two.position[i].x);
    EXPECT_EQ(one.position[i].y, two.position[i].y);
    EXPECT_EQ(one.velocity[i].x, two.velocity[i].x);
    EXPECT_EQ(one.velocity[i].y, two.velocity[i].y);
  }
}

}  // namespace
}  // namespace sloshsph
