#pragma once
// The first impact peak of a pressure record (a wall probe hit by a dam-break surge or a breaking
// wave): its value and time, its rise time and the impulse under it. Definitions in
// docs/physics.md, "Impact peak"; summary.json `pressure_probes` (run/run_case.cpp) reports them.
#include <optional>
#include <vector>

namespace sloshsph {

struct ImpactPeakOptions {
  // The rise starts where p - p0 first reaches onset_fraction * (max p - p0), p0 the first sample.
  double onset_fraction = 0.1;
  // The first peak is over once the signal falls this fraction of (max p - p0) below its running
  // maximum: a fluctuation smaller than that does not end it.
  double drop_fraction = 0.1;
  // Reference levels of the rise time, as fractions of the peak above p0 (IEEE Std 181: 10% and 90%).
  double low_level = 0.1, high_level = 0.9;
};

struct ImpactPeak {
  double baseline = 0.0;    // p0, the first sample (Pa)
  double value = 0.0;       // the first peak (Pa, absolute, not above p0)
  double time = 0.0;        // s, of the peak sample
  double rise_start = 0.0;  // s, last up-crossing of p0 + low_level (value - p0) before the peak
  double rise_end = 0.0;    // s, last up-crossing of p0 + high_level (value - p0) before the peak
  double rise_time = 0.0;   // s, rise_end - rise_start
  double end = 0.0;         // s, where the peak ends (see impulse)
  double impulse = 0.0;     // Pa s, integral of (p - p0) dt from rise_start to end
};

// The first impact peak of p(t) (t increasing, p finite, as many samples as t, at least 2):
//  * onset: the first sample at which p - p0 >= onset_fraction * (max p - p0);
//  * peak: from the onset, the largest sample before the signal first falls drop_fraction *
//    (max p - p0) below its running maximum (or before the end of the record);
//  * rise time: between the last up-crossings of the low and high reference levels before the
//    peak (linear interpolation between samples);
//  * end: the first down-crossing of the low level after the peak, or, if the signal first stops
//    falling after it has dropped drop_fraction * (max p - p0) below the peak (a plateau or a
//    second rise), that local minimum; the end of the record otherwise;
//  * impulse: the integral of p - p0 over [rise_start, end] (trapezoids on the linear interpolant).
// Nothing (std::nullopt) when the record never rises above its first sample.
std::optional<ImpactPeak> first_impact_peak(const std::vector<double>& t, const std::vector<double>& p,
                                            const ImpactPeakOptions& options = {});

// The integral over [a, b] of the piecewise-linear interpolant of y(t) (clamped to the record).
double integral_between(const std::vector<double>& t, const std::vector<double>& y, double a, double b);

}  // namespace sloshsph
