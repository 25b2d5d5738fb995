#include "sloshsph/analysis/admittance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sloshsph {

Spectrum mechanical_admittance(const Spectrum& response, double force_psd_level, double stiffness) {
  if (!(force_psd_level > 0.0)) throw std::invalid_argument("admittance: the force PSD level must be > 0");
  Spectrum h = response;
  for (double& v : h.value) v *= stiffness * stiffness / force_psd_level;  // thesis eq. 4.30
  return h;
}

Spectrum mechanical_admittance(const Spectrum& response, const Spectrum& force, double stiffness, double floor) {
  if (response.f.size() != force.f.size() || std::abs(response.df - force.df) > 1e-12 * response.df)
    throw std::invalid_argument("admittance: response and force spectra are on different grids");
  const double fmax = *std::max_element(force.value.begin(), force.value.end());
  Spectrum h = response;
  for (std::size_t k = 0; k < h.value.size(); ++k)
    h.value[k] = force.value[k] > floor * fmax ? response.value[k] * stiffness * stiffness / force.value[k] : 0.0;
  return h;
}

double sdof_admittance(double f, double f_n, double zeta) {
  const double r = f / f_n;
  const double a = 1.0 - r * r, b = 2.0 * zeta * r;
  return 1.0 / (a * a + b * b);
}

double effective_damping_ratio(const Spectrum& admittance, double f_n, double f_lo, double f_hi) {
  const double area = spectrum_integral(admittance, f_lo, f_hi);
  if (!(area > 0.0)) throw std::invalid_argument("effective damping: the admittance has no area in the range");
  return std::numbers::pi * f_n / (4.0 * area);  // Vickery et al. (1983)
}

}  // namespace sloshsph
