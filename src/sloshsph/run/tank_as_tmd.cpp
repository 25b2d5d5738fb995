#include "sloshsph/run/tank_as_tmd.hpp"

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/modal.hpp"
#include "sloshsph/run/structure_coupling.hpp"

namespace sloshsph {

TankAsTmd tank_as_tmd(const CaseSpec& spec) {
  if (!spec.structure) throw InputError(spec.source, "structure", "the case has no [structure] to put a TMD on");
  const StructureSpec& s = *spec.structure;
  if (s.tanks < 1)
    throw InputError(spec.where("structure.tanks"), "structure.tanks",
                     "tanks = 0: the liquid does not act on the structure, so it has no equivalent TMD");
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  const SloshingMode mode = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, 1).front();
  const double width = s.tank_width * s.tanks;

  TankAsTmd t;
  t.liquid_mass = spec.fluid.density * still_water_area(tank, spec.fill.depth) * width;
  t.convective_fraction = mode.effective_mass_fraction;
  t.tmd.structure = sdof_spec(s);
  t.tmd.convective_mass = t.convective_fraction * t.liquid_mass;
  t.tmd.rigid_mass = (1.0 - t.convective_fraction) * t.liquid_mass + s.rigid_mass * width;
  t.tmd.convective_omega = mode.omega;
  t.band_from_load = s.load.type == StructureLoadType::noise;
  const double fn = t.tmd.structure.natural_frequency();
  t.band_low = t.band_from_load ? s.load.band_low : 0.01 * fn;
  t.band_high = t.band_from_load ? s.load.band_high : 10.0 * fn;
  return t;
}

}  // namespace sloshsph
