#include "sloshsph/analysis/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sloshsph/analysis/filter.hpp"

namespace sloshsph {
namespace {

// y low-passed at cutoff_hz (t uniform; analysis/filter.hpp).
std::vector<double> smoothed(const std::vector<double>& t, const std::vector<double>& y, double cutoff_hz) {
  if (t.size() < 2) return y;
  return lowpass_if_resolved(y, (t.back() - t.front()) / static_cast<double>(t.size() - 1), cutoff_hz);
}

std::vector<double> half_heights(const PeriodExtremes& e) {
  std::vector<double> h(e.crest.size());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = 0.5 * (e.crest[k] - e.trough[k]);
  return h;
}

}  // namespace

PeriodExtremes extremes_per_period(const std::vector<double>& t, const std::vector<double>& y, double start,
                                   double period, int count) {
  if (t.size() != y.size()) throw std::invalid_argument("extremes_per_period: t and y differ in length");
  if (!(period > 0.0) || count < 0) throw std::invalid_argument("extremes_per_period: period <= 0 or count < 0");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PeriodExtremes e{std::vector<double>(static_cast<std::size_t>(count), nan),
                   std::vector<double>(static_cast<std::size_t>(count), nan)};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double k = std::floor((t[i] - start) / period);
    if (k < 0 || k >= count) continue;
    double& c = e.crest[static_cast<std::size_t>(k)];
    double& d = e.trough[static_cast<std::size_t>(k)];
    if (std::isnan(c) || y[i] > c) c = y[i];
    if (std::isnan(d) || y[i] < d) d = y[i];
  }
  return e;
}

EnvelopeComparison compare_envelopes(const std::vector<double>& t_reference, const std::vector<double>& y_reference,
                                     const std::vector<double>& t_simulated, const std::vector<double>& y_simulated,
                                     double start, double period, int count, double lowpass_hz) {
  EnvelopeComparison c;
  c.reference_extremes =
      extremes_per_period(t_reference, smoothed(t_reference, y_reference, lowpass_hz), start, period, count);
  c.simulated_extremes =
      extremes_per_period(t_simulated, smoothed(t_simulated, y_simulated, lowpass_hz), start, period, count);
  c.reference = half_heights(c.reference_extremes);
  c.simulated = half_heights(c.simulated_extremes);
  double largest = 0.0;
  for (double r : c.reference)
    if (!std::isnan(r)) largest = std::max(largest, r);
  bool missing = false;  // a period without a sample in either series makes the worst NaN
  for (int k = 0; k < count; ++k) {
    const double d = largest > 0.0 ? (c.simulated[k] - c.reference[k]) / largest
                                   : std::numeric_limits<double>::quiet_NaN();
    c.deviation.push_back(d);
    if (std::isnan(d)) missing = true;
    else c.worst_deviation = std::max(c.worst_deviation, std::abs(d));
  }
  if (missing) c.worst_deviation = std::numeric_limits<double>::quiet_NaN();
  return c;
}

}  // namespace sloshsph
