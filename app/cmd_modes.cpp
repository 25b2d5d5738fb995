// sloshsph modes CASE [--count N] [--json] [--tank-damping Z]... [--set KEY=VALUE]...
// The first natural sloshing modes of the case's tank and fill (linear/modal.hpp) and, for a case
// with [structure], the tanks as a linear equivalent TMD on it (run/tank_as_tmd.hpp).
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/linear/closed_form.hpp"
#include "sloshsph/linear/three_d_modes.hpp"
#include "sloshsph/run/modes_summary.hpp"

namespace sloshsph::app {
namespace {

void print_tmd(const TankAsTmd& t, const std::vector<EquivalentTmdResponse>& responses) {
  const SdofSpec& s = t.tmd.structure;
  std::printf("\nequivalent TMD (mode 1 as a mass on a spring, linear; structure/equivalent_tmd.hpp):\n");
  std::printf("  liquid %.6g t, of which mode 1 sloshes %.6g t (%.1f%%); mass ratio m_1 / M_s = %.4f%%\n",
              t.liquid_mass / 1e3, t.tmd.convective_mass / 1e3, 100.0 * t.convective_fraction,
              100.0 * t.tmd.convective_mass / s.mass);
  std::printf("  rigid with the structure: %.6g t; structure %.6g Hz, zeta %.3f%%; tuning f_1 / f_s = %.4f\n",
              t.tmd.rigid_mass / 1e3, s.natural_frequency(), 100.0 * s.damping_ratio(),
              t.tmd.convective_omega / s.angular_frequency());
  std::printf("  white-noise force over %.4g-%.4g Hz (%s); zeta_eff by the area method, as summary.json\n",
              t.band_low, t.band_high, t.band_from_load ? "the load's band" : "0.01-10 f_s: the load is not noise");
  std::printf("  %12s %12s %16s %16s\n", "tank zeta", "zeta_eff", "RMS x / alone", "RMS a / alone");
  for (std::size_t k = 0; k < responses.size(); ++k) {
    const EquivalentTmdResponse& r = responses[k];
    std::printf("  %11.3f%% %11.3f%% %16.4f %16.4f%s\n", 100.0 * r.zeta_tank, 100.0 * r.effective_damping,
                r.displacement_rms_ratio, r.acceleration_rms_ratio, k + 1 == responses.size() ? "  (optimum)" : "");
  }
}

// A 3D box or cylinder: its closed-form modes (linear/three_d_modes.hpp), labelled (m, n).
int print_three_d_modes(const CaseSpec& spec, int count, bool json) {
  const std::vector<ThreeDMode> modes = three_d_modes(spec, count);
  const bool cylinder = spec.tank.shape == "cylinder";
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const ThreeDMode& m : modes)
      list.push_back({{"m", m.m}, {"n", m.n}, {"omega", m.omega}, {"frequency", m.omega / (2.0 * M_PI)}});
    std::printf("%s\n", nlohmann::json{{"modes", list}}.dump(2).c_str());
    return 0;
  }
  std::printf("%s: 3D %s, depth %.6g m (linear potential theory, closed form; %s)\n", spec.source.c_str(),
              cylinder ? "upright cylinder" : "box", spec.fill.depth,
              cylinder ? "(m, n): m nodal diameters, n-th zero of J_m'" : "(m, n): half-waves along x and along y");
  std::printf("%8s %14s %14s %12s\n", "(m, n)", "omega [rad/s]", "frequency [Hz]", "period [s]");
  for (const ThreeDMode& m : modes) {
    const double f = m.omega / (2.0 * M_PI);
    std::printf("  (%d, %d) %14.6f %14.6f %12.6f\n", m.m, m.n, m.omega, f, 1.0 / f);
  }
  return 0;
}

}  // namespace

Command add_modes_command(CLI::App& app) {
  struct Options {
    std::string case_path;
    std::vector<std::string> sets;
    std::vector<double> tank_damping;
    double tank_frequency_scale = 1.0;
    int count = 4;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "modes", "Print the first linear sloshing modes of a case's tank (and, with [structure], its equivalent TMD)");
  sub->add_option("case", o->case_path, "Case file (TOML)")->required();
  sub->add_option("--count", o->count, "Number of modes (default 4)")->check(CLI::Range(1, 50));
  sub->add_option("--tank-damping", o->tank_damping,
                  "With [structure]: also estimate the effective damping at these tank damping ratios (e.g. 0.0275)")
      ->check(CLI::Range(1e-4, 1.0));
  sub->add_option("--tank-frequency-scale", o->tank_frequency_scale,
                  "With [structure]: multiply the TMD's frequency omega_1 by this (e.g. a measured free-decay "
                  "frequency over the linear one; default 1)")
      ->check(CLI::Range(0.5, 2.0));
  sub->add_flag("--json", o->json,
                "Print {\"modes\": [{\"omega\": ..., \"frequency\": ..., \"effective_mass_fraction\": ...}, ...], "
                "\"equivalent_tmd\": {...}} on stdout");
  add_set_option(sub, o->sets);
  return {sub, [o]() {
            const CaseSpec spec = load_case(o->case_path, o->sets);
            if (spec.tank.dimensions == 3) return print_three_d_modes(spec, o->count, o->json);
            const ModesSummary m = modes_summary(spec, o->count, o->tank_damping, o->tank_frequency_scale);
            if (o->json) {
              std::printf("%s\n", modes_json(m).dump(2).c_str());
              return 0;
            }
            const auto& modes = m.modes;
            std::printf("%s: %s tank, depth %.6g m (linear potential theory, finite elements)\n", spec.source.c_str(),
                        spec.tank.shape.c_str(), spec.fill.depth);
            std::printf("%6s %14s %14s %12s %10s\n", "mode", "omega [rad/s]", "frequency [Hz]", "period [s]",
                        "m_n / m_w");
            for (std::size_t k = 0; k < modes.size(); ++k)
              std::printf("%6zu %14.6f %14.6f %12.6f %10.4f\n", k + 1, modes[k].omega, modes[k].frequency,
                          1.0 / modes[k].frequency, modes[k].effective_mass_fraction);
            try {
              const double w = thesis_closed_form_omega(spec.tank, spec.fill.depth, spec.fluid.gravity);
              std::printf("thesis closed form (mode 1): %.6f rad/s (%+.2f%% from the modal value)\n", w,
                          100.0 * (w / modes[0].omega - 1.0));
            } catch (const InputError& e) {
              std::printf("thesis closed form (mode 1): not applicable (%s)\n", e.what());
            }
            if (m.tmd) {
              print_tmd(*m.tmd, m.responses);
              if (o->tank_frequency_scale != 1.0)
                std::printf("  (omega_1 of the TMD is the modal value x %.6g, --tank-frequency-scale)\n",
                            o->tank_frequency_scale);
            }
            return 0;
          }};
}

}  // namespace sloshsph::app
