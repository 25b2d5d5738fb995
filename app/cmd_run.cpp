// sloshsph run [CASE] [--out DIR] [--set KEY=VALUE]... [--threads N] [--force] [--quiet]
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/run/run_case.hpp"

namespace sloshsph::app {

Command add_run_command(CLI::App& app) {
  struct Options {
    std::string case_path, out_dir;
    std::vector<std::string> sets;
    int threads = 0;
    double checkpoint_every = 0.0;
    bool force = false, quiet = false, report = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("run", "Run one simulation into a run directory");
  sub->add_option("case", o->case_path, "Case file (TOML); without it, the built-in default case");
  sub->add_option("--out", o->out_dir, "Run directory (default: out/<case name>)");
  add_set_option(sub, o->sets);
  sub->add_option("--threads", o->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  sub->add_flag("--force", o->force, "Allow writing into an existing, non-empty run directory");
  sub->add_flag("--quiet", o->quiet, "No progress output");
  sub->add_option("--checkpoint-every", o->checkpoint_every,
                  "Write checkpoint.bin every T seconds of simulated time (resume with `sloshsph resume DIR`)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--report", o->report, "Write plots and report.html into the run directory at the end");
  return {sub, [o]() {
            set_threads(o->threads);
            const CaseSpec spec = load_case(o->case_path, o->sets);
            RunOptions options;
            options.out_dir = o->out_dir;
            options.force = o->force;
            options.progress = !o->quiet;
            options.command_line = command_line();
            options.checkpoint_every = o->checkpoint_every;
            install_stop_handlers();
            const int code = run_case(spec, options);
            if (!o->report || code == kExitInterrupted) return code;
            const int report = write_report(options.out_dir.empty() ? "out/" + spec.name : options.out_dir);
            return code != kExitSuccess ? code : report;
          }};
}

}  // namespace sloshsph::app
