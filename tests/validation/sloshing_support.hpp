#pragma once
// The rectangular-tank sloshing checks, shared by the CI tests (coarse, sloshing_validation.cpp)
// and the long tests at the cases' own resolution (sloshing_long.cpp): the same references and
// tolerances at both resolutions.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "validation_check.hpp"

namespace sloshsph::testing {

// Samples of column `c` with time in [t0, t1].
inline std::pair<std::vector<double>, std::vector<double>> window(const RunResult& r, const std::string& c, double t0,
                                                                  double t1) {
  std::vector<double> t, x;
  for (std::size_t k = 0; k < r["time"].size(); ++k)
    if (r["time"][k] >= t0 && r["time"][k] <= t1) {
      t.push_back(r["time"][k]);
      x.push_back(r[c][k]);
    }
  return {t, x};
}

// cases/linear_sloshing.toml with `overrides` (`resolution` names them in the check text): two
// periods of excitation, then free decay. Reference: linear theory
// omega1 = sqrt(pi g / L tanh(pi h / L)) (thesis eq. 4.29). Tolerance: the free-decay period
// (mean up-crossing period of each gauge, after the excitation) within 3% of 2 pi / omega1; no
// particle leaves the tank.
inline void check_linear_sloshing_frequency(const std::vector<std::string>& overrides, const std::string& resolution) {
  const auto r = run_case_in_memory("linear_sloshing.toml", overrides);
  const double omega1 = rectangular_sloshing_omega(0.5, 0.25, 9.81);
  const double t_stop = 1.6713;
  for (const char* gauge : {"eta:left", "eta:right"}) {
    const auto [t, x] = window(r, gauge, t_stop + 0.2, 6.0);
    const double period = zero_crossing_period(t, x);
    const double omega = 2.0 * std::numbers::pi / period;
    report(std::string("free_decay_omega_") + (gauge + 4), omega);
    report(std::string("free_decay_omega_error_") + (gauge + 4), omega / omega1 - 1.0);
    const std::string quantity = "free-decay angular frequency (mean up-crossing period, 1.87-6 s), gauge ";
    check_relative(quantity + (gauge + 4) + ", " + resolution, omega, omega1, 0.03,
                   "linear theory omega1 = sqrt(pi g / L tanh(pi h / L)), thesis eq. 4.29", "rad/s");
  }
  check_at_most("particles leaked from the tank, " + resolution, static_cast<double>(r.leaked), 0.0, "none may leave");
  record_curve({"gauges", "Linear sloshing: two periods of excitation, then free decay (" + resolution + ")",
                "time (s)", "eta (m)", r["time"], r["eta:left"], "right gauge (same run)", r["time"], r["eta:right"],
                false});
}

// cases/liu_lin_2008.toml (thesis 2.6.2): L = 0.57 m, h = 0.15 m, X0/L = 0.0088, beta = 1, 7 s.
// Tolerances: no particle leaves the tank; the gauge 20 mm from the left wall oscillates at the
// excitation frequency (FFT peak of the last 4 s within 3%).
inline void check_liu_lin_resonance(std::vector<std::string> overrides, const std::string& resolution) {
  overrides.push_back("output.snapshot_interval=0");
  const auto r = run_case_in_memory("liu_lin_2008.toml", overrides);
  check_at_most("particles leaked from the tank, " + resolution, static_cast<double>(r.leaked), 0.0, "none may leave");
  const double omega_e = rectangular_sloshing_omega(0.57, 0.15, 9.81);
  const auto [t, x] = window(r, "eta:left", 3.0, 7.0);
  const double f = dominant_frequency_fft(x, t[1] - t[0]);
  report("liu_lin_gauge_frequency_hz", f);
  report("liu_lin_gauge_frequency_error", 2.0 * std::numbers::pi * f / omega_e - 1.0);
  check_relative("dominant (FFT) frequency of the gauge 20 mm from the left wall, 3-7 s, " + resolution, f,
                 omega_e / (2.0 * std::numbers::pi), 0.03,
                 "the excitation frequency, beta = 1 of linear omega1 (L = 0.57 m, h = 0.15 m), Liu & Lin (2008)",
                 "Hz");
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  report("liu_lin_gauge_peak_m", peak);
  report("liu_lin_wall_seconds", r.wall_seconds);
  record_curve({"gauge", "Liu & Lin (2008) at resonance: gauge 20 mm from the left wall (" + resolution + ")",
                "time (s)", "eta (m)", r["time"], r["eta:left"], "", {}, {}});
}

}  // namespace sloshsph::testing
