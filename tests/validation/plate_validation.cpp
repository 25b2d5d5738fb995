// Elastic plates coupled with the fluid (run/plate_coupling.hpp, issue: Dincer 2019 plate).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph::testing {
namespace {

// cases/hydrostatic_plate.toml: a 1 m water column on a 2 m plate clamped at both ends (WCSPH,
// dp = 20 mm, 1 s of damped settling of fluid and plate together, then 0.5 s). Reference: the clamped-clamped beam under the uniform load of the water and
// of the plate's own weight, w = q L^4 / (384 E I) + q L^2 / (8 k G A) (Timoshenko's shear part,
// 1.1% here), q = rho g H + rho_s g t. Tolerance 5% (the bar) on the mean mid-span
// deflection over 0-0.5 s; the load on the plate within 2% of the weight carried.
TEST(Validation, HydrostaticPlateDeflectsAsTheClampedBeam) {
  const RunResult r = run_case_in_memory("hydrostatic_plate.toml", {});
  const double rho = 1000.0, g = 9.81, H = 1.0, L = 2.0, t = 0.06, E = 1.0e10, nu = 0.3, rho_s = 2700.0;
  const double EI = E * t * t * t / 12.0, kGA = 5.0 / 6.0 * E / (2.0 * (1.0 + nu)) * t;
  const double q_water = rho * g * H, q = q_water + rho_s * g * t;
  const double w_ref = q * std::pow(L, 4) / (384.0 * EI) + q * L * L / (8.0 * kGA);
  const double w = -r.mean("plate_mid_dy:floor", 0.0, 0.5);
  const double load = -r.mean("F_plate_y:floor", 0.01, 0.5);
  report("hydrostatic_plate_midspan_m", w);
  report("hydrostatic_plate_reference_m", w_ref);
  report("hydrostatic_plate_ratio", w / w_ref);
  // The formula with the water alone, q = rho g H, for comparison (the plate's own weight
  // is 16% of the water's here).
  report("hydrostatic_plate_ratio_water_only_formula", w / (q_water * std::pow(L, 4) / (384.0 * EI)));
  report("hydrostatic_plate_load_ratio", load / (q_water * L));
  check_relative("mean mid-span deflection, 0-0.5 s", w, w_ref, 0.05,
                 "clamped-clamped beam, q L^4/(384 EI) + q L^2/(8 kGA), q = water + plate weight", "m");
  check_relative("vertical load on the plate / weight of water above it", load / (q_water * L), 1.0, 0.02,
                 "hydrostatics: rho g H L");
  check_at_most("particles that crossed the plate", r.max("plate_crossings:floor"), 0.0, "none may pass");
  check_at_most("particles inside the plate", r.max("plate_inside:floor"), 0.0, "none may sit inside");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
}

// The plate under Dincer's pulse (dp = 1.8 mm, 0.5 s, about 420 s of a CI run) is in plate_long.cpp
// (ValidationLong.ElasticPlateUnderAPulseKeepsTheFluidOnItsSides): CI's 30 minutes could not hold it
// beside the unit tests under the sanitizers.

}  // namespace
}  // namespace sloshsph::testing
