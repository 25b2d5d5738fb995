#pragma once
// Tuning a tank: the fill depth that gives a target first sloshing frequency (thesis
// 3.4.5.3: every tank tuned to omega_t = 4.43 rad/s with the same water mass m_w, by
// choosing the depth and the out-of-plane tank width B).
#include <optional>

#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/modal.hpp"

namespace sloshsph {

// The smallest fill depth (m above tank.y_bottom, at most the top of the lower wall) whose
// modal omega_1 (linear/modal.hpp) equals target_omega. omega_1(depth) need not be monotonic
// (it rises with depth in flat and circular tanks, falls in V-shaped ones), so the depths are
// scanned first, then the first bracket is refined (to 1e-9 of the wall height). Throws InputError
// (key target_omega) when no depth in the tank gives the target, with the reachable range.
double depth_for_omega(const TankGeometry& tank, double target_omega, double gravity,
                       const ModalOptions& options = {});

struct TunedTank {
  double depth = 0.0;               // m, fill depth above tank.y_bottom
  double omega = 0.0;               // rad/s, modal omega_1 at that depth
  double area = 0.0;                // m^2, still-water section area (per metre of width)
  std::optional<double> width;      // m, out-of-plane width B = m_w / (rho area) when a mass is given
  std::optional<double> water_mass; // kg, the given m_w
};

// depth_for_omega, plus the section area and, for a given water mass m_w (kg), the tank
// width B = m_w / (density * area) that holds it (thesis Table 3.6: B_tank).
TunedTank tune_for_omega(const TankGeometry& tank, double target_omega, double gravity,
                         std::optional<double> water_mass_kg, double density, const ModalOptions& options = {});

}  // namespace sloshsph
