#pragma once
// `sloshsph modes` as data: the first linear sloshing modes of a case's tank and fill
// (linear/modal.hpp) and, for a case whose [structure] carries the tanks, the tanks as a linear
// equivalent TMD at a spread of tank damping ratios (run/tank_as_tmd.hpp). The command prints it
// as a table or as JSON; the Python module returns the JSON as a dict.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/linear/modal.hpp"
#include "sloshsph/run/tank_as_tmd.hpp"

namespace sloshsph {

struct ModesSummary {
  std::vector<SloshingMode> modes;
  std::optional<TankAsTmd> tmd;                 // only for a case with [structure] and tanks >= 1
  std::vector<EquivalentTmdResponse> responses;  // one per tank damping ratio, the optimum last
  double frequency_scale = 1.0;                  // omega_1 of the TMD = modal omega_1 x this
};

// `count` modes; `tank_damping` ratios added to the fixed spread 0.5, 1, 2, 3, 5 and 10%.
// Throws InputError (key `structure`) when tank damping or a frequency scale other than 1 is
// asked of a case without tanks on a structure.
ModesSummary modes_summary(const CaseSpec& spec, int count, const std::vector<double>& tank_damping,
                           double frequency_scale);

// {"modes": [{"omega", "frequency", "effective_mass_fraction"}, ...], "equivalent_tmd": {...}}:
// what `sloshsph modes --json` prints.
nlohmann::json modes_json(const ModesSummary& m);

}  // namespace sloshsph
