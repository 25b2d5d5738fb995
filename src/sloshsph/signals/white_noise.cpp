#include "sloshsph/signals/white_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "sloshsph/signals/random.hpp"

namespace sloshsph {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Adds sum_j amplitude cos(w_j n dt + phi_j) to out[n] for a group of up to kGroup components, by
// rotating each phasor e^{i(w_j n dt + phi_j)}; the phasors are recomputed exactly every 256
// samples so rounding cannot accumulate. Several independent phasors per pass keep the CPU busy
// (one rotation alone is a chain of dependent multiplications).
constexpr std::size_t kGroup = 8;

void add_components(std::vector<double>& out, double amplitude, const double* w, const double* phi,
                    std::size_t count, double dt) {
  double cr[kGroup], sr[kGroup], c[kGroup], s[kGroup];
  for (std::size_t j = 0; j < kGroup; ++j) {
    cr[j] = j < count ? std::cos(w[j] * dt) : 1.0;
    sr[j] = j < count ? std::sin(w[j] * dt) : 0.0;
    c[j] = s[j] = 0.0;
  }
  for (std::size_t start = 0; start < out.size(); start += 256) {
    for (std::size_t j = 0; j < count; ++j) {
      const double angle = w[j] * static_cast<double>(start) * dt + phi[j];
      c[j] = std::cos(angle);
      s[j] = std::sin(angle);
    }
    const std::size_t stop = std::min(out.size(), start + 256);
    for (std::size_t n = start; n < stop; ++n) {
      double sum = 0.0;
      for (std::size_t j = 0; j < kGroup; ++j) {  // unused slots hold c = s = 0
        sum += c[j];
        const double c_next = c[j] * cr[j] - s[j] * sr[j];
        s[j] = s[j] * cr[j] + c[j] * sr[j];
        c[j] = c_next;
      }
      out[n] += amplitude * sum;
    }
  }
}

double acceleration_gain_squared(double m, double c, double k, double f) {
  const double w = kTwoPi * f;
  const double re = k - m * w * w, im = c * w;
  return w * w * w * w / (re * re + im * im);
}

}  // namespace

BandLimitedNoise band_limited_white_noise(const BandLimitedNoiseSpec& spec) {
  if (!(spec.duration > 0.0) || !(spec.dt > 0.0)) throw std::invalid_argument("white noise: duration and dt must be > 0");
  if (!(spec.f_lo >= 0.0) || !(spec.f_hi > spec.f_lo)) throw std::invalid_argument("white noise: need 0 <= f_lo < f_hi");
  if (!(spec.f_hi < 0.5 / spec.dt)) throw std::invalid_argument("white noise: f_hi must be below the Nyquist frequency 1/(2 dt)");
  if (!(spec.rms >= 0.0) || !(spec.psd_level >= 0.0))
    throw std::invalid_argument("white noise: rms and psd_level must be >= 0");
  const double df = 1.0 / spec.duration;
  const auto k_lo = static_cast<long long>(std::max(1.0, std::ceil(spec.f_lo / df - 1e-9)));
  const auto k_hi = static_cast<long long>(std::floor(spec.f_hi / df + 1e-9));
  if (k_hi < k_lo) throw std::invalid_argument("white noise: the band holds no harmonic of 1/duration (duration too short)");
  // Bounds before anything is allocated: a band reaching down to a tiny f_lo asks for a signal
  // of duration 1/f_lo, a wide band for many components (the work is samples x components).
  const double samples = std::ceil(spec.duration / spec.dt - 1e-9) + 1.0;
  const double components = static_cast<double>(k_hi - k_lo + 1);
  char why[240];
  if (samples > kMaxNoiseSamples) {
    std::snprintf(why, sizeof why,
                  "white noise: %.3g samples needed (duration %.3g s at dt %.3g s: at least 1/f_low), more than the "
                  "limit of %.3g; raise the low end of the band or shorten the run",
                  samples, spec.duration, spec.dt, kMaxNoiseSamples);
    throw std::invalid_argument(why);
  }
  if (samples * components > kMaxNoiseWork) {
    std::snprintf(why, sizeof why,
                  "white noise: %.3g components over %.3g samples is more than %.3g sample-components of work; "
                  "narrow the band or shorten the run",
                  components, samples, kMaxNoiseWork);
    throw std::invalid_argument(why);
  }
  const auto n_comp = static_cast<std::size_t>(components);
  const auto n_samples = static_cast<std::size_t>(samples);

  // The variance is S0 times the band actually covered, N df.
  const double rms = spec.psd_level > 0.0 ? std::sqrt(spec.psd_level * static_cast<double>(n_comp) * df) : spec.rms;
  std::vector<double> values(n_samples, 0.0);
  const double amplitude = rms * std::sqrt(2.0 / static_cast<double>(n_comp));
  Xoshiro256ss rng(spec.seed);
  // Phases are drawn in order of increasing frequency, one uniform each: the signal depends only
  // on the seed and the spec.
  for (long long k0 = k_lo; k0 <= k_hi; k0 += static_cast<long long>(kGroup)) {
    double w[kGroup], phi[kGroup];
    std::size_t count = 0;
    for (long long k = k0; k <= k_hi && count < kGroup; ++k, ++count) {
      w[count] = kTwoPi * static_cast<double>(k) * df;
      phi[count] = kTwoPi * rng.uniform01();
    }
    add_components(values, amplitude, w, phi, count, spec.dt);
  }
  BandLimitedNoise noise;
  noise.series = uniform_series(spec.dt, std::move(values));
  noise.components = n_comp;
  noise.f_lo = static_cast<double>(k_lo) * df;
  noise.f_hi = static_cast<double>(k_hi) * df;
  noise.psd_level = rms * rms / (static_cast<double>(n_comp) * df);
  return noise;
}

