#include "sloshsph/signals/time_series.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sloshsph {

TimeSeries uniform_series(double dt, std::vector<double> values, double t0) {
  if (!(dt > 0.0)) throw std::invalid_argument("uniform_series: dt must be > 0");
  TimeSeries s;
  s.t.resize(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) s.t[i] = t0 + static_cast<double>(i) * dt;
  s.value = std::move(values);
  return s;
}

double sample(const TimeSeries& series, double t) {
  const auto& ts = series.t;
  if (ts.size() < 2) throw std::invalid_argument("sample: a series needs at least 2 samples");
  if (t < ts.front() || t > ts.back()) return 0.0;
  // First sample strictly after t; the interval is [i-1, i].
  std::size_t i = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  if (i >= ts.size()) return series.value.back();  // t == end
  const double w = (t - ts[i - 1]) / (ts[i] - ts[i - 1]);
  return (1.0 - w) * series.value[i - 1] + w * series.value[i];
}

void check_time_series(const TimeSeries& series, const std::string& what) {
  if (series.t.size() != series.value.size())
    throw std::invalid_argument(what + ": time and value arrays differ in length");
  if (series.t.size() < 2) throw std::invalid_argument(what + ": needs at least 2 samples");
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (!std::isfinite(series.t[i]) || !std::isfinite(series.value[i]))
      throw std::invalid_argument(what + ": non-finite sample at index " + std::to_string(i));
    if (i > 0 && !(series.t[i] > series.t[i - 1]))
      throw std::invalid_argument(what + ": times not strictly increasing at index " + std::to_string(i));
  }
}

}  // namespace sloshsph
