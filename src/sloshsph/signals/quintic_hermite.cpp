#include "sloshsph/signals/quintic_hermite.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sloshsph {

HermiteSamples hermite_samples(const CubicInterpolant& spline) {
  HermiteSamples h{spline.t, spline.y, {}, spline.moment};
  for (double t : spline.t) h.first.push_back(evaluate(spline, t).first);
  return h;
}

void check_hermite_samples(const HermiteSamples& s, const std::string& what) {
  const std::size_t n = s.t.size();
  if (s.value.size() != n || s.first.size() != n || s.second.size() != n)
    throw std::invalid_argument(what + ": times, values and derivatives differ in length");
  if (n < 2) throw std::invalid_argument(what + ": needs at least 2 samples");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.t[i]) || !std::isfinite(s.value[i]) || !std::isfinite(s.first[i]) ||
        !std::isfinite(s.second[i]))
      throw std::invalid_argument(what + ": non-finite sample at index " + std::to_string(i));
    if (i > 0 && !(s.t[i] > s.t[i - 1]))
      throw std::invalid_argument(what + ": times not strictly increasing at index " + std::to_string(i));
  }
}

SplineSample evaluate(const HermiteSamples& s, double t) {
  const std::size_t upper = static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin());
  const std::size_t i = std::clamp<std::size_t>(upper, 1, s.t.size() - 1) - 1;
  const double h = s.t[i + 1] - s.t[i];
  const double u = (t - s.t[i]) / h, u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u;
  // The six weights (end data scaled by h, h^2 as in the header) and their u-derivatives.
  const double c[6] = {s.value[i], h * s.first[i], h * h * s.second[i],
                       h * h * s.second[i + 1], h * s.first[i + 1], s.value[i + 1]};
  const double b[6] = {1.0 - 10.0 * u3 + 15.0 * u4 - 6.0 * u5, u - 6.0 * u3 + 8.0 * u4 - 3.0 * u5,
                       0.5 * (u2 - 3.0 * u3 + 3.0 * u4 - u5),   0.5 * (u3 - 2.0 * u4 + u5),
                       -4.0 * u3 + 7.0 * u4 - 3.0 * u5,         10.0 * u3 - 15.0 * u4 + 6.0 * u5};
  const double db[6] = {-30.0 * u2 + 60.0 * u3 - 30.0 * u4,    1.0 - 18.0 * u2 + 32.0 * u3 - 15.0 * u4,
                        0.5 * (2.0 * u - 9.0 * u2 + 12.0 * u3 - 5.0 * u4), 0.5 * (3.0 * u2 - 8.0 * u3 + 5.0 * u4),
                        -12.0 * u2 + 28.0 * u3 - 15.0 * u4,     30.0 * u2 - 60.0 * u3 + 30.0 * u4};
  const double ddb[6] = {-60.0 * u + 180.0 * u2 - 120.0 * u3,  -36.0 * u + 96.0 * u2 - 60.0 * u3,
                         0.5 * (2.0 - 18.0 * u + 36.0 * u2 - 20.0 * u3), 0.5 * (6.0 * u - 24.0 * u2 + 20.0 * u3),
                         -24.0 * u + 84.0 * u2 - 60.0 * u3,    60.0 * u - 180.0 * u2 + 120.0 * u3};
  SplineSample r;
  for (int k = 0; k < 6; ++k) {
    r.value += c[k] * b[k];
    r.first += c[k] * db[k];
    r.second += c[k] * ddb[k];
  }
  r.first /= h;
  r.second /= h * h;
  return r;
}

}  // namespace sloshsph
