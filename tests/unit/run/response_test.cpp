// Steady-state response analysis (run/response.hpp) on synthetic series with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/run/response.hpp"

namespace sloshsph {
namespace {

struct Series {
  std::vector<std::string> names{"time", "x_base", "eta:g", "F_w", "E_kin"};
  std::vector<std::string> units{"s", "m", "m", "N/m", "J/m"};
  std::vector<std::vector<double>> columns = std::vector<std::vector<double>>(5);
};

// X = X0 sin(w t); eta = a sin(w t + 0.3) + 0.004 (a surface set up above its datum, and a
// 20 Hz ripple the 5 Hz filter must remove); F_w = k X + c X' (a spring and a dashpot).
Series synthetic(double omega, double x0, double a, double k, double c, double end, double dt) {
  Series s;
  for (double t = 0.0; t <= end + 1e-12; t += dt) {
    const double x = x0 * std::sin(omega * t), v = x0 * omega * std::cos(omega * t);
    s.columns[0].push_back(t);
    s.columns[1].push_back(x);
    s.columns[2].push_back(a * std::sin(omega * t + 0.3) + 0.004 + 0.002 * std::sin(2 * std::numbers::pi * 20 * t));
    s.columns[3].push_back(k * x + c * v);
    s.columns[4].push_back(1.0);
  }
  return s;
}

// Reference: the averages of the per-cycle maxima and minima of a sine of amplitude a about a
// mean m are m +- a; the 20 Hz ripple (amplitude 2 mm) is attenuated by the zero-phase 4th-order
// Butterworth at 5 Hz by |H(20 Hz)|^2 = 1 / (1 + 4^8) = 1.5e-5. Tolerance 1e-4 m (2% of a): the
// sampling (100 Hz) limits the peak refinement. The energy per cycle of F = k X + c X' over a
// closed cycle is the dashpot's pi c w X0^2 (the spring returns what it takes), within 0.5%.
TEST(SteadyStateResponse, SineAmplitudesAndDashpotEnergy) {
  const double omega = 2.0 * std::numbers::pi * 0.9, x0 = 0.005, a = 0.02, k = 50.0, c = 3.0;
  const Series s = synthetic(omega, x0, a, k, c, 30.0, 0.01);
  ResponseOptions o;
  o.period = 2.0 * std::numbers::pi / omega;
  o.cycles = 10;
  o.water_mass = 100.0;
  o.amplitude = x0;
  const Response r = steady_state_response(s.names, s.units, s.columns, o);
  ASSERT_TRUE(r.note.empty()) << r.note;
  EXPECT_EQ(r.cycles, 10);
  EXPECT_EQ(r.cutoff_hz, 5.0);
  const ResponseValue* eta = r.find("eta:g");
  ASSERT_NE(eta, nullptr);
  EXPECT_NEAR(eta->avg_max, 0.004 + a, 1e-4);
  EXPECT_NEAR(eta->avg_min, 0.004 - a, 1e-4);
  EXPECT_EQ(r.find("E_kin"), nullptr);  // energies are not response amplitudes
  ASSERT_TRUE(r.energy_per_cycle.has_value());
  const double dashpot = std::numbers::pi * c * omega * x0 * x0;
  EXPECT_NEAR(*r.energy_per_cycle / dashpot, 1.0, 0.005);
  // eq. 4.27: E / (0.5 m (X0 w)^2)
  EXPECT_NEAR(*r.normalised_energy, *r.energy_per_cycle / (0.5 * 100.0 * std::pow(x0 * omega, 2)), 1e-12);
  EXPECT_NE(response_csv(r).find("energy_per_cycle,J/m,,,"), std::string::npos);
}

// A run shorter than one period has no steady state: a note, no numbers, no exception.
TEST(SteadyStateResponse, ShortRecordGivesANote) {
  const Series s = synthetic(1.0, 0.005, 0.02, 0.0, 0.0, 3.0, 0.01);
  ResponseOptions o;
  o.period = 2.0 * std::numbers::pi;
  const Response r = steady_state_response(s.names, s.units, s.columns, o);
  EXPECT_FALSE(r.note.empty());
  EXPECT_TRUE(r.values.empty());
  EXPECT_TRUE(response_json(r).contains("note"));
}

}  // namespace
}  // namespace sloshsph
