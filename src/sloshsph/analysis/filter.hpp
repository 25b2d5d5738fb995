#pragma once
// Zero-phase low-pass filtering of uniformly sampled series. The thesis (sec. 2.6.3.1) low-pass
// filters the simulated series at 5 Hz, as the experimental data were, before comparing them.
#include <complex>
#include <vector>

namespace sloshsph {

// One second-order section H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2)
// (a first-order section has b2 = a2 = 0).
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;
  double a1 = 0.0, a2 = 0.0;
};

// Digital Butterworth low-pass of the given order as cascaded sections, by the bilinear transform
// with pre-warping (so the -3 dB point is exactly at `cutoff_hz`):
//   Omega = tan(pi fc / fs); analog poles of the normalised prototype s_k = exp(i pi (2k + n - 1) / (2n));
//   each conjugate pair -> Omega^2 / (s^2 + 2 zeta_k Omega s + Omega^2), zeta_k = sin(pi (2k - 1) / (2n)),
//   k = 1 .. n/2; odd n adds Omega / (s + Omega); then s = (1 - z^-1) / (1 + z^-1):
//   biquad: b = Omega^2 (1, 2, 1) / a0, a1 = 2 (Omega^2 - 1) / a0, a2 = (1 - 2 zeta_k Omega + Omega^2) / a0,
//           a0 = 1 + 2 zeta_k Omega + Omega^2;
//   first order: b = Omega (1, 1) / (1 + Omega), a1 = (Omega - 1) / (1 + Omega).
// Unit gain at DC. Throws std::invalid_argument unless order >= 1 and 0 < cutoff < fs / 2.
std::vector<Biquad> butterworth_lowpass(int order, double cutoff_hz, double sample_rate_hz);

// H(e^{i 2 pi f / fs}) of the cascade.
std::complex<double> frequency_response(const std::vector<Biquad>& sections, double f_hz, double sample_rate_hz);

// One causal pass (transposed direct form II), state starting at zero.
std::vector<double> filter_causal(const std::vector<Biquad>& sections, const std::vector<double>& x);

// Zero-phase (forward-backward) Butterworth low-pass, like the thesis' 5 Hz filtering: the series
// is filtered forward, then backward, so the phase cancels and the magnitude is squared
// (|H|^2: -6.02 dB at the cut-off, an effective order 2n). End effects: the series is extended
// at each end by an odd reflection about its end value (x[-j] = 2 x[0] - x[j]) over
// max(3 (order + 1), 3 fs / fc) samples (three cut-off periods, limited to n - 1), and each pass
// starts in the steady state of the straight line through its first value with the mean slope of
// its first quarter cut-off period (like scipy's filtfilt, which starts in the steady state of a
// constant, but matching the slope too): a constant or a ramp passes unchanged, and a smooth
// signal has only a curvature-driven start-up transient, which decays inside the padding.
// Needs >= 2 samples. Default: 4th order at 5 Hz (thesis sec. 2.6.3.1).
std::vector<double> lowpass_zero_phase(const std::vector<double>& x, double dt, double cutoff_hz = 5.0,
                                       int order = 4);

// lowpass_zero_phase at cutoff_hz, or x itself when the cut-off is off (<= 0), x has fewer than
// 2 samples, or the cut-off is not below the Nyquist frequency 0.5/dt (then filtering would
// change nothing the samples can show).
std::vector<double> lowpass_if_resolved(const std::vector<double>& x, double dt, double cutoff_hz);

}  // namespace sloshsph
