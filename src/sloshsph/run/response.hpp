#pragma once
// Steady-state response of a harmonically excited tank, computed from the sampled time series
// after a run (thesis sec. 2.6.3 and 4.3.1): the series are low-pass filtered (zero phase, 5 Hz
// by default, as the thesis filters its data), then the per-cycle maxima and minima of the last
// N excitation cycles are averaged, and the energy dissipated per cycle (eq. 4.28) is integrated
// from the base shear and the base displacement.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

struct ResponseOptions {
  double period = 0.0;         // s, the excitation period 2 pi / omega
  int cycles = 10;             // cycles averaged, counted back from the end of the run
  double cutoff_hz = 5.0;      // zero-phase Butterworth low-pass cut-off; <= 0: no filtering
  double water_mass = 0.0;     // kg/m, for the normalised energy of eq. 4.27
  double amplitude = 0.0;      // m, base amplitude X0, for eq. 4.27
  bool energy = true;          // eq. 4.28 (horizontal base motion only: F_w dX)
  bool whole_tank = false;     // 3D: forces in N and energies in J (2D: per metre, N/m and J/m)
};

// The analysis a resolved case asks for (an SPH run's and the linear model's alike): the period of
// its excitation (excitation.omega > 0), output.response_cycles, output.lowpass_hz, the water mass
// and base amplitude of eq. 4.27, and eq. 4.28's energy for a harmonic translation (a pitch does
// its work through a moment, not F_w dX).
ResponseOptions response_options(const CaseSpec& spec, double water_mass, bool whole_tank);

struct ResponseValue {
  std::string name;  // the time-series column, e.g. "eta:right", "F_sw"
  std::string unit;
  double avg_max = 0.0;
  double avg_min = 0.0;
};

struct Response {
  std::vector<ResponseValue> values;        // every gauge, pressure probe and force column
  std::optional<double> energy_per_cycle;   // J/m (3D: J) per cycle, eq. 4.28 (needs F_w and x_base)
  std::optional<double> normalised_energy;  // eq. 4.27
  int cycles = 0;                           // cycles actually averaged
  double cutoff_hz = 0.0;
  std::string note;  // why nothing could be computed (run shorter than one cycle, ...)
  bool whole_tank = false;  // ResponseOptions::whole_tank: the energy in J, not J/m

  const ResponseValue* find(const std::string& name) const;
};

// `names`/`units` are the time-series columns, `columns[k]` the samples of column k (the
// first is time). Columns analysed: every "eta:", "p:" and "F_screen:" column, F_w, F_sw (and the
// 3D F_sw_y).
// A record shorter than one period gives a Response with only `note` set.
Response steady_state_response(const std::vector<std::string>& names, const std::vector<std::string>& units,
                               const std::vector<std::vector<double>>& columns, const ResponseOptions& options);

nlohmann::json response_json(const Response& r);

// response.csv: quantity, unit, avg_max, avg_min, value (one row per analysed column, then
// energy_per_cycle and normalised_energy with their number under `value`).
std::string response_csv(const Response& r);

}  // namespace sloshsph
