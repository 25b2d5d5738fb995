// Particle shifting (physics/shifting.hpp): the concentration gradient on a lattice, the limits at
// walls, and both schemes with it on (ISPH: scheme.shifting = "lind", Lind et al. 2012; WCSPH:
// "delta_plus", Sun et al. 2017).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/shifting.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "sloshsph/schemes/wcsph.hpp"
#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.01;
constexpr double kH = 1.4 * kDp;

// A square lattice of fluid particles, n x n, spacing dp, centred on the origin (n odd).
Particles fluid_lattice(int n) {
  Particles p;
  p.resize(static_cast<std::size_t>(n * n));
  p.n_fluid = p.size();
  p.volume = kDp * kDp;
  p.mass = 1000.0 * p.volume;
  std::size_t k = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) p.position[k++] = Vec2{(a - n / 2) * kDp, (b - n / 2) * kDp};
  return p;
}

std::size_t nearest(const Particles& p, Vec2 at) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (norm(p.position[i] - at) < norm(p.position[best] - at)) best = i;
  return best;
}

struct Pairs {
  NeighbourList list{2.0 * kH, 0.0};
  PairList pairs;
  explicit Pairs(const Particles& p) {
    list.build(p.position, p.n_fluid);
    pairs.build(KernelType::wendland_c2, kH, p.position, list);
  }
};

// Reference: on a uniform lattice the kernel gradients cancel by symmetry, so grad C = 0 to
// round-off (tolerance 1e-9 of one pair's term V |grad W| ~ 1/dp). A neighbour moved 0.3 dp
// towards the centre particle makes C higher on that side: the shift -grad C points away from it.
TEST(IsphShifting, ConcentrationGradientVanishesOnALatticeAndPushesAwayFromACluster) {
  Particles p = fluid_lattice(9);
  const WendlandC2 kernel(kH);
  const std::size_t centre = nearest(p, Vec2{0.0, 0.0});
  {
    Pairs pr(p);
    const ConcentrationGradient g = concentration_gradient(pr.pairs, p.volume, kernel.w(kDp), centre);
    EXPECT_LT(norm(g.shifting), 1e-9 / kDp);
    EXPECT_LT(norm(g.plain), 1e-9 / kDp);
  }
  const std::size_t right = nearest(p, Vec2{kDp, 0.0});
  p.position[right].x -= 0.3 * kDp;
  Pairs pr(p);
  const Vec2 shift = -concentration_gradient(pr.pairs, p.volume, kernel.w(kDp), centre).shifting;
  EXPECT_LT(shift.x, 0.0) << "the shift moves the particle away from its crowded side";
  EXPECT_LT(std::abs(shift.y), 1e-9 * std::abs(shift.x)) << "symmetric about the x axis";
}

// The anti-clustering factor 1 + 0.2 (W/W(dp))^4: two particles closer than dp on a lattice push
// apart harder with it than the plain gradient would (Lind et al. 2012; Monaghan 2000).
// Reference: the factor is at least 1 for every pair and 1.2 at r = dp, so the magnitude of grad C
// at a particle whose neighbour came to 0.5 dp exceeds the plain sum by more than 20%.
TEST(IsphShifting, AntiClusteringTermStrengthensTheGradientOfAClosePair) {
  Particles p = fluid_lattice(9);
  const WendlandC2 kernel(kH);
  const std::size_t centre = nearest(p, Vec2{0.0, 0.0});
  const std::size_t right = nearest(p, Vec2{kDp, 0.0});
  p.position[right].x -= 0.5 * kDp;
  Pairs pr(p);
  const ConcentrationGradient g = concentration_gradient(pr.pairs, p.volume, kernel.w(kDp), centre);
  const Vec2 with = g.shifting, plain = g.plain;
  EXPECT_GT(norm(with), 1.2 * norm(plain));
  EXPECT_GT(dot(with, plain), 0.0);
}

