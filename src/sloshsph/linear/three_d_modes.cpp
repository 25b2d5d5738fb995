#include "sloshsph/linear/three_d_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

// The first zeros j'_{m,n} of J_m' (m = 0..6, n = 1..3; Abramowitz & Stegun 1964, Table 9.5),
// the trivial zero of J_0' at 0 left out.
constexpr double kBesselDerivativeZeros[7][3] = {
    {3.8317, 7.0156, 10.1735}, {1.8412, 5.3314, 8.5363}, {3.0542, 6.7061, 9.9695}, {4.2012, 8.0152, 11.3459},
    {5.3176, 9.2824, 12.6819}, {6.4156, 10.5199, 13.9872}, {7.5013, 11.7349, 15.2682}};

double dispersion_omega(double k, double depth, double gravity) { return std::sqrt(gravity * k * std::tanh(k * depth)); }

}  // namespace

std::vector<ThreeDMode> three_d_modes(const CaseSpec& spec, int count) {
  const double h = spec.fill.depth, g = spec.fluid.gravity;
  std::vector<ThreeDMode> modes;
  if (spec.tank.shape == "cylinder") {
    for (int m = 0; m < 7; ++m)
      for (int n = 1; n <= 3; ++n)
        modes.push_back({m, n, dispersion_omega(kBesselDerivativeZeros[m][n - 1] / spec.tank.radius, h, g)});
  } else if (spec.tank.shape == "rectangle") {
    const double L = spec.tank.length, B = spec.tank.breadth;
    for (int m = 0; m <= count; ++m)
      for (int n = 0; n <= count; ++n)
        if (m + n > 0)
          modes.push_back({m, n, dispersion_omega(std::numbers::pi * std::hypot(m / L, n / B), h, g)});
  } else {
    throw InputError(spec.where("tank.shape"), "tank.shape",
                     "the 3D modes have a closed form for a box (\"rectangle\") and a \"cylinder\" only; the modes of "
                     "the section (along x) are those of the 2D tank");
  }
  std::stable_sort(modes.begin(), modes.end(), [](const ThreeDMode& a, const ThreeDMode& b) { return a.omega < b.omega; });
  if (static_cast<int>(modes.size()) > count) modes.resize(static_cast<std::size_t>(count));
  return modes;
}

}  // namespace sloshsph
