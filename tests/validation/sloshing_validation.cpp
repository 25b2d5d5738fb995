// Sloshing in rectangular tanks, CI resolution: linear frequency and the Liu &
// Lin (2008) resonance case at dp = 10 mm, dt = 1 ms (25 and 15 particles
// across the depths; the cases' own dp = 5 mm runs are in sloshing_long.cpp, 8
// times the cost: 352 s and 305 s on one thread).
#include "sloshing_support.hpp"

namespace sloshsph {
namespace {

const std::vector<std::string> kCiResolution = {"particles.dp=0.01", "time.dt=0.001"};

TEST(Validation, LinearSloshingFrequency) { testing::check_linear_sloshing_frequency(kCiResolution, "dp = 10 mm"); }

TEST(Validation, LiuLin2008Resonance) { testing::check_liu_lin_resonance(kCiResolution, "dp = 10 mm"); }

}  // namespace
}  // namespace sloshsph
