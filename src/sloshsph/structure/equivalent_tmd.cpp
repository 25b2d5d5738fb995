#include "sloshsph/structure/equivalent_tmd.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace sloshsph {
namespace {

// Displacement of the structure per unit force, X / F, at angular frequency w.
std::complex<double> structure_receptance(const EquivalentTmd& tmd, double zeta_tank, double w) {
  using namespace std::complex_literals;
  const SdofSpec& s = tmd.structure;
  const double m1 = tmd.convective_mass;
  const double w1 = tmd.convective_omega;
  std::complex<double> dynamic_stiffness =
      -(s.mass + tmd.rigid_mass) * w * w + 1i * w * s.damping + s.stiffness;
  if (m1 > 0.0) {
    // The convective mass seen from the structure: (i w c1 + k1) (-m1 w^2) / (-m1 w^2 + i w c1 + k1).
    const std::complex<double> link = m1 * w1 * w1 + 1i * w * (2.0 * zeta_tank * m1 * w1);
    dynamic_stiffness += link * (-m1 * w * w) / (-m1 * w * w + link);
  }
  return 1.0 / dynamic_stiffness;
}

double bare_receptance_squared(const SdofSpec& s, double w) {
  const double re = s.stiffness - s.mass * w * w, im = w * s.damping;
  return 1.0 / (re * re + im * im);
}

}  // namespace

double equivalent_tmd_admittance(const EquivalentTmd& tmd, double zeta_tank, double frequency) {
  const double k = tmd.structure.stiffness;
  return std::norm(k * structure_receptance(tmd, zeta_tank, 2.0 * std::numbers::pi * frequency));
}

EquivalentTmdResponse equivalent_tmd_response(const EquivalentTmd& tmd, double zeta_tank, double f_lo, double f_hi) {
  if (!(f_hi > f_lo && f_lo >= 0.0)) throw std::invalid_argument("equivalent_tmd_response: bad band");
  const double f_n = tmd.structure.natural_frequency();
  // Simpson on an even number of intervals, 50 per half-width zeta f_n of the sharpest peak the
  // system can have (its modes are damped at least about as much as the less damped of the two).
  const double zeta_structure = tmd.structure.damping_ratio();
  const double zeta_min = std::max(1e-5, zeta_structure > 0.0 ? std::min(zeta_structure, zeta_tank) : zeta_tank);
  const double width = zeta_min * f_n / 50.0;
  const auto intervals = 2 * static_cast<long>(std::ceil(std::min((f_hi - f_lo) / width, 4e6) / 2.0));
  const double df = (f_hi - f_lo) / intervals;
  double displacement = 0.0, bare_displacement = 0.0, acceleration = 0.0, bare_acceleration = 0.0;
  for (long i = 0; i <= intervals; ++i) {
    const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double w = 2.0 * std::numbers::pi * (f_lo + i * df);
    const double h2 = std::norm(structure_receptance(tmd, zeta_tank, w));
    const double b2 = bare_receptance_squared(tmd.structure, w);
    displacement += weight * h2;
    bare_displacement += weight * b2;
    acceleration += weight * h2 * std::pow(w, 4);
    bare_acceleration += weight * b2 * std::pow(w, 4);
  }
  const double area = displacement * df / 3.0 * tmd.structure.stiffness * tmd.structure.stiffness;
  EquivalentTmdResponse r;
  r.zeta_tank = zeta_tank;
  r.effective_damping = std::numbers::pi * f_n / (4.0 * area);
  r.displacement_rms_ratio = std::sqrt(displacement / bare_displacement);
  r.acceleration_rms_ratio = std::sqrt(acceleration / bare_acceleration);
  return r;
}

EquivalentTmdResponse optimal_equivalent_tmd(const EquivalentTmd& tmd, double f_lo, double f_hi) {
  // Golden-section search for the maximum of zeta_eff over u = log(zeta_tank).
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = std::log(1e-4), b = std::log(1.0);
  auto damping = [&](double u) { return equivalent_tmd_response(tmd, std::exp(u), f_lo, f_hi).effective_damping; };
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = damping(c), fd = damping(d);
  while (b - a > 1e-3) {  // zeta_tank to 0.1%
    if (fc > fd) {
      b = d, d = c, fd = fc;
      c = b - ratio * (b - a), fc = damping(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + ratio * (b - a), fd = damping(d);
    }
  }
  return equivalent_tmd_response(tmd, std::exp(0.5 * (a + b)), f_lo, f_hi);
}

std::optional<double> tank_damping_for_effective_damping(const EquivalentTmd& tmd, double zeta_eff, double f_lo,
                                                         double f_hi) {
  const EquivalentTmdResponse best = optimal_equivalent_tmd(tmd, f_lo, f_hi);
  auto damping = [&](double u) { return equivalent_tmd_response(tmd, std::exp(u), f_lo, f_hi).effective_damping; };
  double lo = std::log(1e-4), hi = std::log(best.zeta_tank);
  if (!(zeta_eff >= damping(lo) && zeta_eff <= best.effective_damping)) return std::nullopt;
  while (hi - lo > 1e-3) {
    const double mid = 0.5 * (lo + hi);
    (damping(mid) < zeta_eff ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace sloshsph
