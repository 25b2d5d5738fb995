#pragma once
// Band-limited white noise for random excitation of the structure (thesis sec. 4.4.2.1: a one-hour
// random force with frequency content 0.05-0.5 Hz, scaled so that the structure without TLD has a
// mean hourly peak acceleration of 10 or 44 milli-g), and the scaling by peak-factor theory.
#include <cstdint>
#include <vector>

#include "sloshsph/signals/time_series.hpp"

namespace sloshsph {

// Limits of one generated noise signal (std::invalid_argument beyond them, before allocating):
// 5e7 samples (400 MB; 5.8 days at dt = 0.01 s) and 2e11 sample-components (minutes of work; a
// 10-hour run of the default 0.05-0.5 Hz band is 6e10).
inline constexpr double kMaxNoiseSamples = 5e7;
inline constexpr double kMaxNoiseWork = 2e11;

struct BandLimitedNoiseSpec {
  std::uint64_t seed = 1;
  double f_lo = 0.05;        // Hz, lowest frequency of the band (thesis 4.4.2.1)
  double f_hi = 0.5;         // Hz, highest frequency of the band
  double duration = 3600.0;  // s (thesis: one hour)
  double dt = 0.01;          // s, sample interval of the output (must resolve f_hi: dt < 1 / (2 f_hi))
  double rms = 1.0;          // RMS of the signal, in the unit of the signal (N for a force)
  double psd_level = 0.0;    // if > 0: the one-sided PSD level S0 (unit^2/Hz) instead of `rms`
};

// Sum of sinusoids with equal amplitudes and independent uniform random phases:
//   x(t) = sum_k a cos(2 pi f_k t + phi_k),  f_k = k df,  df = 1 / duration,  f_lo <= f_k <= f_hi,
//   a = rms sqrt(2 / N)  (N components)  =>  one-sided PSD S0 = rms^2 / (N df), flat on the band.
// The frequencies are harmonics of 1/duration, so over the whole record the components are
// orthogonal: the variance of the record is rms^2 and its periodogram is exactly flat (no
// random scatter of the spectrum, unlike filtered Gaussian noise); with ~N > 100 components the
// values are close to Gaussian (central limit theorem), as the peak-factor theory assumes.
// Deterministic on every machine: phases from Xoshiro256ss(seed), components evaluated with a
// rotation recurrence re-synchronised with std::cos/std::sin every 256 samples.
// Cost: N x samples (1 h, 0.05-0.5 Hz, dt = 0.01 s: 1621 x 360001, about a second).
struct BandLimitedNoise {
  TimeSeries series;        // t_n = n dt, n = 0 .. ceil(duration / dt)
  double psd_level = 0.0;   // S0, one-sided, unit^2/Hz, constant on [f_lo, f_hi], zero outside
  double f_lo = 0.0;        // Hz, the lowest component actually used
  double f_hi = 0.0;        // Hz, the highest component actually used
  std::size_t components = 0;
};

// Throws std::invalid_argument on a bad spec (empty band, dt not resolving f_hi, ...).
BandLimitedNoise band_limited_white_noise(const BandLimitedNoiseSpec& spec);

// Statistics of the ACCELERATION response x'' of an SDOF structure M x'' + C x' + K x = F(t) to a
// force with one-sided PSD S0 on [f_lo, f_hi] (zero outside), by random vibration theory:
//   |H_a(f)|^2 = w^4 / ((K - M w^2)^2 + (C w)^2),  w = 2 pi f
//   m_j = integral over [f_lo, f_hi] of f^j S0 |H_a(f)|^2 df   (composite Simpson, >= 40 intervals
//         per half-power bandwidth 2 zeta f_n and >= 4000 over the band)
//   sigma = sqrt(m_0),  nu = sqrt(m_2 / m_0)  (Rice's mean zero up-crossing rate, Hz)
struct SdofRandomResponse {
  double sigma_acceleration = 0.0;  // m/s^2
  double upcrossing_rate = 0.0;     // Hz (close to f_n for a lightly damped structure)
};
SdofRandomResponse sdof_random_acceleration(double mass, double damping, double stiffness, double psd_level,
                                            double f_lo, double f_hi);

// Davenport (1964) peak factor of a stationary Gaussian process observed for T seconds:
//   g = sqrt(2 ln(nu T)) + 0.5772 / sqrt(2 ln(nu T))   (0.5772: Euler's constant)
// so that the mean of the largest peak is g sigma. Requires nu T > 1.
double davenport_peak_factor(double upcrossing_rate, double duration);

// The force scale that gives the structure (without TLD) a target mean peak acceleration over
// `duration` (thesis 4.4.2.1: mean hourly peak, 10 and 44 milli-g; 1 milli-g = 1e-3 x 9.80665 m/s^2).
// The response is linear in the force, so scale = target / (g sigma_1), with sigma_1 the RMS
// acceleration for the unscaled force (PSD level psd_level) and g from davenport_peak_factor with
// nu from Rice's formula (or `upcrossing_rate` if > 0, e.g. the natural frequency, as often done).
struct NoiseScaling {
  double force_scale = 0.0;         // multiply the unscaled force by this
  double psd_level = 0.0;           // S0 of the scaled force = force_scale^2 x psd_level
  double sigma_acceleration = 0.0;  // m/s^2, RMS acceleration with the scaled force
  double peak_factor = 0.0;         // g
  double upcrossing_rate = 0.0;     // Hz, the nu used
  double mean_peak = 0.0;           // m/s^2 = g sigma (the target)
};
NoiseScaling scale_noise_to_mean_peak(double mass, double damping, double stiffness, double psd_level, double f_lo,
                                      double f_hi, double target_milli_g, double duration = 3600.0,
                                      double upcrossing_rate = 0.0);

}  // namespace sloshsph
