#pragma once
// A coupled case's tanks as the linear equivalent TMD of structure/equivalent_tmd.hpp: the first
// sloshing mode of the case's tank and fill (linear/modal.hpp) on the case's structure, before
// any simulation. `sloshsph modes` prints it for a case with [structure].
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

}  // namespace sloshsph
