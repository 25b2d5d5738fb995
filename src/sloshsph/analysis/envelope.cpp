#include "sloshsph/analysis/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sloshsph {

std::vector<double> crests_per_period(const std::vector<double>& t, const std::vector<double>& y, double start,
                                      double period, int count) {
  if (t.size() != y.size()) throw std::invalid_argument("crests_per_period: t and y differ in length");
  if (!(period > 0.0) || count < 0) throw std::invalid_argument("crests_per_period: period <= 0 or count < 0");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> crest(static_cast<std::size_t>(count), nan);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double k = std::floor((t[i] - start) / period);
    if (k < 0 || k >= count) continue;
    double& c = crest[static_cast<std::size_t>(k)];
    if (std::isnan(c) || y[i] > c) c = y[i];
  }
  return crest;
}

EnvelopeComparison compare_crest_envelopes(const std::vector<double>& t_reference,
                                           const std::vector<double>& y_reference,
                                           const std::vector<double>& t_simulated,
                                           const std::vector<double>& y_simulated, double start, double period,
                                           int count) {
  EnvelopeComparison c;
  c.reference = crests_per_period(t_reference, y_reference, start, period, count);
  c.simulated = crests_per_period(t_simulated, y_simulated, start, period, count);
  double largest = 0.0;
  for (double r : c.reference)
    if (!std::isnan(r)) largest = std::max(largest, std::abs(r));
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