SdofRandomResponse sdof_random_acceleration(double m, double c, double k, double psd_level, double f_lo, double f_hi) {
  if (!(m > 0.0) || !(k > 0.0) || !(c > 0.0)) throw std::invalid_argument("SDOF random response: need M, C, K > 0");
  if (!(f_hi > f_lo) || f_lo < 0.0) throw std::invalid_argument("SDOF random response: need 0 <= f_lo < f_hi");
  const double f_n = std::sqrt(k / m) / kTwoPi;
  const double zeta = c / (2.0 * std::sqrt(k * m));
  // Resolve the resonance peak: its half-power bandwidth is 2 zeta f_n.
  const double h_target = std::min((f_hi - f_lo) / 4000.0, 2.0 * zeta * f_n / 40.0);
  auto n = static_cast<std::size_t>(std::ceil((f_hi - f_lo) / h_target));
  n += n % 2;  // Simpson needs an even count
  const double h = (f_hi - f_lo) / static_cast<double>(n);
  double m0 = 0.0, m2 = 0.0;
  for (std::size_t i = 0; i <= n; ++i) {
    const double f = f_lo + static_cast<double>(i) * h;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double s = psd_level * acceleration_gain_squared(m, c, k, f);
    m0 += w * s;
    m2 += w * f * f * s;
  }
  m0 *= h / 3.0;
  m2 *= h / 3.0;
  SdofRandomResponse r;
  r.sigma_acceleration = std::sqrt(m0);
  r.upcrossing_rate = m0 > 0.0 ? std::sqrt(m2 / m0) : 0.0;
  return r;
}

double davenport_peak_factor(double nu, double duration) {
  const double nt = nu * duration;
  if (!(nt > 1.0)) throw std::invalid_argument("peak factor: needs nu T > 1");
  const double root = std::sqrt(2.0 * std::log(nt));
  return root + 0.5772 / root;  // Davenport (1964)
}

NoiseScaling scale_noise_to_mean_peak(double m, double c, double k, double psd_level, double f_lo, double f_hi,
                                      double target_milli_g, double duration, double upcrossing_rate) {
  if (!(psd_level > 0.0)) throw std::invalid_argument("noise scaling: the force PSD level must be > 0");
  if (!(target_milli_g > 0.0)) throw std::invalid_argument("noise scaling: the target peak must be > 0");
  const SdofRandomResponse unit = sdof_random_acceleration(m, c, k, psd_level, f_lo, f_hi);
  NoiseScaling s;
  s.upcrossing_rate = upcrossing_rate > 0.0 ? upcrossing_rate : unit.upcrossing_rate;
  s.peak_factor = davenport_peak_factor(s.upcrossing_rate, duration);
  s.mean_peak = target_milli_g * 1e-3 * kStandardGravity;
  s.force_scale = s.mean_peak / (s.peak_factor * unit.sigma_acceleration);
  s.psd_level = s.force_scale * s.force_scale * psd_level;
  s.sigma_acceleration = s.force_scale * unit.sigma_acceleration;
  return s;
}

}  // namespace sloshsph
