#include "sloshsph/analysis/filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sloshsph {
namespace {

// Transposed direct form II state of one section.
struct SectionState {
  double z1 = 0.0, z2 = 0.0;
};

double dc_gain(const Biquad& s) { return (s.b0 + s.b1 + s.b2) / (1.0 + s.a1 + s.a2); }

// Group delay at DC, in samples: D = sum k b_k / sum b_k - sum k a_k / sum a_k (a_0 = 1).
double dc_group_delay(const Biquad& s) {
  return (s.b1 + 2.0 * s.b2) / (s.b0 + s.b1 + s.b2) - (s.a1 + 2.0 * s.a2) / (1.0 + s.a1 + s.a2);
}

// The state in which the section has been fed the ramp x_n = x0 + slope n forever (n < 0): its
// output is then the exact steady ramp y_n = G (x0 + slope (n - D)) (G the DC gain, D the DC group
// delay: a ramp only probes H(1) and H'(1)). The transposed direct form II state at n = 0 is
//   z2 = b2 x_-1 - a2 y_-1,  z1 = b1 x_-1 - a1 y_-1 + b2 x_-2 - a2 y_-2.
// Starting here, a constant or a ramp passes without any start-up transient.
SectionState steady_state(const Biquad& s, double x0, double slope) {
  const double g = dc_gain(s), d = dc_group_delay(s);
  auto x = [&](double n) { return x0 + slope * n; };
  auto y = [&](double n) { return g * (x0 + slope * (n - d)); };
  SectionState st;
  st.z2 = s.b2 * x(-1) - s.a2 * y(-1);
  st.z1 = s.b1 * x(-1) - s.a1 * y(-1) + s.b2 * x(-2) - s.a2 * y(-2);
  return st;
}

// Filters x in place through the cascade. With `steady`, each section starts in the steady state
// of the straight line through x[0] with slope (x[m] - x[0]) / m (m a quarter cut-off period of
// samples, `slope_span`), otherwise at rest.
void run_cascade(const std::vector<Biquad>& sections, std::vector<double>& x, bool steady, std::size_t slope_span) {
  if (x.empty()) return;
  const std::size_t m = std::min(std::max<std::size_t>(slope_span, 1), x.size() - 1);
  double x0 = x.front();
  double slope = m > 0 ? (x[m] - x[0]) / static_cast<double>(m) : 0.0;
  for (const Biquad& s : sections) {
    SectionState st = steady ? steady_state(s, x0, slope) : SectionState{};
    // The next section sees this section's steady ramp.
    x0 = dc_gain(s) * (x0 - slope * dc_group_delay(s));
    slope *= dc_gain(s);
    for (double& v : x) {
      const double in = v;
      const double out = s.b0 * in + st.z1;
      st.z1 = s.b1 * in - s.a1 * out + st.z2;
      st.z2 = s.b2 * in - s.a2 * out;
      v = out;
    }
  }
}

}  // namespace

std::vector<Biquad> butterworth_lowpass(int order, double cutoff_hz, double fs) {
  if (order < 1) throw std::invalid_argument("Butterworth filter: order must be >= 1");
  if (!(fs > 0.0) || !(cutoff_hz > 0.0) || !(cutoff_hz < 0.5 * fs))
    throw std::invalid_argument("Butterworth filter: need 0 < cut-off < sample rate / 2");
  const double omega = std::tan(std::numbers::pi * cutoff_hz / fs);  // pre-warped analog cut-off
  const double o2 = omega * omega;
  std::vector<Biquad> sections;
  for (int k = 1; k <= order / 2; ++k) {
    const double zeta = std::sin(std::numbers::pi * (2.0 * k - 1.0) / (2.0 * order));
    const double a0 = 1.0 + 2.0 * zeta * omega + o2;
    Biquad s;
    s.b0 = o2 / a0;
    s.b1 = 2.0 * o2 / a0;
    s.b2 = o2 / a0;
    s.a1 = 2.0 * (o2 - 1.0) / a0;
    s.a2 = (1.0 - 2.0 * zeta * omega + o2) / a0;
    sections.push_back(s);
  }
  if (order % 2 == 1) {
    Biquad s;
    s.b0 = s.b1 = omega / (1.0 + omega);
    s.a1 = (omega - 1.0) / (1.0 + omega);
    sections.push_back(s);
  }
  return sections;
}

std::complex<double> frequency_response(const std::vector<Biquad>& sections, double f_hz, double fs) {
  const std::complex<double> zi = std::polar(1.0, -2.0 * std::numbers::pi * f_hz / fs);  // z^-1
  std::complex<double> h = 1.0;
  for (const Biquad& s : sections)
    h *= (s.b0 + s.b1 * zi + s.b2 * zi * zi) / (1.0 + s.a1 * zi + s.a2 * zi * zi);
  return h;
}

std::vector<double> filter_causal(const std::vector<Biquad>& sections, const std::vector<double>& x) {
  std::vector<double> y = x;
  run_cascade(sections, y, false, 0);
  return y;
}

std::vector<double> lowpass_zero_phase(const std::vector<double>& x, double dt, double cutoff_hz, int order) {
  if (x.size() < 2) throw std::invalid_argument("low-pass filter: needs at least 2 samples");
  if (!(dt > 0.0)) throw std::invalid_argument("low-pass filter: dt must be > 0");
  const double fs = 1.0 / dt;
  const auto sections = butterworth_lowpass(order, cutoff_hz, fs);
  const std::size_t n = x.size();
  const auto wanted = static_cast<std::size_t>(std::max(3.0 * (order + 1), std::ceil(3.0 * fs / cutoff_hz)));
  const std::size_t pad = std::min(wanted, n - 1);

  std::vector<double> ext;
  ext.reserve(n + 2 * pad);
  for (std::size_t j = pad; j >= 1; --j) ext.push_back(2.0 * x.front() - x[j]);
  ext.insert(ext.end(), x.begin(), x.end());
  for (std::size_t j = 1; j <= pad; ++j) ext.push_back(2.0 * x.back() - x[n - 1 - j]);

  const auto slope_span = static_cast<std::size_t>(std::llround(0.25 * fs / cutoff_hz));
  run_cascade(sections, ext, true, slope_span);
  std::reverse(ext.begin(), ext.end());
  run_cascade(sections, ext, true, slope_span);
  std::reverse(ext.begin(), ext.end());
  return std::vector<double>(ext.begin() + static_cast<std::ptrdiff_t>(pad),
                             ext.begin() + static_cast<std::ptrdiff_t>(pad + n));
}

std::vector<double> lowpass_if_resolved(const std::vector<double>& x, double dt, double cutoff_hz) {
  if (cutoff_hz <= 0.0 || x.size() < 2 || !(dt > 0.0) || cutoff_hz >= 0.5 / dt) return x;
  return lowpass_zero_phase(x, dt, cutoff_hz);
}

}  // namespace sloshsph
