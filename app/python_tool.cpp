// Starts one of the project's Python tools (tools/) and waits for it: the reports and the
// validation report are Python (Debian's python3-matplotlib, numpy, scipy, installed by
// scripts/install-deps.sh).
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;
namespace {

// Debian's interpreter first: it is the one the set-up script gives numpy and matplotlib.
std::string python() {
  if (const char* env = std::getenv("SLOSHSPH_PYTHON"); env && *env) return env;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

}  // namespace

// $SLOSHSPH_TOOLS_DIR, else the source tree this binary was built from.
fs::path tools_dir() {
  if (const char* env = std::getenv("SLOSHSPH_TOOLS_DIR"); env && *env) return env;
  return fs::path(SLOSHSPH_SOURCE_DIR) / "tools";
}

int run_python_tool(const fs::path& script, const std::vector<std::string>& script_args) {
  std::error_code ec;
  if (!fs::is_regular_file(script, ec))
    throw InputError(script.string(), "", "tool script not found (set SLOSHSPH_TOOLS_DIR to the tools/ folder)");
  std::vector<std::string> args = {python(), script.string()};
  args.insert(args.end(), script_args.begin(), script_args.end());
  std::fflush(nullptr);
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
  return WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
}

}  // namespace sloshsph::app
