// sloshsph modes CASE [--count N] [--json] [--set KEY=VALUE]...
// The first natural sloshing modes of the case's tank and fill (linear/modal.hpp).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/closed_form.hpp"
#include "sloshsph/linear/modal.hpp"

namespace sloshsph::app {

Command add_modes_command(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::vector<std::string> sets;
    int count = 4;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("modes", "Print the first linear sloshing modes of a case's tank");
  sub->add_option("case", o->case_path, "Case file (TOML)")->required();
  sub->add_option("--count", o->count, "Number of modes (default 4)")->check(CLI::Range(1, 50));
  sub->add_flag("--json", o->json, "Print {\"modes\": [{\"omega\": ..., \"frequency\": ...}, ...]} on stdout");
  add_set_option(sub, o->sets);
  return {sub, [o]() {
            const CaseSpec spec = load_case(o->case_path, o->sets);
            const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
            const auto modes = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, o->count);
            if (o->json) {
              nlohmann::json j;
              j["modes"] = nlohmann::json::array();
              for (const auto& m : modes) j["modes"].push_back({{"omega", m.omega}, {"frequency", m.frequency}});
              std::printf("%s\n", j.dump(2).c_str());
              return 0;
            }
            std::printf("%s: %s tank, depth %.6g m (linear potential theory, finite elements)\n", spec.source.c_str(),
                        spec.tank.shape.c_str(), spec.fill.depth);
            std::printf("%6s %14s %14s %12s\n", "mode", "omega [rad/s]", "frequency [Hz]", "period [s]");
            for (std::size_t k = 0; k < modes.size(); ++k)
              std::printf("%6zu %14.6f %14.6f %12.6f\n", k + 1, modes[k].omega, modes[k].frequency,
                          1.0 / modes[k].frequency);
            try {
              const double w = thesis_closed_form_omega(spec.tank, spec.fill.depth, spec.fluid.gravity);
              std::printf("thesis closed form (mode 1): %.6f rad/s (%+.2f%% from the modal value)\n", w,
                          100.0 * (w / modes[0].omega - 1.0));
            } catch (const InputError& e) {
              std::printf("thesis closed form (mode 1): not applicable (%s)\n", e.what());
            }
            return 0;
          }};
}

}  // namespace sloshsph::app
