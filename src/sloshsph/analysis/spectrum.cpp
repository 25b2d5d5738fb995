#include "sloshsph/analysis/spectrum.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace sloshsph {
namespace {

// FFTW's planner is not thread-safe (FFTW manual, "Thread safety"): plans are made and destroyed
// under this lock; executing a plan on its own buffers is safe.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

// A real-to-complex transform of fixed size n with its own buffers.
class RealFft {
 public:
  explicit RealFft(std::size_t n) : n_(n) {
    in_ = fftw_alloc_real(n);
    out_ = fftw_alloc_complex(n / 2 + 1);
    if (!in_ || !out_) throw std::bad_alloc();
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan_ = fftw_plan_dft_r2c_1d(static_cast<int>(n), in_, out_, FFTW_ESTIMATE);
  }
  ~RealFft() {
    {
      std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      fftw_destroy_plan(plan_);
    }
    fftw_free(in_);
    fftw_free(out_);
  }
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  double* input() { return in_; }
  void execute() { fftw_execute(plan_); }
  std::complex<double> bin(std::size_t k) const { return {out_[k][0], out_[k][1]}; }
  std::size_t size() const { return n_; }

 private:
  std::size_t n_;
  double* in_ = nullptr;
  fftw_complex* out_ = nullptr;
  fftw_plan plan_ = nullptr;
};

}  // namespace

Spectrum welch_psd(const std::vector<double>& x, double dt, std::size_t seg, double overlap) {
  if (seg < 4) throw std::invalid_argument("Welch PSD: segment length must be >= 4");
  if (x.size() < seg) throw std::invalid_argument("Welch PSD: the series is shorter than one segment");
  if (!(dt > 0.0)) throw std::invalid_argument("Welch PSD: dt must be > 0");
  if (!(overlap >= 0.0 && overlap < 1.0)) throw std::invalid_argument("Welch PSD: overlap must be in [0, 1)");
  const double fs = 1.0 / dt;
  const auto step = std::max<std::size_t>(1, seg - static_cast<std::size_t>(std::llround(overlap * seg)));
  const std::size_t segments = 1 + (x.size() - seg) / step;

  std::vector<double> window(seg);
  double window_power = 0.0;
  for (std::size_t n = 0; n < seg; ++n) {
    window[n] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(n) / static_cast<double>(seg)));
    window_power += window[n] * window[n];
  }
  const std::size_t bins = seg / 2 + 1;
  Spectrum s;
  s.df = fs / static_cast<double>(seg);
  s.f.resize(bins);
  s.value.assign(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k) s.f[k] = static_cast<double>(k) * s.df;

  RealFft fft(seg);
  for (std::size_t j = 0; j < segments; ++j) {
    const double* seg_x = x.data() + j * step;
    double mean = 0.0;
    for (std::size_t n = 0; n < seg; ++n) mean += seg_x[n];
    mean /= static_cast<double>(seg);
    for (std::size_t n = 0; n < seg; ++n) fft.input()[n] = (seg_x[n] - mean) * window[n];
    fft.execute();
    for (std::size_t k = 0; k < bins; ++k) s.value[k] += std::norm(fft.bin(k));
  }
  const double scale = 1.0 / (fs * window_power * static_cast<double>(segments));
  for (std::size_t k = 0; k < bins; ++k) {
    const bool unpaired = (k == 0) || (seg % 2 == 0 && k == seg / 2);  // DC and Nyquist have no mirror
    s.value[k] *= unpaired ? scale : 2.0 * scale;
  }
  return s;
}

double spectrum_integral(const Spectrum& s, double f_lo, double f_hi) {
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < s.f.size(); ++k) {
    if (s.f[k] >= f_lo && s.f[k + 1] <= f_hi) area += 0.5 * (s.value[k] + s.value[k + 1]) * (s.f[k + 1] - s.f[k]);
  }
  return area;
}

double dominant_frequency_fft(const std::vector<double>& x, double dt) {
  const std::size_t n = x.size();
  if (n < 8) throw std::invalid_argument("dominant frequency: needs at least 8 samples");
  RealFft fft(n);
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) fft.input()[i] = x[i] - mean;
  fft.execute();
  const std::size_t bins = n / 2 + 1;
  std::size_t k = 1;
  for (std::size_t j = 2; j < bins; ++j)
    if (std::norm(fft.bin(j)) > std::norm(fft.bin(k))) k = j;
  double delta = 0.0;
  if (k + 1 < bins) {
    const auto xm = fft.bin(k - 1), x0 = fft.bin(k), xp = fft.bin(k + 1);
    const auto denom = 2.0 * x0 - xm - xp;
    if (std::abs(denom) > 0.0) delta = -std::real((xp - xm) / denom);
  }
  return (static_cast<double>(k) + delta) / (static_cast<double>(n) * dt);
}

std::vector<double> mean_up_crossings(const std::vector<double>& t, const std::vector<double>& x) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> ups;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i] - mean, b = x[i + 1] - mean;
    if (a < 0.0 && b >= 0.0) ups.push_back(t[i] + (t[i + 1] - t[i]) * (-a) / (b - a));
  }
  return ups;
}

double zero_crossing_period(const std::vector<double>& t, const std::vector<double>& x) {
  if (t.size() != x.size() || t.size() < 2) throw std::invalid_argument("zero-crossing period: bad series");
  const std::vector<double> ups = mean_up_crossings(t, x);
  return ups.size() < 2 ? 0.0 : (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
}

}  // namespace sloshsph
