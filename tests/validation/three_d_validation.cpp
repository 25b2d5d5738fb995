// The ISPH scheme in 3D (issue 31, section 5's first check): a box of water at rest holds its
// hydrostatic pressure, no particle leaves, the fluid stays at rest and the walls carry its weight.
// The scheme is the 2D one's code (BasicIsphScheme<3>), on a box built by geometry/prism_tank; no
// case file reads 3D yet, so the test sets the particles up itself.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "three_d_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_most;
using testing::check_relative;
using testing::report;

// A 0.3 m x 0.2 m box, 0.4 m high, with H = 0.2 m of water at dp = 20 mm (15 x 10 x 10 = 1,500
// fluid and 2,852 wall particles), the scheme's defaults (implicit PPE with the multigrid, the
// "air" free surface, SPS turbulence), dt = 2 ms, for 2 s from the hydrostatic start.
// References and tolerances, those of the 2D Validation.HydrostaticTank: the mean pressure of each
// layer of particles whose kernel stays below the free surface (z <= H - 2h: the 2D test's
// highest probe is 5 dp below its surface) within 2% of rho g H of rho g (H - z); no particle
// outside the box; the largest speed below 1% of sqrt(g H); the vertical force of the walls on the
// fluid equal to its weight within 0.5%. The layers nearer the surface are reported, not checked.
TEST(Validation, HydrostaticBoxInThreeDimensions) {
  const double rho = 1000.0, g = 9.81, H = 0.2, dp = 0.02, dt = 0.002, duration = 2.0;
  const CaseSpec spec = testing::box_case(0.3, 0.4, H, dp);
  const PrismTank tank{make_tank(spec.tank, "test"), 0.2};
  Particles3 p = testing::particles_at_rest(spec, tank);
  const std::vector<Vec3> started_at = p.position;  // where each particle started (by id: id = index here)
  ASSERT_EQ(p.n_fluid, 1500u);
  ASSERT_EQ(p.n_wall(), 2852u);

  IsphScheme3 scheme(spec, spec.particles.kernel_ratio * dp);
  IsphScheme3::Input in;
  in.dt = dt;
  in.frame.uniform = {0.0, 0.0, -g};
  const auto start = std::chrono::steady_clock::now();
  scheme.initialise(p, in.frame);
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int s = 0; s < steps; ++s) scheme.step(p, in);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The mean pressure of each layer of particles (by the lattice row each started in, found by its
  // id: the scheme reorders the fluid by cells; they move far less than dp).
  std::map<long, std::pair<double, int>> layers;
  std::size_t outside = 0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    auto& layer = layers[std::lround(started_at[static_cast<std::size_t>(p.id[i])].z / dp - 0.5)];
    layer.first += p.pressure[i];
    layer.second += 1;
    outside += tank.signed_distance(p.position[i]) > 0.0 ? 0 : 1;
  }
  const double scale = rho * g * H;
  double worst = 0.0;
  const double h = spec.particles.kernel_ratio * dp;
  for (const auto& [row, sum] : layers) {
    const double z = (row + 0.5) * dp, mean = sum.first / sum.second;
    if (z > H - 2.0 * h) {
      report("hydrostatic_3d_surface_layer_z" + std::to_string(z) + "_error_fraction_of_rho_g_H",
             (mean - rho * g * (H - z)) / scale);
      continue;
    }
    worst = std::max(worst, std::abs(mean - rho * g * (H - z)) / scale);
    check_absolute("mean pressure of the layer at z = " + std::to_string(z) + " m, at 2 s", mean, rho * g * (H - z),
                   0.02 * scale, "hydrostatics rho g (H - z), H = 0.2 m; tolerance 2% of rho g H", "Pa");
  }
  report("hydrostatic_3d_worst_layer_error_fraction_of_rho_g_H", worst);
  check_at_most("particles outside the box", static_cast<double>(outside), 0.0, "none may leave");
  const double max_speed = scheme.diagnostics().max_speed;
  report("hydrostatic_3d_max_speed_m_s", max_speed);
  check_at_most("largest fluid speed at 2 s", max_speed, 0.01 * std::sqrt(g * H), "1% of sqrt(g H), H = 0.2 m", "m/s");
  const double weight = p.mass * static_cast<double>(p.n_fluid) * g;
  report("hydrostatic_3d_vertical_wall_force_over_weight", scheme.diagnostics().wall_force.z / weight);
  check_relative("vertical force of the walls on the fluid, at 2 s", scheme.diagnostics().wall_force.z, weight, 0.005,
                 "the fluid's weight m g", "N");
  report("hydrostatic_3d_wall_seconds", seconds);
}

}  // namespace
}  // namespace sloshsph
