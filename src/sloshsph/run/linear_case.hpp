#pragma once
// `sloshsph linear` as data: the linear modal solution from rest (linear/forced_response.hpp)
// of a case's tank, fill, base motion and gauges, with a modal damping of the user's choice, as
// the time series an SPH run of the case writes (the same column names), for a comparison of
// the two.
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/linear/forced_response.hpp"
#include "sloshsph/linear/screen_drag.hpp"
#include "sloshsph/run/response.hpp"

namespace sloshsph {

struct LinearCaseOptions {
  int modes = 10;
  // "auto": boundary-layer for a rectangle, none otherwise; "none"; "boundary-layer" (a
  // rectangle only); or a damping ratio applied to every mode, as text ("0.005").
  std::string damping = "auto";
  // The drag of the case's vertical screens in a rectangular tank (linear/screen_drag.hpp); false:
  // a clean tank.
  bool screens = true;
};

struct LinearCase {
  std::vector<SloshingMode> modes;
  std::vector<double> damping;     // zeta per mode
  std::string damping_model;       // "none", "boundary-layer" or "given"
  std::vector<std::string> gauge_names;
  std::vector<std::string> ignored;  // parts of the case the linear model leaves out (plates, ...)
  std::vector<LinearScreen> screens; // the screens it takes, with their loss laws
  double still_water_area = 0.0;     // m^2, of the section below the still level
  LinearResponse response;
  std::vector<double> base_displacement;  // m, x of the base at each of response.time
};

// Throws InputError naming the key when the case cannot be a linear horizontal motion from rest:
// a pitch (excitation.type), a tank on a structure (structure), blocks of water (fill.blocks);
// and, for the option, "--damping" when it is not one of the forms above or asks for the
// boundary layers of a tank that is not a rectangle.
LinearCase linear_case_response(const CaseSpec& spec, const LinearCaseOptions& options);

// The columns `time`, `x_base`, `eta:<gauge>`..., `F_w`, `F_sw` (the SPH run's names and units).
void write_linear_csv(const std::string& path, const LinearCase& result);

// The linear model's steady state at one frequency ratio: the response (run/response.hpp) of its
// time series, analysed as an SPH run's (the last output.response_cycles periods, low-passed at
// output.lowpass_hz).
struct LinearFrequencyPoint {
  double beta = 0.0;
  double omega = 0.0;  // rad/s
  Response response;
};

struct LinearFrequencyResponse {
  LinearCase model;  // the modes, damping and screens (at the first ratio; its time series dropped)
  std::vector<LinearFrequencyPoint> points;
};

// The linear model of the case file at each frequency ratio of `betas`, the case read with `sets`
// and the frequency key the case uses set as `sloshsph sweep` sets it (run/sweep.hpp). Throws
// InputError naming excitation.type unless the excitation is harmonic.
LinearFrequencyResponse linear_frequency_response(const std::string& case_path, const std::vector<std::string>& sets,
                                                  const std::vector<double>& betas, const LinearCaseOptions& options);

// The columns of a sweep's frequency_response.csv that the linear model has: beta, omega, eta_max,
// eta_min (the first gauge), F_sw_max, F_sw_min, energy_per_cycle, F_w_max, F_w_min, then
// eta_max:<gauge>, eta_min:<gauge> for every gauge.
void write_linear_frequency_csv(const std::string& path, const std::vector<LinearFrequencyPoint>& points,
                                const std::vector<std::string>& gauge_names);

}  // namespace sloshsph
