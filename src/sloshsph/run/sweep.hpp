#pragma once
// Sweeps (`sloshsph sweep`): one run per frequency ratio beta and per value of every ranged
// --set (KEY=A:B:N or KEY=a,b,c: amplitude, depth, screen layout...), the Cartesian product of
// them all, each in its own run directory under the sweep directory, then one
// frequency_response.csv assembled from the points' summary.json files. Process management lives in the command (app/cmd_sweep.cpp);
// this is the plan and the table.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// "A:B:N" -> N ratios from A to B inclusive, evenly spaced; "a,b,c" -> the list as given;
// a single number -> one point. Throws InputError(where, "--beta", ...) for a bad text,
// non-positive ratios or N < 1.
std::vector<double> parse_beta_range(const std::string& text, const std::string& where = "--beta");

// One swept key: `--set KEY=A:B:N` (N numbers from A to B) or `--set KEY=a,b,c` (the TOML values
// as given, split at the commas outside brackets, braces and quotes).
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;  // TOML value texts
};

// The --set texts of a sweep, split into those that hold for every point and the ranged ones.
struct SweepSets {
  std::vector<std::string> fixed;
  std::vector<SweepAxis> axes;
};
SweepSets split_sweep_sets(const std::vector<std::string>& sets);

struct SweepPoint {
  double beta = 0.0;                   // NaN until known when the sweep does not set it
  std::string label;                   // "beta_1.0100", "beta_1.0000__fill.depth_0.12": the run directory's name
  std::vector<std::string> overrides;  // the --set texts that make this point (frequency, then the axes)
  std::vector<std::string> axis_values;  // the value of each axis at this point
  std::string directory;               // sweep_dir/label
};

// The points of a sweep of `spec` (read from its case file): every beta (none: the case's own
// frequency) times every combination of the axes' values. The frequency override sets the key
// the case itself uses (excitation.beta, or excitation.frequency / omega computed from beta and
// the reference frequency), so a case given in Hz sweeps without editing it. Throws InputError
// when betas are given and the case has no harmonic or pitch excitation, or when there is
// nothing to sweep.
std::vector<SweepPoint> plan_sweep(const CaseSpec& spec, const std::vector<double>& betas,
                                   const std::vector<SweepAxis>& axes, const std::string& sweep_dir);

// The frequency ratio of a resolved case's harmonic or pitch excitation (NaN for other kinds).
double excitation_beta(const CaseSpec& spec);

// What a point's run directory says: "completed", "failed", "interrupted", or "" when it has no
// readable summary.json (not run, or killed).
std::string point_status(const std::string& directory);

// Whether a point need not run again: it completed (or failed, unless `retry_failed`) from the
// same case: `expected_case_toml` gives what resolved_case_toml makes of the point's case (called
// only then: reading a case can take a modal solve). Throws InputError(directory) when the
// directory holds a run of another case or other --set values.
bool point_finished(const SweepPoint& p, bool retry_failed, const std::function<std::string()>& expected_case_toml);

// Whether a point was interrupted with a checkpoint to resume from (rather than to run again).
bool point_resumable(const SweepPoint& p);

// frequency_response.csv from the points' summary.json files. Fixed columns (users' scripts
// rely on them): beta, omega, eta_max, eta_min, F_sw_max, F_sw_min, energy_per_cycle, status;
// then normalised_energy, F_w_max, F_w_min, eta_max:<gauge>, eta_min:<gauge> for every gauge,
// set:<key> for every axis of the sweep, wall_time_s and run_dir. eta_* without a gauge name are
// those of the case's first gauge.
// Missing numbers (a failed point, a case without gauges) are written as nan.
std::string frequency_response_csv(const CaseSpec& spec, const std::vector<SweepAxis>& axes,
                                   const std::vector<SweepPoint>& points);

}  // namespace sloshsph
