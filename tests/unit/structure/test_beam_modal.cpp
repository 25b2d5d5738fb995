// Natural frequencies of the beam model (Beam::natural_frequencies) against Euler-Bernoulli theory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sloshsph/structure/beam.hpp"

namespace sloshsph {
namespace {

// L/t = 200, so that shear deformation and rotary inertia (Timoshenko corrections, ~(beta_n r / L)^2
// with r = t/sqrt(12): < 0.03 % for the third mode) are negligible against the Euler-Bernoulli reference.
BeamSpec slender_beam(int elements, BeamMass mass) {
  BeamSpec spec;
  spec.start = {0.0, 0.0};
  spec.end = {1.0, 0.0};
  spec.elements = elements;
  spec.thickness = 0.005;
  spec.youngs_modulus = 2e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1200.0;
  spec.mass = mass;
  return spec;
}

double euler_bernoulli_omega(const Beam& beam, double beta_l) {
  const double length = beam.length();
  return beta_l * beta_l * std::sqrt(beam.section().bending / (beam.mass_per_length() * std::pow(length, 4)));
}

// Test 3a. Reference: clamped-free Euler-Bernoulli beam, beta_n L = 1.8751, 4.6941, 7.8548,
// omega_n = (beta_n L)^2 sqrt(E I / (rho A L^4)) (e.g. Blevins, "Formulas for natural frequency and mode
// shape", 1979, table 8-1). Tolerance 1 % on each of the first three, 40 elements, both mass matrices.
TEST(BeamModal, CantileverFirstThreeFrequencies) {
  const double beta_l[3] = {1.8751, 4.6941, 7.8548};
  for (const BeamMass mass : {BeamMass::kLumped, BeamMass::kConsistent}) {
    const Beam beam(slender_beam(40, mass));
    const std::vector<double> omega = beam.natural_frequencies(3);
    ASSERT_EQ(omega.size(), 3u);
    for (int n = 0; n < 3; ++n) {
      const double reference = euler_bernoulli_omega(beam, beta_l[n]);
      std::printf("cantilever mode %d (%s mass): omega %.5f rad/s vs %.5f (ratio %.5f)\n", n + 1,
                  mass == BeamMass::kLumped ? "lumped" : "consistent", omega[static_cast<std::size_t>(n)], reference,
                  omega[static_cast<std::size_t>(n)] / reference);
      EXPECT_NEAR(omega[static_cast<std::size_t>(n)] / reference, 1.0, 0.01) << "mode " << n + 1;
    }
  }
}

// Test 3b. Reference: clamped-clamped Euler-Bernoulli beam, beta_1 L = 4.7300 (Blevins 1979).
// Tolerance 1 %, 40 elements.
TEST(BeamModal, ClampedClampedFirstFrequency) {
  BeamSpec spec = slender_beam(40, BeamMass::kLumped);
  spec.end_support = BeamSupport::kClamped;
  const Beam beam(spec);
  const double omega = beam.natural_frequencies(1).at(0);
  const double reference = euler_bernoulli_omega(beam, 4.7300);
  std::printf("clamped-clamped mode 1: omega %.5f rad/s vs %.5f (ratio %.5f)\n", omega, reference, omega / reference);
  EXPECT_NEAR(omega / reference, 1.0, 0.01);
}

// The frequencies are linearised about the current state: an axial tensile preload raises the first
// frequency of a pinned-pinned string-beam. Reference: omega_1^2 = (pi/L)^4 EI/m + (pi/L)^2 T/m
// (Blevins 1979, beam under axial tension, pinned ends). Tolerance 1 %. The far end is held by a
// roller (y fixed) and pulled with T.
TEST(BeamModal, TensionRaisesTheFirstFrequency) {
  BeamSpec spec = slender_beam(40, BeamMass::kLumped);
  spec.start_support = BeamSupport::kPinned;
  spec.end_support = BeamSupport::kFree;
  spec.constraints.push_back({40, false, true, false});
  Beam beam(spec);
  const double ei = beam.section().bending;
  const double tension = 10.0 * ei * M_PI * M_PI;  // 10 x the Euler-like load pi^2 EI / L^2
  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces.back() = {tension, 0.0};
  beam.static_solve(loads);
  const double m = beam.mass_per_length();
  const double reference = std::sqrt(std::pow(M_PI, 4) * ei / m + M_PI * M_PI * tension / m);
  const double omega = beam.natural_frequencies(1).at(0);
  std::printf("pinned-pinned under tension: omega %.5f vs %.5f (ratio %.5f)\n", omega, reference, omega / reference);
  EXPECT_NEAR(omega / reference, 1.0, 0.01);
}

}  // namespace
}  // namespace sloshsph
