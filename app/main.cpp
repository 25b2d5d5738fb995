// The sloshsph command line. Exit codes (README.md):
//   0 success, 1 internal error, 2 bad case or usage, 3 the run failed, 4 interrupted.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/core/version.hpp"

int main(int argc, char** argv) {
  using namespace sloshsph;
  CLI::App app{"sloshsph: 2D and 3D SPH simulation of liquid sloshing in tanks and tuned liquid dampers"};
  app.set_version_flag("--version", std::string("sloshsph ") + kVersion + " (" + kGitRevision + ")");
  app.require_subcommand(1);
  for (int k = 0; k < argc; ++k) app::command_line() += (k ? " " : "") + std::string(argv[k]);

  std::vector<app::Command> commands = {app::add_run_command(app), app::add_modes_command(app),
                                        app::add_linear_command(app),
                                        app::add_tune_command(app), app::add_sweep_command(app),
                                        app::add_report_command(app), app::add_resume_command(app),
                                        app::add_validate_command(app), app::add_status_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitSuccess : kExitBadInput;
  }

  try {
    for (const app::Command& c : commands)
      if (c.sub->parsed()) return c.run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "sloshsph: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "sloshsph: %s\n", e.what());
    return kExitInterrupted;
  } catch (const RunFailure& e) {
    std::fprintf(stderr, "sloshsph: run failed: %s\n", e.what());
    return kExitRunFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sloshsph: internal error: %s\n", e.what());
    return kExitInternal;
  }
  return kExitSuccess;
}
