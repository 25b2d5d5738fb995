#include "sloshsph/analysis/impact_peak.hpp"

#include <algorithm>
#include <cmath>

namespace sloshsph {
namespace {

// Time at which the segment from sample i to i + 1 passes `level` (linear between the samples).
double crossing_time(const std::vector<double>& t, const std::vector<double>& p, std::size_t i, double level) {
  const double dp = p[i + 1] - p[i];
  const double w = dp != 0.0 ? (level - p[i]) / dp : 0.0;
  return t[i] + std::clamp(w, 0.0, 1.0) * (t[i + 1] - t[i]);
}

// The index of the first peak: from `onset`, the running maximum until the signal first falls
// `drop` below it.
std::size_t first_peak_index(const std::vector<double>& p, std::size_t n, std::size_t onset, double drop) {
  std::size_t peak = onset;
  for (std::size_t i = onset; i < n; ++i) {
    if (p[i] > p[peak]) peak = i;
    else if (p[i] < p[peak] - drop) break;
  }
  return peak;
}

// The last time before sample `peak` at which p rises through `level` (p[peak] >= level).
double last_up_crossing(const std::vector<double>& t, const std::vector<double>& p, std::size_t peak, double level) {
  for (std::size_t i = peak; i-- > 0;)
    if (p[i] < level && p[i + 1] >= level) return crossing_time(t, p, i, level);
  return t[0];
}

// Where the peak ends: the first fall through `low` after it, or the first local minimum below
// `dropped` (a plateau or a second rise follows), or the last sample.
double peak_end(const std::vector<double>& t, const std::vector<double>& p, std::size_t n, std::size_t peak,
                double low, double dropped) {
  for (std::size_t i = peak + 1; i < n; ++i) {
    if (p[i] <= low) return crossing_time(t, p, i - 1, low);
    if (p[i] < dropped && (i + 1 == n || p[i + 1] >= p[i])) return t[i];
  }
  return t[n - 1];
}

// Samples before the first non-finite one (a failed run's record ends in a good state, but be safe).
std::size_t finite_prefix(const std::vector<double>& t, const std::vector<double>& p) {
  const std::size_t n = std::min(t.size(), p.size());
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(t[i]) || !std::isfinite(p[i])) return i;
  return n;
}

}  // namespace

double integral_between(const std::vector<double>& t, const std::vector<double>& y, double a, double b) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < std::min(t.size(), y.size()); ++i) {
    const double lo = std::max(a, t[i]), hi = std::min(b, t[i + 1]);
    if (!(hi > lo)) continue;
    const double slope = (y[i + 1] - y[i]) / (t[i + 1] - t[i]);
    const double y_lo = y[i] + slope * (lo - t[i]), y_hi = y[i] + slope * (hi - t[i]);
    sum += 0.5 * (y_lo + y_hi) * (hi - lo);  // exact: y is linear on the piece
  }
  return sum;
}

std::optional<ImpactPeak> first_impact_peak(const std::vector<double>& t, const std::vector<double>& p,
                                            const ImpactPeakOptions& options) {
  const std::size_t n = finite_prefix(t, p);
  if (n < 2) return std::nullopt;
  const double p0 = p[0];
  const double range = *std::max_element(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(n)) - p0;
  if (!(range > 0.0)) return std::nullopt;

  std::size_t onset = 0;
  while (p[onset] - p0 < options.onset_fraction * range) ++onset;  // ends: the maximum qualifies
  const double drop = options.drop_fraction * range;
  const std::size_t peak = first_peak_index(p, n, onset, drop);

  ImpactPeak r;
  r.baseline = p0;
  r.value = p[peak];
  r.time = t[peak];
  const double height = r.value - p0;
  const double low = p0 + options.low_level * height, high = p0 + options.high_level * height;
  r.rise_start = last_up_crossing(t, p, peak, low);
  r.rise_end = last_up_crossing(t, p, peak, high);
  r.rise_time = r.rise_end - r.rise_start;
  r.end = peak_end(t, p, n, peak, low, r.value - drop);
  std::vector<double> excess(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(n));
  for (double& v : excess) v -= p0;
  r.impulse = integral_between(t, excess, r.rise_start, r.end);
  return r;
}

}  // namespace sloshsph
