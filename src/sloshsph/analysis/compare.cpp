#include "sloshsph/analysis/compare.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sloshsph {

NormalisedError normalised_error(const std::vector<double>& x_ref, const std::vector<double>& f_ref,
                                 const std::vector<double>& x_model, const std::vector<double>& f_model) {
  if (x_ref.size() != f_ref.size() || x_model.size() != f_model.size() || x_model.empty())
    throw std::invalid_argument("normalised error: abscissa and value arrays differ in length");
  for (std::size_t i = 1; i < x_model.size(); ++i)
    if (!(x_model[i] > x_model[i - 1]))
      throw std::invalid_argument("normalised error: model abscissae must be strictly increasing");
  NormalisedError r;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < x_ref.size(); ++i) {
    const double x = x_ref[i];
    if (x < x_model.front() || x > x_model.back()) {
      ++r.skipped;
      continue;
    }
    double f = f_model.back();
    if (x < x_model.back()) {
      const auto j = static_cast<std::size_t>(std::upper_bound(x_model.begin(), x_model.end(), x) - x_model.begin());
      const double w = (x - x_model[j - 1]) / (x_model[j] - x_model[j - 1]);
      f = (1.0 - w) * f_model[j - 1] + w * f_model[j];
    }
    num += (f - f_ref[i]) * (f - f_ref[i]);
    den += f_ref[i] * f_ref[i];
    ++r.points;
  }
  if (r.points == 0 || den == 0.0)
    throw std::invalid_argument("normalised error: no usable reference point (ranges do not overlap, or all zero)");
  r.epsilon = std::sqrt(num / den);
  return r;
}

}  // namespace sloshsph
