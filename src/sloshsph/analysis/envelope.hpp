#pragma once
// The crest envelope of a response: its largest value in each period, for comparing a
// simulation with a reference (e.g. the linear modal solution, linear/forced_response.hpp)
// period by period.
#include <vector>

namespace sloshsph {

// The largest y over t in [start + k period, start + (k + 1) period), k = 0 .. count - 1;
// NaN for a window without a sample. t ascending, the same length as y.
std::vector<double> crests_per_period(const std::vector<double>& t, const std::vector<double>& y, double start,
                                      double period, int count);

struct EnvelopeComparison {
  std::vector<double> reference, simulated;  // crest of each period
  // (simulated - reference) / the largest reference crest, per period, and its largest magnitude
  // (relative to the largest crest, so that the small first crests of a start from rest do not
  // turn their small absolute differences into large ratios).
  std::vector<double> deviation;
  double worst_deviation = 0.0;
};

// Compares the crests of two series (each on its own time grid) over `count` periods from `start`.
EnvelopeComparison compare_crest_envelopes(const std::vector<double>& t_reference,
                                           const std::vector<double>& y_reference,
                                           const std::vector<double>& t_simulated,
                                           const std::vector<double>& y_simulated, double start, double period,
                                           int count);

}  // namespace sloshsph
