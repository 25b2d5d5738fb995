#pragma once
// Frequency sweeps (`sloshsph sweep`): one run per frequency ratio beta, each in its own run
// directory under the sweep directory, then one frequency_response.csv assembled from the
// points' summary.json files. Process management lives in the command (app/cmd_sweep.cpp);
// this is the plan and the table.
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// "A:B:N" -> N ratios from A to B inclusive, evenly spaced; "a,b,c" -> the list as given;
// a single number -> one point. Throws InputError(where, "--beta", ...) for a bad text,
// non-positive ratios or N < 1.
std::vector<double> parse_beta_range(const std::string& text, const std::string& where = "--beta");

struct SweepPoint {
  double beta = 0.0;
  std::string label;                   // "beta_1.0100": the run directory's name
  std::string override_text;           // the --set that gives this point its frequency
  std::string directory;               // sweep_dir/label
};

// The points of a sweep of `spec` (read from its case file). The override sets the key the
// case itself uses (excitation.beta, or excitation.frequency / omega computed from beta and
// the reference frequency), so a case given in Hz sweeps without editing it. Throws
// InputError unless the case has a harmonic or pitch excitation.
std::vector<SweepPoint> plan_sweep(const CaseSpec& spec, const std::vector<double>& betas,
                                   const std::string& sweep_dir);

// What a point's run directory says: "completed", "failed", "interrupted", or "" when it has no
// readable summary.json (not run, or killed).
std::string point_status(const std::string& directory);

// frequency_response.csv from the points' summary.json files. Fixed columns (users' scripts
// rely on them): beta, omega, eta_max, eta_min, F_sw_max, F_sw_min, energy_per_cycle, status;
// then normalised_energy, F_w_max, F_w_min, eta_max:<gauge>, eta_min:<gauge> for every gauge,
// wall_time_s and run_dir. eta_* without a gauge name are those of the case's first gauge.
// Missing numbers (a failed point, a case without gauges) are written as nan.
std::string frequency_response_csv(const CaseSpec& spec, const std::vector<SweepPoint>& points);

}  // namespace sloshsph
