#pragma once
// `sloshsph linear` as data: the linear modal solution from rest (linear/forced_response.hpp)
// of a case's tank, fill, base motion and gauges, with a modal damping of the user's choice, as
// the time series an SPH run of the case writes (the same column names), for a comparison of
// the two.
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/linear/forced_response.hpp"

namespace sloshsph {

struct LinearCaseOptions {
  int modes = 10;
  // "auto": boundary-layer for a rectangle, none otherwise; "none"; "boundary-layer" (a
  // rectangle only); or a damping ratio applied to every mode, as text ("0.005").
  std::string damping = "auto";
};

struct LinearCase {
  std::vector<SloshingMode> modes;
  std::vector<double> damping;     // zeta per mode
  std::string damping_model;       // "none", "boundary-layer" or "given"
  std::vector<std::string> gauge_names;
  std::vector<std::string> ignored;  // parts of the case the linear model leaves out (screens, ...)
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

}  // namespace sloshsph
