#pragma once
// Deterministic Gaussian white noise and a reference SDOF integrator for the analysis tests.
// (test_analysis links only sloshsph_analysis, so it cannot use signals/random.hpp or
// structure/sdof.hpp; these few lines stand in for them.) std::mt19937_64's output sequence is
// fixed by the C++ standard; the normal deviates come from our own Box-Muller transform, not
// from std::normal_distribution (implementation-defined).
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace sloshsph::test {

inline std::vector<double> gaussian_noise(std::uint64_t seed, std::size_t n, double sigma) {
  std::mt19937_64 gen(seed);
  auto uniform = [&] { return static_cast<double>(gen() >> 11) * 0x1.0p-53; };
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; i += 2) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - uniform()));
    const double th = 2.0 * std::numbers::pi * uniform();
    x[i] = sigma * r * std::cos(th);
    if (i + 1 < n) x[i + 1] = sigma * r * std::sin(th);
  }
  return x;
}

// Displacement of M x'' + C x' + K x = F, from rest, F sampled every dt; Newmark average acceleration.
inline std::vector<double> sdof_displacement(double m, double c, double k, const std::vector<double>& force,
                                             double dt) {
  double x = 0, v = 0, a = force.front() / m;
  std::vector<double> out{x};
  const double m_eff = m + 0.5 * dt * c + 0.25 * dt * dt * k;
  for (std::size_t n = 1; n < force.size(); ++n) {
    const double xp = x + dt * v + 0.25 * dt * dt * a, vp = v + 0.5 * dt * a;
    a = (force[n] - c * vp - k * xp) / m_eff;
    x = xp + 0.25 * dt * dt * a;
    v = vp + 0.5 * dt * a;
    out.push_back(x);
  }
  return out;
}

}  // namespace sloshsph::test
