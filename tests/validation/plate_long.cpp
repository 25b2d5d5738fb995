// Long runs of the elastic plate cases at the paper's resolution (Dincer 2019, dp = 1.5 mm).
// Reference: the paper reports the maximum horizontal tip displacement, about 4 cm (cosine
// pulse), 3.5 cm (sine pulse) and 2 cm (El Centro). Its pulse period and amplitude, tank length
// and plate density are not in the extracted text (the cases say what was assumed), so those
// numbers are reported beside ours, not asserted. Asserted: no fluid particle passes through the
// plate (the contact step of run/plate_coupling enforces it; its count is reported), none leaves
// the tank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph::testing {
namespace {

void check_plate_run(const std::string& file, const std::vector<std::string>& overrides, const std::string& key,
                     double paper_tip) {
  const RunResult r = run_case_in_memory(file, overrides);
  const std::vector<double>& tip = r["plate_dx:plate"];
  double peak = 0.0;
  for (double x : tip) peak = std::max(peak, std::abs(x));
  const std::vector<double>& crossings = r["plate_crossings:plate"];
  report(key + "_max_tip_dx_m", peak);
  report(key + "_paper_max_tip_dx_m", paper_tip);
  report(key + "_crossings", crossings.back());
  report(key + "_max_inside", r.max("plate_inside:plate"));
  report(key + "_contacts", r["plate_contacts:plate"].back());
  report(key + "_wall_s", r.wall_seconds);
  check_at_most("particles that crossed the plate, end of the run", crossings.back(), 0.0, "none may pass");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
  record_curve({"tip", "Plate tip deflection, " + key, "time (s)", "tip dx (m)", r["time"], tip, "", {}, {}});
}

// cases/elastic_plate_pulse.toml (Dincer 2019, 3.1) for 0.5 s (in CI until 2026-12-02; moved here
// when CI began to run the unit tests under the sanitizers) (the pulse acts from 0.1 to 0.6 s;
// the plate swings back through the vertical near 0.35 s, where without the contact step fluid
// passed through it, and its tip nears its first peak at 0.5 s), at dp = 1.8 mm, the coarsest the
// 3 mm plate allows (thickness + dp >= 2h; 0.58 times the cost of the case's dp = 1.5 mm, 13,292
// fluid particles, which plate_long.cpp runs for the full 3 s): the plate must bend visibly (the
// paper: about 4 cm at the tip), no fluid particle may pass through it or sit inside it, none
// may leave the tank.
TEST(ValidationLong, ElasticPlateUnderAPulseKeepsTheFluidOnItsSides) {
  const RunResult r = run_case_in_memory("elastic_plate_pulse.toml", {"time.end=0.5", "particles.dp=0.0018"});
  const std::vector<double>& tip = r["plate_dx:plate"];
  double peak = 0.0;
  for (double x : tip) peak = std::max(peak, std::abs(x));
  report("pulse_plate_max_tip_dx_m", peak);
  report("pulse_plate_crossings", r.max("plate_crossings:plate"));
  report("pulse_plate_max_inside", r.max("plate_inside:plate"));
  report("pulse_plate_contacts", r.max("plate_contacts:plate"));
  // A 10 MPa plate under 0.3 g bends by centimetres, not by nothing, and not beyond its own height.
  check_between("peak tip deflection, 0-0.5 s", peak, 0.005, 0.08, "Dincer 2019, 3.1: about 4 cm", "m");
  check_at_most("particles that crossed the plate", r.max("plate_crossings:plate"), 0.0, "none may pass");
  check_at_most("particles inside the plate", r.max("plate_inside:plate"), 0.0, "none may sit inside");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
  record_curve({"tip", "Plate tip deflection under the cosine pulse", "time (s)", "tip dx (m)", r["time"], tip,
                "", {}, {}});
}

TEST(ValidationLong, ElasticPlateCosinePulse) {
  check_plate_run("elastic_plate_pulse.toml", {}, "plate_cosine_pulse", 0.04);
}

TEST(ValidationLong, ElasticPlateSinePulse) {
  check_plate_run("elastic_plate_pulse.toml", {"excitation.shape=\"sine\""}, "plate_sine_pulse", 0.035);
}

// The strong motion of the El Centro record (to 3.5 s; the peak ground acceleration is at 2.1 s)
// in 23 minutes on 2 threads instead of the full 12 s (issue 30, section 4): before the wall-contact
// step (docs/physics.md "Wall contact") 39 particles left through the tank's floor and end walls
// from 2.2 s on; with it none (2026-12-06: 4.3 million corrections, 0.21% of the particle-steps),
// and with `scheme.wall_contact = false` the same run loses them again (docs/validation/notes.md,
// "Elastic plates").
TEST(ValidationLong, ElasticPlateElCentroStrongMotion) {
  check_plate_run("elastic_plate_elcentro.toml", {"time.end=3.5", "output.snapshot_interval=0"},
                  "plate_elcentro_3_5s", 0.02);
}

// Issue 31: cases/hydrostatic_plate3d.toml, the hydrostatic plate of the CI test
// Validation.HydrostaticPlateDeflectsAsTheClampedBeam in a box 4 dp broad (20,000 fluid particles,
// WCSPH, 1 s of settling then 0.5 s). The plate spans the breadth and bends as the 2D beam per metre
// of breadth, so the references and tolerances are the 2D test's: the mean mid-span deflection
// within 5% of q L^4 / (384 E I) + q L^2 / (8 kGA), q = rho g H + rho_s g t; the whole vertical load
// within 2% of the weight of the water above the plate, rho g H L B (B = 4 dp); none through or
// inside the plate, none lost.
TEST(ValidationLong, HydrostaticPlateInThreeDimensionsDeflectsAsTheClampedBeam) {
  const RunResult r = run_file_in_memory<3>(case_path("hydrostatic_plate3d.toml"), {}, [](const Simulation3&) {});
  const double rho = 1000.0, g = 9.81, H = 1.0, L = 2.0, B = 0.08, t = 0.06, E = 1.0e10, nu = 0.3, rho_s = 2700.0;
  const double EI = E * t * t * t / 12.0, kGA = 5.0 / 6.0 * E / (2.0 * (1.0 + nu)) * t;
  const double q = rho * g * H + rho_s * g * t;
  const double w_ref = q * std::pow(L, 4) / (384.0 * EI) + q * L * L / (8.0 * kGA);
  const double w = -r.mean("plate_mid_dz:floor", 0.0, 0.5);
  const double load = -r.mean("F_plate_z:floor", 0.01, 0.5);
  report("hydrostatic_plate3d_midspan_m", w);
  report("hydrostatic_plate3d_ratio", w / w_ref);
  report("hydrostatic_plate3d_load_ratio", load / (rho * g * H * L * B));
  report("hydrostatic_plate3d_wall_s", r.wall_seconds);
  check_relative("mean mid-span deflection, 0-0.5 s, 3D slab", w, w_ref, 0.05,
                 "clamped-clamped beam, q L^4/(384 EI) + q L^2/(8 kGA), q = water + plate weight (as in 2D)", "m");
  check_relative("whole vertical load on the plate / weight of water above it, 3D slab", load / (rho * g * H * L * B), 1.0,
                 0.02, "hydrostatics: rho g H L B");
  check_at_most("particles that crossed the plate", r.max("plate_crossings:floor"), 0.0, "none may pass");
  check_at_most("particles inside the plate", r.max("plate_inside:floor"), 0.0, "none may sit inside");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
}

TEST(ValidationLong, ElasticPlateElCentro) {
  check_plate_run("elastic_plate_elcentro.toml", {}, "plate_elcentro", 0.02);
}

}  // namespace
}  // namespace sloshsph::testing
