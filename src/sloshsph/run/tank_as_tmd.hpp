#pragma once
// A coupled case's tanks as the linear equivalent TMD of structure/equivalent_tmd.hpp: the first
// sloshing mode of the case's tank and fill (linear/modal.hpp) on the case's structure, before
// any simulation. `sloshsph modes` prints it for a case with [structure].
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/structure/equivalent_tmd.hpp"

namespace sloshsph {

struct TankAsTmd {
  EquivalentTmd tmd;
  double liquid_mass = 0.0;          // kg, of all the tanks (rho x section area x width x tanks)
  double convective_fraction = 0.0;  // m_1 / m_w of mode 1
  double band_low = 0.0, band_high = 0.0;  // Hz, the band the area method integrates over
  bool band_from_load = false;  // the noise load's band; otherwise 0.01-10 f_n (white noise)
};

// An upright cylinder (3D) under the sway along x, or with along_y that of [structure.y]: its
// first mode (cylinder_first_sloshing_omega, cylinder_convective_mass_fraction) over the liquid
// of `structure.tanks` cylinders, rigid_mass kg each. Throws InputError as tank_as_tmd.
TankAsTmd cylinder_as_tmd(const CaseSpec& spec, bool along_y = false);

// Throws InputError (naming the case's `structure` key) if the case has no [structure] or its
// tanks do not act on it (tanks = 0). Screens, baffles and floors inside the tank are ignored:
// the mode is that of the open section (their effect is what zeta_t stands for).
TankAsTmd tank_as_tmd(const CaseSpec& spec);

// The estimate as JSON (`sloshsph modes --json`, summary.json): masses, mass and tuning ratios,
// the band, `responses` (one object per tank damping ratio) and `optimum`.
nlohmann::json equivalent_tmd_json(const TankAsTmd& t, const std::vector<EquivalentTmdResponse>& responses,
                                   const EquivalentTmdResponse& optimum);

// summary.json structure.equivalent_tmd of a coupled run: the estimate with its optimum, and the
// tank damping a linear TMD of the same mass and tuning needs to give the run's measured zeta_eff
// (`tank_damping_for_measured_effective_damping`, null if none does). A tank the modal solver
// cannot take gives {"note": why} instead: the end of a long run must not fail here.
// In 3D (issue 31) the estimate of the sway along x, or with along_y that of [structure.y], from
// sway_section_case.
nlohmann::json equivalent_tmd_summary(const CaseSpec& spec, std::optional<double> measured_effective_damping,
                                      bool along_y = false);

// A 3D case's sway along x (or, with along_y, along y) as the 2D case tank_as_tmd takes: the
// section the liquid sloshes in along that direction (along x the case's section; along y a box's
// breadth as the length of a rectangle of the same depth), the tank's other extent as tank_width
// (rigid_mass, per tank in 3D, divided by it), and that direction's sway mode as [structure].
// Throws InputError for a cylinder, and along y for anything but a box.
CaseSpec sway_section_case(const CaseSpec& spec, bool along_y);

}  // namespace sloshsph
