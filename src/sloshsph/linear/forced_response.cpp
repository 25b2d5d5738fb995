#include "sloshsph/linear/forced_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sloshsph {
namespace {

// q and q' of every mode.
struct ModalState {
  std::vector<double> q, v;
};

// q'' of every mode under the base acceleration a and state (q, q') (the modal equations of the header).
std::vector<double> modal_accelerations(const LinearResponseInput& in, double a, const std::vector<double>& q,
                                        const std::vector<double>& v) {
  std::vector<double> acc(q.size());
  for (std::size_t n = 0; n < q.size(); ++n) {
    const double w = in.modes[n].omega;
    const double zeta = n < in.damping.size() ? in.damping[n] : 0.0;
    acc[n] = -in.modes[n].horizontal_forcing * a - 2.0 * zeta * w * v[n] - w * w * q[n];
  }
  if (in.modal_drag) in.modal_drag(v, acc);
  return acc;
}

// One classical Runge-Kutta step of the second-order system.
void rk4_step(const LinearResponseInput& in, double t, double h, ModalState& s) {
  const std::size_t m = s.q.size();
  auto shifted = [m](const std::vector<double>& x, const std::vector<double>& dx, double c) {
    std::vector<double> y(m);
    for (std::size_t n = 0; n < m; ++n) y[n] = x[n] + c * dx[n];
    return y;
  };
  const double a_mid = in.base_acceleration(t + h / 2);  // stages 2 and 3
  const std::vector<double> k1q = s.v, k1v = modal_accelerations(in, in.base_acceleration(t), s.q, s.v);
  const std::vector<double> q2 = shifted(s.q, k1q, h / 2), v2 = shifted(s.v, k1v, h / 2);
  const std::vector<double> k2v = modal_accelerations(in, a_mid, q2, v2);
  const std::vector<double> q3 = shifted(s.q, v2, h / 2), v3 = shifted(s.v, k2v, h / 2);
  const std::vector<double> k3v = modal_accelerations(in, a_mid, q3, v3);
  const std::vector<double> q4 = shifted(s.q, v3, h), v4 = shifted(s.v, k3v, h);
  const std::vector<double> k4v = modal_accelerations(in, in.base_acceleration(t + h), q4, v4);
  for (std::size_t n = 0; n < m; ++n) {
    s.q[n] += h / 6 * (k1q[n] + 2 * v2[n] + 2 * v3[n] + v4[n]);
    s.v[n] += h / 6 * (k1v[n] + 2 * k2v[n] + 2 * k3v[n] + k4v[n]);
  }
}

}  // namespace

double mode_elevation_at(const SloshingMode& mode, double x) {
  const std::vector<double>& xs = mode.surface_x;
  const std::vector<double>& ys = mode.surface_eta;
  if (xs.empty()) return 0.0;
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const std::size_t i = std::upper_bound(xs.begin(), xs.end(), x) - xs.begin();
  const double f = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + f * (ys[i] - ys[i - 1]);
}

LinearResponse linear_response_from_rest(const LinearResponseInput& in) {
  if (!(in.sample_interval > 0.0)) throw std::invalid_argument("linear_response_from_rest: sample_interval <= 0");
  if (!in.base_acceleration) throw std::invalid_argument("linear_response_from_rest: no base acceleration");
  double shortest_period = in.sample_interval * 200.0;
  for (const SloshingMode& m : in.modes)
    if (m.omega > 0.0) shortest_period = std::min(shortest_period, 2.0 * std::numbers::pi / m.omega);
  // Sub-steps per sample: the RK4 step at most 1/200 of the shortest period.
  const int substeps = std::max(1, static_cast<int>(std::ceil(200.0 * in.sample_interval / shortest_period)));
  const double h = in.sample_interval / substeps;

  std::vector<std::vector<double>> shape(in.gauge_x.size(), std::vector<double>(in.modes.size()));
  for (std::size_t g = 0; g < in.gauge_x.size(); ++g)
    for (std::size_t n = 0; n < in.modes.size(); ++n) shape[g][n] = mode_elevation_at(in.modes[n], in.gauge_x[g]);

  LinearResponse out;
  out.integration_step = h;
  out.elevation.resize(in.gauge_x.size());
  ModalState s{std::vector<double>(in.modes.size(), 0.0), std::vector<double>(in.modes.size(), 0.0)};
  const long samples = static_cast<long>(std::floor(in.end_time / in.sample_interval + 1e-9));
  for (long k = 0; k <= samples; ++k) {
    const double t = k * in.sample_interval;
    if (k > 0)
      for (int j = 0; j < substeps; ++j) rk4_step(in, t - in.sample_interval + j * h, h, s);
    out.time.push_back(t);
    for (std::size_t g = 0; g < in.gauge_x.size(); ++g) {
      double eta = 0.0;
      for (std::size_t n = 0; n < in.modes.size(); ++n) eta += s.q[n] * shape[g][n];
      out.elevation[g].push_back(eta);
    }
    const double a = in.base_acceleration(t);
    const std::vector<double> acc = modal_accelerations(in, a, s.q, s.v);
    double moment = 0.0;
    for (std::size_t n = 0; n < in.modes.size(); ++n) moment += acc[n] * in.modes[n].surface_moment;
    out.sloshing_force.push_back(in.density * moment);
    out.wall_force.push_back(in.density * (in.still_water_area * a + moment));
  }
  return out;
}

double rectangular_boundary_layer_damping(double length, double depth, double gravity, double viscosity, int n) {
  const double k = n * std::numbers::pi / length;
  const double kh = k * depth;
  const double omega = std::sqrt(gravity * k * std::tanh(kh));
  const double sh = std::sinh(kh);
  const double wetted = length / 2 + std::sinh(2 * kh) / (2 * k) - depth;  // bottom and both walls
  const double layers = std::sqrt(viscosity / (2 * omega)) * k * std::tanh(kh) * wetted / (length * sh * sh);
  const double bulk = 2 * viscosity * k * k / omega;
  return layers + bulk;
}

}  // namespace sloshsph
