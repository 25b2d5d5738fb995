// sloshsph report DIR [-- extra options]: plots and a self-contained report.html of a run
// directory (tools/report/report.py) or of a sweep directory (tools/report/sweep_report.py,
// chosen when DIR holds frequency_response.csv). The plotting is Python (Debian's
// python3-matplotlib, numpy, scipy, installed by scripts/install-deps.sh).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;
namespace {

// The report scripts: $SLOSHSPH_TOOLS_DIR, else the source tree this binary was built from.
fs::path tools_dir() {
  if (const char* env = std::getenv("SLOSHSPH_TOOLS_DIR"); env && *env) return env;
  return fs::path(SLOSHSPH_SOURCE_DIR) / "tools";
}

// Debian's interpreter first: it is the one the set-up script gives numpy and matplotlib.
std::string python() {
  if (const char* env = std::getenv("SLOSHSPH_PYTHON"); env && *env) return env;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

}  // namespace

int write_report(const std::string& dir, const std::vector<std::string>& extra) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, "", "no such run or sweep directory");
  const bool sweep = fs::exists(fs::path(dir) / "frequency_response.csv", ec);
  const fs::path script = tools_dir() / "report" / (sweep ? "sweep_report.py" : "report.py");
  if (!fs::is_regular_file(script, ec))
    throw InputError(script.string(), "", "report script not found (set SLOSHSPH_TOOLS_DIR to the tools/ folder)");
  std::vector<std::string> args = {python(), script.string(), dir};
  args.insert(args.end(), extra.begin(), extra.end());
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::perror("sloshsph: cannot start python3");
    _exit(kExitInternal);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return kExitInternal;
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
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
