#include "sloshsph/analysis/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sloshsph {
namespace {

void check_series(const std::vector<double>& t, const std::vector<double>& x, const char* what) {
  if (t.size() != x.size() || t.size() < 2) throw std::invalid_argument(std::string(what) + ": bad series");
}

// Number of whole cycles of `period` that fit in the record, capped at n_cycles.
int cycles_that_fit(const std::vector<double>& t, double period, int n_cycles, const char* what) {
  if (!(period > 0.0) || n_cycles < 1) throw std::invalid_argument(std::string(what) + ": need period > 0, cycles >= 1");
  const double span = t.back() - t.front();
  const int fit = static_cast<int>(std::floor(span / period * (1.0 + 1e-12)));
  if (fit < 1) throw std::invalid_argument(std::string(what) + ": the record is shorter than one period");
  return std::min(fit, n_cycles);
}

// The extreme value of the parabola through (t[i-1], x[i-1]), (t[i], x[i]), (t[i+1], x[i+1]).
double parabola_vertex_value(const std::vector<double>& t, const std::vector<double>& x, std::size_t i) {
  const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
  const double d0 = (x[i] - x[i - 1]) / h0, d1 = (x[i + 1] - x[i]) / h1;
  const double curvature = 2.0 * (d1 - d0) / (h0 + h1);  // second derivative of the parabola
  if (curvature == 0.0) return x[i];
  const double slope_at_i = (d0 * h1 + d1 * h0) / (h0 + h1);  // first derivative at t[i]
  return x[i] - 0.5 * slope_at_i * slope_at_i / curvature;
}

}  // namespace

SteadyAmplitude steady_state_amplitude(const std::vector<double>& t, const std::vector<double>& x, double period,
                                       int n_cycles) {
  check_series(t, x, "steady-state amplitude");
  const int cycles = cycles_that_fit(t, period, n_cycles, "steady-state amplitude");
  SteadyAmplitude r;
  r.cycles = cycles;
  const double t_end = t.back();
  for (int k = 1; k <= cycles; ++k) {
    const double lo = t_end - k * period, hi = t_end - (k - 1) * period;
    const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), lo) - t.begin());
    const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), hi) - t.begin());
    if (last <= first) throw std::invalid_argument("steady-state amplitude: a cycle holds no sample");
    std::size_t imax = first, imin = first;
    for (std::size_t i = first; i < last; ++i) {
      if (x[i] > x[imax]) imax = i;
      if (x[i] < x[imin]) imin = i;
    }
    // Refine only true local extrema (at a window edge on a slope the parabola would extrapolate).
    const bool max_local = imax > 0 && imax + 1 < t.size() && x[imax] >= x[imax - 1] && x[imax] >= x[imax + 1];
    const bool min_local = imin > 0 && imin + 1 < t.size() && x[imin] <= x[imin - 1] && x[imin] <= x[imin + 1];
    r.avg_max += max_local ? std::max(x[imax], parabola_vertex_value(t, x, imax)) : x[imax];
    r.avg_min += min_local ? std::min(x[imin], parabola_vertex_value(t, x, imin)) : x[imin];
  }
  r.avg_max /= cycles;
  r.avg_min /= cycles;
  return r;
}

CycleEnergy energy_per_cycle(const std::vector<double>& t, const std::vector<double>& force,
                             const std::vector<double>& displacement, double period, int n_cycles) {
  check_series(t, force, "energy per cycle");
  check_series(t, displacement, "energy per cycle");
  const int cycles = cycles_that_fit(t, period, n_cycles, "energy per cycle");
  const double t0 = t.back() - cycles * period;
  // First sample strictly after t0; the partial interval [t0, t[i]] is interpolated.
  auto i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t0) - t.begin());
  double f_prev = force[i], x_prev = displacement[i];
  if (i > 0) {
    const double w = (t0 - t[i - 1]) / (t[i] - t[i - 1]);
    f_prev = (1.0 - w) * force[i - 1] + w * force[i];
    x_prev = (1.0 - w) * displacement[i - 1] + w * displacement[i];
  }
  double work = 0.0;
  for (; i < t.size(); ++i) {
    work += 0.5 * (f_prev + force[i]) * (displacement[i] - x_prev);
    f_prev = force[i];
    x_prev = displacement[i];
  }
  return {work / cycles, cycles};
}

CycleEnergy energy_per_cycle_from_work(const std::vector<double>& t, const std::vector<double>& work, double period,
                                       int n_cycles) {
  check_series(t, work, "energy per cycle");
  const int cycles = cycles_that_fit(t, period, n_cycles, "energy per cycle");
  const double t0 = t.back() - cycles * period;
  const auto i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t0) - t.begin());
  double w0 = work[i];
  if (i > 0) {
    const double w = (t0 - t[i - 1]) / (t[i] - t[i - 1]);
    w0 = (1.0 - w) * work[i - 1] + w * work[i];
  }
  return {(work.back() - w0) / cycles, cycles};
}

double normalised_energy(double energy, double water_mass, double amplitude, double omega) {
  const double v = amplitude * omega;
  return energy / (0.5 * water_mass * v * v);  // thesis eq. 4.27
}

}  // namespace sloshsph
