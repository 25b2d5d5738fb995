#include "sloshsph/analysis/free_decay.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sloshsph/analysis/spectrum.hpp"

namespace sloshsph {

FreeDecayFit fit_free_decay(const std::vector<double>& t, const std::vector<double>& y) {
  if (t.size() != y.size() || t.size() < 4) throw std::invalid_argument("fit_free_decay: too few samples");
  const std::vector<double> ups = mean_up_crossings(t, y);
  if (ups.size() < 4) throw std::invalid_argument("fit_free_decay: fewer than 3 full cycles");
  std::vector<double> heights;
  std::size_t i = 0;
  for (std::size_t c = 0; c + 1 < ups.size(); ++c) {
    double high = -INFINITY, low = INFINITY;
    while (i < t.size() && t[i] < ups[c]) ++i;
    for (std::size_t j = i; j < t.size() && t[j] < ups[c + 1]; ++j) high = std::max(high, y[j]), low = std::min(low, y[j]);
    heights.push_back(high - low);
  }
  const double n = static_cast<double>(heights.size());
  double km = 0.0, lm = 0.0;
  for (std::size_t k = 0; k < heights.size(); ++k) km += static_cast<double>(k) / n, lm += std::log(heights[k]) / n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const double dk = static_cast<double>(k) - km;
    sxy += dk * (std::log(heights[k]) - lm);
    sxx += dk * dk;
  }
  const double delta = -sxy / sxx;
  FreeDecayFit fit;
  fit.zeta = delta / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + delta * delta);
  fit.omega = 2.0 * std::numbers::pi * static_cast<double>(ups.size() - 1) / (ups.back() - ups.front());
  fit.cycles = static_cast<int>(heights.size());
  fit.first_height = heights.front();
  return fit;
}

}  // namespace sloshsph
