#include "sloshsph/linear/tuning.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

double depth_for_omega(const TankGeometry& tank, double target_omega, double gravity, const ModalOptions& options) {
  if (!(target_omega > 0.0) || !std::isfinite(target_omega))
    throw InputError("", "target_omega", "the target frequency must be a positive number");
  const double full = std::min(tank.wall.front().y, tank.wall.back().y) - tank.y_bottom;

  // Scan: geometric depths near the bottom (omega_1 changes fastest there), then uniform.
  std::vector<double> depths;
  for (int k = 8; k >= 1; --k) depths.push_back(full / 16.0 / std::pow(2.0, k));
  for (int k = 1; k <= 16; ++k) depths.push_back(full * k / 16.0);
  ModalOptions coarse = options;
  coarse.resolution = std::max(8, options.resolution / 2);
  auto omega_at = [&](double depth, const ModalOptions& o) { return first_sloshing_omega(tank, depth, gravity, o); };

  std::vector<double> omegas;
  for (double d : depths) omegas.push_back(omega_at(d, coarse));
  for (std::size_t k = 0; k + 1 < depths.size(); ++k) {
    if ((omegas[k] - target_omega) * (omegas[k + 1] - target_omega) > 0.0) continue;
    // Refine at full resolution: false position, with bisection whenever the false-position
    // point falls in the outer tenth of the bracket (guards against one-sided convergence).
    double a = depths[k], b = depths[k + 1];
    double fa = omega_at(a, options) - target_omega, fb = omega_at(b, options) - target_omega;
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    if (fa * fb > 0.0) continue;  // the coarse scan saw a crossing the fine one does not
    for (int it = 0; it < 100 && b - a > 1e-9 * full; ++it) {
      double c = a - fa * (b - a) / (fb - fa);
      if (!(c > a + 0.1 * (b - a) && c < b - 0.1 * (b - a))) c = 0.5 * (a + b);
      const double fc = omega_at(c, options) - target_omega;
      if (fc == 0.0 || std::abs(fc) < 1e-12 * target_omega) return c;
      if ((fc < 0.0) == (fa < 0.0)) {
        a = c, fa = fc;
      } else {
        b = c, fb = fc;
      }
    }
    return std::abs(fa) < std::abs(fb) ? a : b;
  }
  const auto [lo, hi] = std::minmax_element(omegas.begin(), omegas.end());
  std::ostringstream m;
  m << "no fill depth gives omega_1 = " << target_omega << " rad/s: between depths of " << depths.front() << " and "
    << full << " m this tank's omega_1 spans " << *lo << " to " << *hi << " rad/s";
  throw InputError("", "target_omega", m.str());
}

TunedTank tune_for_omega(const TankGeometry& tank, double target_omega, double gravity,
                         std::optional<double> water_mass_kg, double density, const ModalOptions& options) {
  if (water_mass_kg && !(*water_mass_kg > 0.0))
    throw InputError("", "water_mass", "the water mass must be positive");
  if (!(density > 0.0)) throw InputError("", "fluid.density", "the density must be positive");
  TunedTank t;
  t.depth = depth_for_omega(tank, target_omega, gravity, options);
  t.omega = first_sloshing_omega(tank, t.depth, gravity, options);
  t.area = section_area(tank, t.depth);
  if (water_mass_kg) {
    t.water_mass = water_mass_kg;
    t.width = *water_mass_kg / (density * t.area);  // m_w = rho B A
  }
  return t;
}

}  // namespace sloshsph
