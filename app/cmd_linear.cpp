// sloshsph linear CASE [--modes N] [--damping auto|none|boundary-layer|ZETA] [--screens drag|none]
//                      [--out FILE] [--compare RUN_DIR] [--periods N] [--set KEY=VALUE]...
//                      [--beta RATIOS [--response-out FILE]]
// The linear modal solution from rest of a case's tank under its horizontal base motion
// (run/linear_case.hpp), with the drag of its vertical screens in a rectangular tank, written as a
// time series with the SPH run's column names, and, with --compare, the amplitude envelope of an
// SPH run's gauges against it, period by period. With --beta: its steady-state response at each
// frequency ratio, in the columns of a sweep's frequency_response.csv.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>

#include "commands.hpp"
#include "sloshsph/analysis/envelope.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/run/linear_case.hpp"
#include "sloshsph/run/sweep.hpp"

namespace sloshsph::app {
namespace {

void print_modes(const CaseSpec& spec, const LinearCase& r) {
  std::printf("%s: linear modal solution from rest, %zu modes, damping: %s\n", spec.source.c_str(), r.modes.size(),
              r.damping_model.c_str());
  std::printf("%6s %14s %12s %12s %12s\n", "mode", "omega [rad/s]", "period [s]", "zeta [%]", "forcing");
  for (std::size_t n = 0; n < r.modes.size(); ++n)
    std::printf("%6zu %14.6f %12.6f %12.5f %12.5f\n", n + 1, r.modes[n].omega,
                2.0 * std::numbers::pi / r.modes[n].omega, 100.0 * r.damping[n], r.modes[n].horizontal_forcing);
  for (const LinearScreen& s : r.screens)
    std::printf("screen at x = %.4g m over z = %.4g to %.4g m: loss coefficient C_l = %.4g, Darcy term r = %.4g Pa s/m\n",
                s.x, s.z_from, s.z_to, s.loss_coefficient, s.linear_resistance);
  for (const std::string& part : r.ignored)
    std::printf("note: not part of the linear model: %s\n", part.c_str());
}

int frequency_response(const std::string& case_path, const std::vector<std::string>& sets, const std::string& betas,
                       const LinearCaseOptions& options, const std::string& out) {
  const CaseSpec spec = load_case(case_path, sets);
  const LinearFrequencyResponse response = linear_frequency_response(case_path, sets, parse_beta_range(betas), options);
  print_modes(spec, response.model);
  const std::vector<LinearFrequencyPoint>& points = response.points;
  std::vector<std::string> gauges;
  for (const GaugeSpec& g : spec.gauges) gauges.push_back(g.name);
  write_linear_frequency_csv(out, points, gauges);
  std::printf("%10s %14s %14s %14s\n", "beta", "omega [rad/s]", "eta_max [mm]", "eta_min [mm]");
  for (const LinearFrequencyPoint& p : points) {
    const ResponseValue* v = gauges.empty() ? nullptr : p.response.find("eta:" + gauges.front());
    std::printf("%10.4f %14.5f %14.4f %14.4f\n", p.beta, p.omega, v ? 1e3 * v->avg_max : NAN, v ? 1e3 * v->avg_min : NAN);
  }
  std::printf("wrote %s (%zu frequency ratios)\n", out.c_str(), points.size());
  return 0;
}

// The period of the comparison windows: the excitation's, or mode 1's for a motion without one.
double comparison_period(const CaseSpec& spec, const LinearCase& r) {
  if (spec.excitation.type == ExcitationType::harmonic && spec.excitation.omega > 0.0)
    return 2.0 * std::numbers::pi / spec.excitation.omega;
  return 2.0 * std::numbers::pi / r.modes.front().omega;
}

int compare_with_run(const CaseSpec& spec, const LinearCase& r, const std::string& run_dir, int periods) {
  const std::string path = (std::filesystem::path(run_dir) / "timeseries.csv").string();
  if (!std::filesystem::exists(path)) throw InputError(run_dir, "--compare", "no timeseries.csv in the run directory");
  const CsvTable run = read_csv_table(path);
  const double period = comparison_period(spec, r);
  const double cutoff = spec.output.lowpass_hz;
  std::printf("\namplitude (half the crest-to-trough height) of each period (%.6g s) from t = 0, both series "
              "low-passed at %.3g Hz (output.lowpass_hz; 0: raw): linear against %s; deviation = (SPH - linear) / "
              "largest linear amplitude\n",
              period, cutoff, path.c_str());
  double worst = 0.0;
  for (std::size_t g = 0; g < r.gauge_names.size(); ++g) {
    const std::string column = "eta:" + r.gauge_names[g];
    if (!run.has(column)) {
      std::printf("%s: not in the run\n", column.c_str());
      continue;
    }
    const EnvelopeComparison c = compare_envelopes(r.response.time, r.response.elevation[g],
                                                         run.column("time"), run.column(column), 0.0, period, periods, cutoff);
    std::printf("%s\n%8s %14s %14s %12s %24s %24s\n", column.c_str(), "period", "linear [mm]", "SPH [mm]",
                "deviation", "crest, trough linear [mm]", "crest, trough SPH [mm]");
    for (int k = 0; k < periods; ++k)
      std::printf("%8d %14.4f %14.4f %+11.2f%% %11.4f %12.4f %11.4f %12.4f\n", k + 1, 1e3 * c.reference[k],
                  1e3 * c.simulated[k], 100.0 * c.deviation[k], 1e3 * c.reference_extremes.crest[k],
                  1e3 * c.reference_extremes.trough[k], 1e3 * c.simulated_extremes.crest[k],
                  1e3 * c.simulated_extremes.trough[k]);
    std::printf("%s: largest deviation %.2f%% of the largest linear amplitude\n", column.c_str(),
                100.0 * c.worst_deviation);
    worst = std::isnan(c.worst_deviation) || std::isnan(worst) ? NAN : std::max(worst, c.worst_deviation);
  }
  std::printf("largest deviation over the gauges: %.2f%%\n", 100.0 * worst);
  return 0;
}

}  // namespace

Command add_linear_command(CLI::App& app) {
  struct Options {
    std::string case_path, out = "linear.csv", compare, screens = "drag", betas,
        response_out = "linear_frequency_response.csv";
    std::vector<std::string> sets;
    LinearCaseOptions linear;
    int periods = 8;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "linear", "The linear modal solution from rest of a case's tank under its horizontal motion (and an SPH "
                "run's amplitudes against it)");
  sub->add_option("case", o->case_path, "Case file (TOML)")->required();
  sub->add_option("--modes", o->linear.modes, "Number of sloshing modes (default 10)")->check(CLI::Range(1, 50));
  sub->add_option("--damping", o->linear.damping,
                  "Modal damping: auto (boundary-layer for a rectangle, none otherwise; the default), none, "
                  "boundary-layer (laminar Stokes layers and bulk, clean rectangular tank), or a ratio for every "
                  "mode (e.g. 0.005)");
  sub->add_option("--screens", o->screens,
                  "drag (the default): the pressure loss of the case's vertical screens in a rectangular tank "
                  "acts on the modes; none: a clean tank")
      ->check(CLI::IsMember({"drag", "none"}));
  sub->add_option("--out", o->out, "Time series to write (default linear.csv): time, x_base, eta:<gauge>, F_w, F_sw");
  sub->add_option("--beta", o->betas,
                  "Frequency ratios A:B:N, a,b,c or one value: the steady-state response at each (the case's "
                  "harmonic excitation), written to --response-out instead of the time series");
  sub->add_option("--response-out", o->response_out,
                  "With --beta: the table to write (default linear_frequency_response.csv; the columns of a sweep's "
                  "frequency_response.csv)");
  sub->add_option("--compare", o->compare,
                  "A run directory of the same case: print the amplitude of each gauge in each period against "
                  "the linear one");
  sub->add_option("--periods", o->periods, "With --compare: the number of periods from t = 0 (default 8)")
      ->check(CLI::Range(1, 100000));
  add_set_option(sub, o->sets);
  return {sub, [o]() {
            o->linear.screens = o->screens == "drag";
            if (!o->betas.empty()) return frequency_response(o->case_path, o->sets, o->betas, o->linear, o->response_out);
            const CaseSpec spec = load_case(o->case_path, o->sets);
            const LinearCase r = linear_case_response(spec, o->linear);
            print_modes(spec, r);
            write_linear_csv(o->out, r);
            std::printf("wrote %s (%zu rows, RK4 step %.3g s)\n", o->out.c_str(), r.response.time.size(),
                        r.response.integration_step);
            if (!o->compare.empty()) return compare_with_run(spec, r, o->compare, o->periods);
            return 0;
          }};
}

}  // namespace sloshsph::app
