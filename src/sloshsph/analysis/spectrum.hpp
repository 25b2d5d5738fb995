#pragma once
// Spectra of uniformly sampled series (FFTW3, double precision).
#include <cstddef>
#include <vector>

namespace sloshsph {

// A one-sided spectrum on a uniform frequency grid f_k = k df, k = 0 .. L/2.
struct Spectrum {
  std::vector<double> f;      // Hz
  std::vector<double> value;  // PSD: unit^2/Hz; admittance: dimensionless
  double df = 0.0;            // Hz
};

// Welch's averaged periodogram (Welch 1967): segments of `segment_length` samples overlapping by
// `overlap` (0.5 default), each with its mean removed and a periodic Hann window
// w_n = (1 - cos(2 pi n / L)) / 2, then
//   S_k = 2 |X_k|^2 / (fs sum w_n^2)  for 0 < k < L/2   (one-sided; S_0 and S_{L/2} not doubled)
// averaged over the segments. This "density" scaling makes sum_k S_k df equal to the
// (window-weighted) variance of the series: the integral of the PSD is the variance.
// Throws std::invalid_argument if the series is shorter than one segment or L < 4.
Spectrum welch_psd(const std::vector<double>& x, double dt, std::size_t segment_length, double overlap = 0.5);

// Integral of a spectrum over [f_lo, f_hi] (trapezoid on the grid points inside the range).
double spectrum_integral(const Spectrum& s, double f_lo, double f_hi);

// The dominant frequency: the largest bin of the FFT of the whole (mean-removed, not windowed)
// series, refined by Jacobsen's three-bin estimator
//   delta = -Re[(X_{k+1} - X_{k-1}) / (2 X_k - X_{k-1} - X_{k+1})],  f = (k + delta) / (n dt)
// (E. Jacobsen & P. Kootsookos, IEEE Signal Processing Magazine 24(3), 2007). Hz.
double dominant_frequency_fft(const std::vector<double>& x, double dt);

// The mean period between successive up-crossings of the mean (crossing times by linear
// interpolation): (t_last - t_first) / (crossings - 1). Times need not be uniform. Returns 0 if
// fewer than 2 up-crossings.
double zero_crossing_period(const std::vector<double>& t, const std::vector<double>& x);

// The times at which x crosses its mean upwards (x_i < mean <= x_{i+1}), by linear interpolation.
std::vector<double> mean_up_crossings(const std::vector<double>& t, const std::vector<double>& x);

}  // namespace sloshsph
