// The free-decay fit (analysis/free_decay): a damped cosine with an offset gives back its ratio
// and damped frequency.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "sloshsph/analysis/free_decay.hpp"

namespace sloshsph {
namespace {

TEST(FreeDecay, DampedCosineWithAnOffset) {
  const double omega = 7.5, zeta = 0.005, offset = -0.002;
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  std::vector<double> t, y;
  for (int k = 0; k * 0.005 < 10.0; ++k) {
    t.push_back(k * 0.005);
    y.push_back(offset + 0.01 * std::exp(-zeta * omega * t.back()) * std::cos(wd * t.back()));
  }
  const FreeDecayFit fit = fit_free_decay(t, y);
  // Sampling at 1/168 of a period puts each crest within 2e-4 of its height; the removed mean of
  // a decaying signal is not exactly the offset: 2% of zeta, 0.1% of omega.
  EXPECT_NEAR(fit.zeta, zeta, 0.02 * zeta);
  EXPECT_NEAR(fit.omega, wd, 1e-3 * wd);
  EXPECT_GE(fit.cycles, 10);
  EXPECT_NEAR(fit.first_height, 0.02, 0.001);
}

TEST(FreeDecay, RefusesTooFewCycles) {
  std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4}, y{0.0, 1.0, 0.0, -1.0, 0.0};
  EXPECT_THROW(fit_free_decay(t, y), std::invalid_argument);
}

}  // namespace
}  // namespace sloshsph
