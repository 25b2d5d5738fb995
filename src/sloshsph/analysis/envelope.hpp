#pragma once
// The amplitude envelope of a response, period by period, for comparing a simulation with a
// reference (e.g. the linear modal solution from rest, linear/forced_response.hpp).
#include <vector>

namespace sloshsph {

struct PeriodExtremes {
  std::vector<double> crest, trough;  // per period; NaN for a window without a sample
};

// The largest and smallest y over t in [start + k period, start + (k + 1) period),
// k = 0 .. count - 1. t ascending, the same length as y.
PeriodExtremes extremes_per_period(const std::vector<double>& t, const std::vector<double>& y, double start,
                                   double period, int count);

struct EnvelopeComparison {
  // Half the crest-to-trough height of each period (the amplitude), reference and simulated.
  std::vector<double> reference, simulated;
  PeriodExtremes reference_extremes, simulated_extremes;
  // (simulated - reference) / the largest reference amplitude, per period, and its largest
  // magnitude (relative to the largest amplitude, so that the small first periods of a start from
  // rest do not turn small absolute differences into large ratios). NaN when a period is missing.
  std::vector<double> deviation;
  double worst_deviation = 0.0;
};

// Compares the amplitude envelopes of two series (each on its own uniform time grid) over `count`
// periods from `start`. Half heights, not crests: a particle fill's still level differs from the
// nominal one by a fraction of dp (at h = 2 dp the gauges of cases/clean_tank_free_decay.toml rest
// 0.6-0.7 mm high; with a gap at a wall 2 mm low), a constant that is not sloshing and would count
// in every crest. With lowpass_hz > 0 both series are first passed through the zero-phase low-pass
// of analysis/filter.hpp at that cut-off (the 5 Hz of the thesis and of the run's response block).
EnvelopeComparison compare_envelopes(const std::vector<double>& t_reference, const std::vector<double>& y_reference,
                                     const std::vector<double>& t_simulated, const std::vector<double>& y_simulated,
                                     double start, double period, int count, double lowpass_hz = 0.0);

}  // namespace sloshsph
