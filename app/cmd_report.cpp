// sloshsph report DIR [-- extra options]: plots and a self-contained report.html of a run
// directory (tools/report/report.py) or of a sweep directory (tools/report/sweep_report.py,
// chosen when DIR holds frequency_response.csv). The plotting is Python (Debian's
// python3-matplotlib, numpy, scipy, installed by scripts/install-deps.sh).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;

int write_report(const std::string& dir, const std::vector<std::string>& extra) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, "", "no such run or sweep directory");
  const bool sweep = fs::exists(fs::path(dir) / "frequency_response.csv", ec);
  const fs::path script = tools_dir() / "report" / (sweep ? "sweep_report.py" : "report.py");
  std::vector<std::string> args = {dir};
  args.insert(args.end(), extra.begin(), extra.end());
  const int code = run_python_tool(script, args);
  if (code == 0) std::fprintf(stderr, "sloshsph: report written: %s\n", (fs::path(dir) / "report.html").c_str());
  return code == 0 ? kExitSuccess : code == 2 ? kExitBadInput : kExitInternal;
}

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string dir;
    std::vector<std::string> extra;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("report", "Plots and report.html of a run or sweep directory");
  sub->add_option("dir", o->dir, "Run directory, or sweep directory (with frequency_response.csv)")->required();
  sub->add_option("extra", o->extra, "Options passed to the report script after --, e.g. -- --cycles 5");
  sub->allow_extras(false);
  return {sub, [o]() { return write_report(o->dir, o->extra); }};
}

}  // namespace sloshsph::app
