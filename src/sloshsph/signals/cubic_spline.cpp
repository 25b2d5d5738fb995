#include "sloshsph/signals/cubic_spline.hpp"

#include <algorithm>
#include <stdexcept>

namespace sloshsph {
namespace {

// One row of the tridiagonal system for the interior moments M_1 .. M_n-2.
struct Row {
  double sub = 0.0, diag = 0.0, super = 0.0, rhs = 0.0;
};

// Thomas algorithm. The rows are diagonally dominant (also the two rows changed by the
// not-a-knot conditions, see interior_rows), so no pivoting is needed.
std::vector<double> solve_tridiagonal(std::vector<Row> rows) {
  const std::size_t m = rows.size();
  for (std::size_t k = 1; k < m; ++k) {
    const double f = rows[k].sub / rows[k - 1].diag;
    rows[k].diag -= f * rows[k - 1].super;
    rows[k].rhs -= f * rows[k - 1].rhs;
  }
  std::vector<double> x(m);
  x[m - 1] = rows[m - 1].rhs / rows[m - 1].diag;
  for (std::size_t k = m - 1; k-- > 0;) x[k] = (rows[k].rhs - rows[k].super * x[k + 1]) / rows[k].diag;
  return x;
}

// The continuity of s' at t_1 .. t_n-2, with M_0 and M_n-1 eliminated by not-a-knot:
//   M_0    = ((h_0 + h_1) M_1 - h_0 M_2) / h_1
//   M_n-1  = ((h_n-3 + h_n-2) M_n-2 - h_n-2 M_n-3) / h_n-3
// The first row becomes [2 (h0 + h1) + h0 (h0 + h1)/h1] M_1 + [h1 - h0^2/h1] M_2, whose diagonal
// (h0 + h1)(h0 + 2 h1)/h1 exceeds |h1^2 - h0^2|/h1 = |h1 - h0| (h0 + h1)/h1: still dominant.
std::vector<Row> interior_rows(const std::vector<double>& t, const std::vector<double>& y) {
  const std::size_t n = t.size();
  std::vector<Row> rows(n - 2);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    Row& r = rows[i - 1];
    r.sub = h0;
    r.diag = 2.0 * (h0 + h1);
    r.super = h1;
    r.rhs = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
  }
  const double h0 = t[1] - t[0], h1 = t[2] - t[1];
  rows.front().diag += h0 * (h0 + h1) / h1;
  rows.front().super -= h0 * h0 / h1;
  const double ha = t[n - 2] - t[n - 3], hb = t[n - 1] - t[n - 2];
  rows.back().diag += hb * (ha + hb) / ha;
  rows.back().sub -= hb * hb / ha;
  rows.front().sub = 0.0;
  rows.back().super = 0.0;
  return rows;
}

}  // namespace

CubicInterpolant not_a_knot_spline(const TimeSeries& samples) {
  check_time_series(samples, "cubic spline");
  const std::size_t n = samples.size();
  if (n < 4) throw std::invalid_argument("a not-a-knot cubic spline needs at least 4 samples, found " + std::to_string(n));
  CubicInterpolant s{samples.t, samples.value, std::vector<double>(n, 0.0)};
  const std::vector<double> inner = solve_tridiagonal(interior_rows(s.t, s.y));
  std::copy(inner.begin(), inner.end(), s.moment.begin() + 1);
  const double h0 = s.t[1] - s.t[0], h1 = s.t[2] - s.t[1];
  s.moment[0] = ((h0 + h1) * s.moment[1] - h0 * s.moment[2]) / h1;
  const double ha = s.t[n - 2] - s.t[n - 3], hb = s.t[n - 1] - s.t[n - 2];
  s.moment[n - 1] = ((ha + hb) * s.moment[n - 2] - hb * s.moment[n - 3]) / ha;
  return s;
}

SplineSample evaluate(const CubicInterpolant& s, double t) {
  // Interval [t_i, t_i+1] holding t (the first or the last one outside the knots).
  const std::size_t upper = static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin());
  const std::size_t i = std::clamp<std::size_t>(upper, 1, s.t.size() - 1) - 1;
  const double h = s.t[i + 1] - s.t[i];
  const double a = s.t[i + 1] - t, b = t - s.t[i];
  const double m0 = s.moment[i], m1 = s.moment[i + 1];
  SplineSample r;
  r.value = (m0 * a * a * a + m1 * b * b * b) / (6.0 * h) + (s.y[i] - m0 * h * h / 6.0) * a / h +
            (s.y[i + 1] - m1 * h * h / 6.0) * b / h;
  r.first = (m1 * b * b - m0 * a * a) / (2.0 * h) + (s.y[i + 1] - s.y[i]) / h - (m1 - m0) * h / 6.0;
  r.second = (m0 * a + m1 * b) / h;
  return r;
}

}  // namespace sloshsph
