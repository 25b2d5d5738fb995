// sloshsph status DIR... [--json]: how far the runs in run directories are, whether each is
// still going (its process holds run.lock), the wall time left, and whether a stopped run can be
// resumed. Reads the directories' files and changes nothing. DIR may be a run directory, or a
// folder of them (a sweep's, SLOSHSPH_LONG_RUN_DIR).
#include <cstdio>
#include <ctime>
#include <memory>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/run/run_status.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;

Command add_status_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> dirs;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("status", "Where the runs in run directories stand (progress, running or not, time left)");
  sub->add_option("dirs", o->dirs, "Run directories, or folders of run directories")->required();
  sub->add_flag("--json", o->json, "One JSON array on stdout instead of the table");
  return {sub, [o]() {
            std::vector<RunStatus> runs;
            const std::time_t now = std::time(nullptr);
            for (const std::string& dir : o->dirs) {
              const std::vector<fs::path> found = run_directories(dir);
              if (found.empty()) throw InputError(dir, "", "not a run directory (no case.toml), nor a folder of run directories");
              for (const fs::path& run : found) runs.push_back(read_run_status(run, now));
            }
            if (o->json) {
              nlohmann::json all = nlohmann::json::array();
              for (const RunStatus& r : runs) all.push_back(status_json(r));
              std::printf("%s\n", all.dump(2).c_str());
            } else {
              std::fputs(status_table(runs).c_str(), stdout);
            }
            return kExitSuccess;
          }};
}

}  // namespace sloshsph::app
