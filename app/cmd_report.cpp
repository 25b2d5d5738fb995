// sloshsph report DIR [-- extra options]: plots and a self-contained report.html of a run
// directory (tools/report/report.py) or of a sweep directory (tools/report/sweep_report.py,
// chosen when DIR holds frequency_response.csv), or a comparison of the run directories in a folder
// (tools/report/compare_report.py, when DIR is a folder of them). The plotting is Python (Debian's
// python3-matplotlib, numpy, scipy, installed by scripts/install-deps.sh).
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/files.hpp"
#include "sloshsph/run/run_status.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;

namespace {

// A folder of run directories (not itself a run, not a sweep): compare_report.py, given the runs'
// states as `sloshsph status --json` reads them (a temporary file, removed after).
int write_comparison(const std::string& dir, const std::vector<fs::path>& runs, const std::vector<std::string>& extra) {
  nlohmann::json states = nlohmann::json::array();
  const std::time_t now = std::time(nullptr);
  for (const fs::path& run : runs) states.push_back(status_json(read_run_status(run, now)));
  const fs::path status_file = fs::temp_directory_path() / ("sloshsph_status_" + std::to_string(::getpid()) + ".json");
  write_file_atomic(status_file.string(), states.dump() + "\n");
  std::vector<std::string> args = {dir, "--status", status_file.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const int code = run_python_tool(tools_dir() / "report" / "compare_report.py", args);
  std::error_code ignored;
  fs::remove(status_file, ignored);
  return code;
}

}  // namespace

int write_report(const std::string& dir, const std::vector<std::string>& extra) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, "", "no such run or sweep directory");
  const bool sweep = fs::exists(fs::path(dir) / "frequency_response.csv", ec);
  const std::vector<fs::path> runs = run_directories(dir);
  const bool folder = !sweep && !runs.empty() && runs.front() != fs::path(dir);
  std::vector<std::string> args = {dir};
  args.insert(args.end(), extra.begin(), extra.end());
  const fs::path script = tools_dir() / "report" / (sweep ? "sweep_report.py" : "report.py");
  const int code = folder ? write_comparison(dir, runs, extra) : run_python_tool(script, args);
  if (code == 0) std::fprintf(stderr, "sloshsph: report written: %s\n", (fs::path(dir) / "report.html").c_str());
  return code == 0 ? kExitSuccess : code == 2 ? kExitBadInput : kExitInternal;
}

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string dir;
    std::vector<std::string> extra;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("report", "Plots and report.html of a run or sweep directory, or a comparison of the runs in a folder");
  sub->add_option("dir", o->dir, "Run directory, sweep directory (with frequency_response.csv), or a folder of run directories (a comparison)")->required();
  sub->add_option("extra", o->extra, "Options passed to the report script after --, e.g. -- --cycles 5");
  sub->allow_extras(false);
  return {sub, [o]() { return write_report(o->dir, o->extra); }};
}

}  // namespace sloshsph::app
