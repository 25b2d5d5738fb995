#pragma once
// A portable pseudo-random generator: the same seed gives the same numbers on every machine and
// standard library. (std::normal_distribution and std::uniform_real_distribution are
// implementation-defined, so they are not used anywhere in sloshsph.)
#include <cstdint>

namespace sloshsph {

// SplitMix64 (Steele, Lea & Flood 2014; public-domain reference by S. Vigna): advances `state`
// and returns the next output. Used to expand a 64-bit seed into the xoshiro state.
std::uint64_t splitmix64_next(std::uint64_t& state);

// xoshiro256** 1.0 (Blackman & Vigna 2018, "Scrambled linear pseudorandom number generators"),
// seeded by filling its four state words with four SplitMix64 outputs from `seed` (the seeding
// the authors recommend). Written from the published algorithm.
class Xoshiro256ss {
 public:
  explicit Xoshiro256ss(std::uint64_t seed);
  std::uint64_t next();
  // Uniform on [0, 1): the top 53 bits times 2^-53 (exact in double).
  double uniform01();
  // Standard normal by the Box-Muller transform (Box & Muller 1958), written here: pairs are
  // generated from two uniforms and the second value is kept for the next call.
  double standard_normal();

 private:
  std::uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace sloshsph
