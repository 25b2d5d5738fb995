// sloshsph validate [--long]: runs the physics validation tests of the build tree (ctest label
// `validation`, and `long` with --long), each of which records its checks (measured, reference,
// tolerance, verdict: tests/validation/validation_check.hpp), and regenerates docs/validation.md,
// docs/validation/results.json and the comparison plots (tools/validate/validate.py).
// Exit codes: 0 every check that ran passed, 3 a check or a test failed, 2 bad usage (no build tree).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;

Command add_validate_command(CLI::App& app) {
  struct Options {
    bool long_tests = false;
    std::string build_dir = SLOSHSPH_BINARY_DIR;
    std::string docs_dir = std::string(SLOSHSPH_SOURCE_DIR) + "/docs";
    std::string filter;
    int jobs = 1;
    bool no_run = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "validate", "Run the validation tests and regenerate docs/validation.md (table and comparison plots)");
  sub->add_flag("--long", o->long_tests, "Also run the long validations (ctest label `long`, hours)");
  sub->add_option("--build-dir", o->build_dir, "Build tree with the tests (default: the one this binary came from)");
  sub->add_option("--docs", o->docs_dir, "Folder to write validation.md, validation/ and figures/validation/ into");
  sub->add_option("--filter", o->filter, "Only the tests whose name matches this regular expression (ctest -R)");
  sub->add_option("--jobs", o->jobs,
                  "Tests run at once; each uses OMP_NUM_THREADS threads (on 2 cores, OMP_NUM_THREADS=1 with --jobs 2 "
                  "is the fastest: about 13 minutes for the validation label)")
      ->check(CLI::Range(1, 64));
  sub->add_flag("--no-run", o->no_run, "Do not run tests: regenerate the page from docs/validation/results.json");
  return {sub, [o]() {
            std::error_code ec;
            if (!o->no_run && !fs::exists(fs::path(o->build_dir) / "CTestTestfile.cmake", ec))
              throw InputError(o->build_dir, "--build-dir", "not a build tree with tests (no CTestTestfile.cmake)");
            std::vector<std::string> args = {"--build-dir", o->build_dir, "--docs", o->docs_dir,
                                             "--source-dir", SLOSHSPH_SOURCE_DIR, "--jobs", std::to_string(o->jobs)};
            if (o->long_tests) args.push_back("--long");
            if (o->no_run) args.push_back("--no-run");
            if (!o->filter.empty()) args.insert(args.end(), {"--filter", o->filter});
            const int code = run_python_tool(tools_dir() / "validate" / "validate.py", args);
            if (code == 0 || code == 3)
              std::fprintf(stderr, "sloshsph: validation report written: %s\n",
                           (fs::path(o->docs_dir) / "validation.md").c_str());
            return code == 0 ? kExitSuccess : code == 3 ? kExitRunFailed : code == 2 ? kExitBadInput : kExitInternal;
          }};
}

}  // namespace sloshsph::app