// Reference: the projection removes the component along grad C exactly (a shift along the
// surface is kept unchanged, one along the normal is removed to round-off).
TEST(IsphShifting, AtTheFreeSurfaceOnlyTheTangentialShiftIsKept) {
  const Vec2 grad_c{0.0, -3.0};  // C falls upwards: the surface is above
  const Vec2 kept = along_free_surface(Vec2{0.2, 0.7}, grad_c);
  EXPECT_DOUBLE_EQ(kept.x, 0.2);
  EXPECT_NEAR(kept.y, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(along_free_surface(Vec2{0.2, 0.7}, Vec2{}).y, 0.7) << "no gradient: nothing to project";
}

// One wall particle at the origin with the inward normal (0, 1), and a fluid particle above it
// (or below it: the other face of a thin wall). Reference: after the limit the particle is no
// closer than dp to the wall particle's plane, unless it already was, in which case it does not
// come closer; the tangential part of the shift is kept.
TEST(IsphShifting, AShiftNeverCarriesAParticleTowardsAWallCloserThanDp) {
  Particles p;
  p.resize(2);
  p.n_fluid = 1;
  p.volume = kDp * kDp;
  p.position[1] = Vec2{0.0, 0.0};
  p.normal[1] = Vec2{0.0, 1.0};
  struct Case {
    double y, shift_y, expected_y;
    bool cut;
  };
  for (const Case c : {Case{1.3 * kDp, -0.5 * kDp, -0.3 * kDp, true},   // stops at dp
                       Case{1.3 * kDp, -0.2 * kDp, -0.2 * kDp, false},  // room enough
                       Case{0.8 * kDp, -0.1 * kDp, 0.0, true},          // already closer: no nearer
                       Case{0.8 * kDp, +0.1 * kDp, +0.1 * kDp, false},  // away from the wall: free
                       Case{-1.2 * kDp, +0.5 * kDp, +0.2 * kDp, true}}) {  // behind a thin wall
    p.position[0] = Vec2{0.0, c.y};
    Pairs pr(p);
    Vec2 shift{0.05 * kDp, c.shift_y};
    const bool cut = keep_shift_off_walls(p, pr.pairs, 0, kDp, shift);
    EXPECT_EQ(cut, c.cut) << "y = " << c.y / kDp << " dp";
    EXPECT_NEAR(shift.y, c.expected_y, 1e-12 * kDp) << "y = " << c.y / kDp << " dp";
    EXPECT_DOUBLE_EQ(shift.x, 0.05 * kDp);
  }
}

CaseSpec dam_break(const std::string& scheme, bool shifting) {
  CaseSpec spec;
  spec.source = "<test>";
  spec.name = "shifting_dam_break";
  spec.tank.shape = "rectangle";
  spec.tank.length = 1.0;
  spec.tank.height = 0.6;
  spec.fill.blocks.push_back(FluidBlock{Vec2{0.0, 0.0}, Vec2{0.25, 0.5}});
  spec.fill.depth = 0.25 * 0.5 / 1.0;  // as the case reader sets it: the blocks' area over the length
  spec.fill.block_head = 0.5;
  spec.particles.dp = 0.02;
  spec.scheme.type = scheme;
  if (shifting) spec.scheme.shifting = scheme == "isph" ? ShiftingModel::lind : ShiftingModel::delta_plus;
  return spec;
}

// Fluid pairs closer than 3/4 dp: clusters, which a Lagrangian motion leaves behind in
// violent flow.
std::size_t close_fluid_pairs(const Particles& p, double dp) {
  std::size_t close = 0;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    for (std::size_t j = i + 1; j < p.n_fluid; ++j) close += norm(p.position[i] - p.position[j]) < 0.75 * dp ? 1 : 0;
  return close;
}

// A water column of 0.25 m x 0.5 m released in a 1 m tank, dp = 20 mm, for 0.5 s (ISPH at dt = 1
// ms, WCSPH at its own stable step): the front has hit the far wall and run up it by the end. The
// scheme alone (the simulation's wall-contact step is not part of it).
std::size_t clusters_after_dam_break(const std::string& type, bool shifting) {
  const CaseSpec spec = dam_break(type, shifting);
  Scene scene = build_scene(spec);
  Particles& p = scene.particles;
  FrameForce g;
  g.uniform = {0.0, -spec.fluid.gravity};
  StepInput in;
  in.frame = g;
  if (type == "isph") {
    IsphScheme scheme(spec, scene.h);
    scheme.initialise(p, g);
    in.dt = 1e-3;
    for (int step = 0; step < 500; ++step) scheme.step(p, in);
  } else {
    WcsphScheme scheme(spec, scene.h);
    scheme.initialise(p, g);
    for (double t = 0.0; t < 0.5;) {
      in.dt = std::min(1e-3, scheme.stable_dt(p, g));
      scheme.step(p, in);
      t += in.dt;
    }
  }
  return close_fluid_pairs(p, spec.particles.dp);
}

void expect_fewer_clusters(const std::string& type, double at_most) {
  const std::size_t plain = clusters_after_dam_break(type, false);
  const std::size_t shifted = clusters_after_dam_break(type, true);
  testing::Test::RecordProperty("close_pairs_plain_" + type, std::to_string(plain));
  testing::Test::RecordProperty("close_pairs_shifted_" + type, std::to_string(shifted));
  std::printf("%s: fluid pairs closer than 3/4 dp after 0.5 s: %zu without shifting, %zu with\n", type.c_str(), plain,
              shifted);
  EXPECT_GT(plain, 20u) << "the dam break must cluster particles for the test to mean anything";
  EXPECT_LE(static_cast<double>(shifted), at_most * static_cast<double>(plain));
}

// Reference: shifting exists to keep particles from clustering (Lind et al. 2012; Sun et al. 2017).
// Measured on this dam break (0.5 s, about 300 fluid particles): 75 fluid pairs closer than 3/4 dp
// without shifting, 4 with it at A = 2. (With the surface normal taken from the shift's own
// gradient, so that no particle near the surface could shift at all, it was 43.) Tolerance:
// shifting removes at least 80% of the close pairs.
TEST(IsphShifting, DamBreakLeavesFewerClusteredPairs) { expect_fewer_clusters("isph", 0.2); }

// The same for the WCSPH scheme with the delta-plus shift (Sun et al. 2017). Measured: 63 close
// pairs without shifting, 4 with it (61 with the parallel normal above). Tolerance as above.
TEST(WcsphShifting, DamBreakLeavesFewerClusteredPairs) { expect_fewer_clusters("wcsph", 0.2); }

}  // namespace
}  // namespace sloshsph
