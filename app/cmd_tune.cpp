// sloshsph tune CASE --target-omega W [--mass KG] [--set KEY=VALUE]...
// The fill depth that gives the tank a target first sloshing frequency (thesis 3.4.5.3);
// with a water mass, also the out-of-plane tank width that holds it.
#include <cstdio>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/tuning.hpp"

namespace sloshsph::app {

Command add_tune_command(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::vector<std::string> sets;
    double target = 0.0;
    double mass = 0.0;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("tune", "Find the fill depth that tunes a tank to a target frequency");
  sub->add_option("case", o->case_path, "Case file (TOML): the tank section is taken from it")->required();
  sub->add_option("--target-omega", o->target, "Target first sloshing frequency (rad/s)")
      ->required()
      ->check(CLI::PositiveNumber);
  sub->add_option("--mass", o->mass, "Water mass of one tank (kg): also report the tank width B")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--json", o->json, "Print the result as JSON");
  add_set_option(sub, o->sets);
  return {sub, [o]() {
            const CaseSpec spec = load_case(o->case_path, o->sets);
            const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
            std::optional<double> mass;
            if (o->mass > 0.0) mass = o->mass;
            const TunedTank t = tune_for_omega(tank, o->target, spec.fluid.gravity, mass, spec.fluid.density);
            if (o->json) {
              std::printf("{\"target_omega\": %.10g, \"depth\": %.10g, \"omega\": %.10g, \"area\": %.10g", o->target,
                          t.depth, t.omega, t.area);
              if (t.width) std::printf(", \"mass\": %.10g, \"width\": %.10g", *t.water_mass, *t.width);
              std::printf("}\n");
              return 0;
            }
            std::printf("%s tank (%s): fill depth %.6f m gives omega1 = %.6f rad/s (target %.6f)\n",
                        spec.tank.shape.c_str(), spec.source.c_str(), t.depth, t.omega, o->target);
            std::printf("still-water section area %.6f m^2 per metre of width\n", t.area);
            if (t.width)
              std::printf("for %.6g kg of water the tank width is B = %.6f m\n", *t.water_mass, *t.width);
            return 0;
          }};
}

}  // namespace sloshsph::app
