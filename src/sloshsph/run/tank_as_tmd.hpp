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
nlohmann::json equivalent_tmd_summary(const CaseSpec& spec, std::optional<double> measured_effective_damping);

}  // namespace sloshsph
