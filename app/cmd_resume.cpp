// sloshsph resume RUN_DIR [--threads N] [--checkpoint-every T] [--quiet] [--report]
// Continues an interrupted run from its checkpoint.bin, appending to the same run directory.
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/run/run_case.hpp"

namespace sloshsph::app {

Command add_resume_command(CLI::App& app) {
  struct Options {
    std::string dir;
    int threads = 0;
    double checkpoint_every = 0.0;
    bool quiet = false, report = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("resume", "Continue an interrupted run from its checkpoint");
  sub->add_option("dir", o->dir, "Run directory holding checkpoint.bin")->required();
  sub->add_option("--threads", o->threads, "OpenMP threads (the same count as before gives bitwise the same results)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--checkpoint-every", o->checkpoint_every, "New checkpoint interval, s (default: as before)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--quiet", o->quiet, "No progress output");
  sub->add_flag("--report", o->report, "Write plots and report.html at the end");
  return {sub, [o]() {
            set_threads(o->threads);
            RunOptions options;
            options.progress = !o->quiet;
            options.command_line = command_line();
            options.checkpoint_every = o->checkpoint_every;
            install_stop_handlers();
            const int code = resume_run(o->dir, options);
            if (!o->report || code == kExitInterrupted) return code;
            const int report = write_report(o->dir);
            return code != kExitSuccess ? code : report;
          }};
}

}  // namespace sloshsph::app
