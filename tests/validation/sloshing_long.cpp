// Sloshing in rectangular tanks at the cases' own resolution (label `long`): dp = 5 mm,
// dt = 0.5 ms, as the thesis runs them (2.6.1-2.6.2); about 6 min each on one thread.
#include "sloshing_support.hpp"

namespace sloshsph {
namespace {

TEST(ValidationLong, LinearSloshingFrequencyAtDp5mm) { testing::check_linear_sloshing_frequency({}, "dp = 5 mm"); }

TEST(ValidationLong, LiuLin2008ResonanceAtDp5mm) { testing::check_liu_lin_resonance({}, "dp = 5 mm"); }

}  // namespace
}  // namespace sloshsph
