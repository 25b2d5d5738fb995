// Pressure probes (observe/probes.hpp): a point probe and a probe with a sensor face.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/observe/probes.hpp"
#include "sloshsph/sph/kernel.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.01;
constexpr double kRhoG = 1000.0 * 9.81;

// Fluid particles on a square lattice filling 0 < x < 1 m, 0 < y < depth, carrying the
// hydrostatic pressure rho g (depth - y). No walls: probes stay 2h inside the fluid or test the surface.
Particles hydrostatic_lattice(double depth) {
  Particles p;
  const int nx = static_cast<int>(std::lround(1.0 / kDp)), ny = static_cast<int>(std::lround(depth / kDp));
  p.resize(static_cast<std::size_t>(nx * ny));
  p.n_fluid = p.size();
  p.volume = kDp * kDp;
  std::size_t i = 0;
  for (int a = 0; a < nx; ++a)
    for (int b = 0; b < ny; ++b, ++i) {
      p.position[i] = {(a + 0.5) * kDp, (b + 0.5) * kDp};
      p.pressure[i] = kRhoG * (depth - p.position[i].y);
    }
  return p;
}

struct Probe {
  Particles particles;
  CellGrid grid;
  WendlandC2 kernel{1.3 * kDp};
  explicit Probe(double depth) : particles(hydrostatic_lattice(depth)) {
    grid.build(particles.position, 0, particles.size(), kernel.support());
  }
  double point(Vec2 at) const { return pressure_at(kernel, particles, grid, at); }
  double face(Vec2 a, Vec2 b) const { return pressure_on_face(kernel, particles, grid, a, b, 0.25 * kDp); }
};

// Inside the fluid the pressure is linear in y: a vertical face reads the pressure at its middle.
// Tolerance 1e-6 relative: Shepard interpolation of a linear field is exact on a lattice whose
// kernel sum is uniform, which holds 2h away from the surface and the edges.
TEST(PressureProbe, FaceInALinearFieldReadsThePressureAtItsMiddle) {
  const Probe probe(0.5);
  const Vec2 a{0.5, 0.10}, b{0.5, 0.19};
  const double expected = kRhoG * (0.5 - 0.145);
  EXPECT_NEAR(probe.point({0.5, 0.145}), expected, 1e-6 * expected);
  EXPECT_NEAR(probe.face(a, b), expected, 1e-6 * expected);
  // Reversing the face changes nothing.
  EXPECT_DOUBLE_EQ(probe.face(a, b), probe.face(b, a));
}

// A face that reaches above the water reads 0 on its dry part, so less than its wet half alone.
TEST(PressureProbe, DryPartOfAFaceReadsAtmospheric) {
  const Probe probe(0.2);
  const Vec2 a{0.5, 0.10}, b{0.5, 0.40};  // wet from 0.10 to 0.20 m, dry above
  EXPECT_EQ(probe.point({0.5, 0.35}), 0.0);
  const double face = probe.face(a, b);
  const double wet_half = probe.face(a, {0.5, 0.2});
  EXPECT_GT(face, 0.0);
  EXPECT_LT(face, 0.5 * wet_half);  // at most a third of the face is wet
}

// A face of zero length is the point probe.
TEST(PressureProbe, FaceOfZeroLengthIsThePointProbe) {
  const Probe probe(0.5);
  const Vec2 a{0.3, 0.2};
  EXPECT_DOUBLE_EQ(probe.face(a, a), probe.point(a));
}

}  // namespace
}  // namespace sloshsph
