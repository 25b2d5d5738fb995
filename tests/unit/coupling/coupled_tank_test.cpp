// Two-way structure-tank coupling (thesis 4.2.3, eqs. 4.20-4.22) with a small SPH tank whose
// sloshing frequency is far above the structure's: the liquid then moves with the tank as an
// added mass (issue 5, test 3) and the force the tank puts on the structure is -m_w x''_s.
// The undamped energy test (issue 5, test 4) is tests/validation/structure_coupling_validation.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <vector>

#include "coupling_test_cases.hpp"
#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

struct CoupledRun {
  std::map<std::string, std::vector<double>> series;
  double fluid_mass = 0.0;  // kg/m at the start
  double sloshing_omega = 0.0;
  std::size_t leaked = 0;
};

CoupledRun run(const std::string& text) {
  const CaseSpec spec = resolve_case(read_case_text(text, "coupled.toml"));
  Simulation sim(spec);
  CoupledRun r;
  r.fluid_mass = sim.fluid_mass();
  r.sloshing_omega = first_sloshing_omega(spec);
  auto record = [&] {
    const std::vector<double> row = sim.sample();
    for (std::size_t k = 0; k < row.size(); ++k) r.series[sim.columns()[k].name].push_back(row[k]);
  };
  record();
  double next = spec.output.sample_interval;
  while (!sim.finished()) {
    sim.step();
    if (sim.time() >= next - 1e-9 || sim.finished()) {
      record();
      while (next <= sim.time() + 1e-9) next += spec.output.sample_interval;
    }
  }
  r.leaked = sim.leaked();
  return r;
}

// Structure of mass M = 10 kg and stiffness K carrying one 1 m wide tank of ~10 kg/m of water
// (0.1 m x 0.1 m), released from x0 at t = 0.
std::string coupled_case(double stiffness, double damping, double x0, double end, const std::string& extra = "",
                         double viscosity = 1.0e-6) {
  char s[512];
  std::snprintf(s, sizeof s,
                "[structure]\nmass = 10.0\nstiffness = %.17g\ndamping = %.17g\ntank_width = 1.0\ntanks = 1\n"
                "initial_displacement = %.17g\n",
                stiffness, damping, x0);
  return test::small_tank_case(extra + s, end, viscosity);
}

TEST(CoupledTank, StiffTankIsAnAddedMass) {
  // Reference: a liquid whose first sloshing frequency is far above the structure's moves with
  // the tank, so the structure vibrates at f = sqrt(K / (M + m_w)) / 2 pi (issue 5: within 2%),
  // m_w the simulated water mass (particles x mass, 10.0 kg here). K is chosen for f = 0.5 Hz;
  // the tank's sloshing frequency is 2.79 Hz (ratio 5.6). Linear theory (the first sloshing mode,
  // effective mass fraction 8 tanh(pi h/L) / (pi^3 h/L) = 0.257, below its resonance) adds
  // 0.257 (f/f_1)^2 / (1 - (f/f_1)^2) = 0.85% of m_w to the mass: -0.2% on f. Measured over the
  // 5 periods of a 10 s free vibration by the mean up-crossing period of x_s.
  const double m = 10.0, m_w_nominal = 10.0, f_target = 0.5;
  const double k = (m + m_w_nominal) * std::pow(2 * kPi * f_target, 2);
  const CoupledRun r = run(coupled_case(k, 0.0, 0.02, 10.0));
  const double m_w = r.fluid_mass;
  const double f_expected = std::sqrt(k / (m + m_w)) / (2 * kPi);
  const double f_measured = 1.0 / zero_crossing_period(r.series.at("time"), r.series.at("x_s"));
  EXPECT_NEAR(f_measured / f_expected, 1.0, 0.02);
  EXPECT_GT(r.sloshing_omega / (2 * kPi * f_expected), 5.0);  // the premise: far above
  EXPECT_EQ(r.leaked, 0u);
  // Sign and size of the tank's force on the structure: F_TLD = -beta m_w x''_s with beta = 1 for
  // a rigid liquid; linear theory adds the first mode's 0.85% (above). beta by least squares over
  // the run (the free sloshing at 2.8 Hz that the release sets off, ~10% of the force, is nearly
  // orthogonal to the 0.5 Hz motion over 5 periods): within 5% of 1.
  const auto& a = r.series.at("a_s");
  const auto& f_tld = r.series.at("F_TLD");
  double fa = 0.0, aa = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {  // row 0 holds no step yet
    fa += f_tld[i] * a[i];
    aa += a[i] * a[i];
  }
  const double beta = -fa / (m_w * aa);
  EXPECT_NEAR(beta, 1.0, 0.05);
  // The exchange is energy-consistent: the structure loses what the walls do on the liquid,
  // E_s(t) - E_s(0) = -n b W_base(t) (n b = 1 m here). Reference: 0 (Newmark's displacement
  // increment is exactly dt times the mean velocity; the extrapolated sloshing force differs from
  // the one measured afterwards by O(dt^2)); tolerance 1e-4 of the initial energy K x0^2 / 2.
  const auto& es = r.series.at("E_s");
  const auto& w = r.series.at("W_base");
  double exchange = 0.0;
  for (std::size_t i = 0; i < es.size(); ++i) exchange = std::max(exchange, std::abs(es[i] - es[0] + w[i]));
  const double e0 = 0.5 * k * 0.02 * 0.02;
  EXPECT_LT(exchange, 1e-4 * e0);
  // The tank is carried by the structure: the base columns are the structure's.
  EXPECT_EQ(r.series.at("x_base"), r.series.at("x_s"));
  EXPECT_EQ(r.series.at("a_base"), r.series.at("a_s"));
  std::printf("added mass: m_w = %.4f kg/m, f = %.5f Hz, sqrt(K/(M+m_w))/2pi = %.5f Hz (ratio %.5f), "
              "sqrt(K/M)/2pi = %.5f Hz; F_TLD = -%.4f m_w a_s; energy exchange error %.2e of K x0^2/2\n",
              m_w, f_measured, f_expected, f_measured / f_expected, std::sqrt(k / m) / (2 * kPi), beta,
              exchange / e0);
}

}  // namespace
}  // namespace sloshsph
