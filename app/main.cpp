// The sloshsph command line. Exit codes (README.md, docs/case-format.md):
//   0 success, 1 internal error, 2 bad case or usage, 3 the run failed, 4 interrupted.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/core/version.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/run_case.hpp"
#include "sloshsph/run/simulation.hpp"

namespace {

using namespace sloshsph;

std::string joined_command(int argc, char** argv) {
  std::string s;
  for (int k = 0; k < argc; ++k) s += (k ? " " : "") + std::string(argv[k]);
  return s;
}

CaseSpec load_case(const std::string& path, const std::vector<std::string>& sets) {
  CaseSpec spec = path.empty() ? read_case_text(default_case_text(), "<built-in default case>", sets)
                               : read_case_file(path, sets);
  if (path.empty()) spec.name = "default";
  return resolve_case(spec);
}

void set_threads(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sloshsph: 2D SPH simulation of liquid sloshing in tanks and tuned liquid dampers"};
  app.set_version_flag("--version", std::string("sloshsph ") + kVersion + " (" + kGitRevision + ")");
  app.require_subcommand(1);

  std::string case_path, out_dir;
  std::vector<std::string> sets;
  int threads = 0;
  bool force = false, quiet = false;
  CLI::App* run = app.add_subcommand("run", "Run one simulation into a run directory");
  run->add_option("case", case_path, "Case file (TOML); without it, the built-in default case");
  run->add_option("--out", out_dir, "Run directory (default: out/<case name>)");
  run->add_option("--set", sets, "Override a case key, KEY=VALUE (repeatable), e.g. --set time.end=2")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_flag("--force", force, "Allow writing into an existing, non-empty run directory");
  run->add_flag("--quiet", quiet, "No progress output");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitSuccess : kExitBadInput;
  }

  try {
    if (*run) {
      set_threads(threads);
      const CaseSpec spec = load_case(case_path, sets);
      RunOptions options;
      options.out_dir = out_dir;
      options.force = force;
      options.progress = !quiet;
      options.command_line = joined_command(argc, argv);
      install_stop_handlers();
      return run_case(spec, options);
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "sloshsph: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const RunFailure& e) {
    std::fprintf(stderr, "sloshsph: run failed: %s\n", e.what());
    return kExitRunFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sloshsph: internal error: %s\n", e.what());
    return kExitInternal;
  }
  return kExitSuccess;
}
