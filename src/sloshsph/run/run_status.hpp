#pragma once
// `sloshsph status`: where the runs in run directories stand, read from their files without
// touching them (an hour of simulated time takes hours; a user wants to know how far each run
// is, whether it is still going, when it will end, and whether a stopped one can be resumed).
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sloshsph {

// What a run directory's files say of its run.
//  state "running"      a process holds run.lock (`pid`);
//        "completed", "failed", "interrupted"   summary.json's status (from the run's last end);
//        "stopped"      timeseries.csv is newer than any summary.json and no process holds the
//                       lock: the process was killed (SIGKILL, a machine or session that ended);
//        "not started"  no timeseries.csv yet.
// A run is `resumable` when it has a checkpoint.bin (`sloshsph resume DIR` continues from it,
// which can be up to one --checkpoint-every interval before `time`).
struct RunStatus {
  std::string dir;
  std::string state;
  long pid = 0;                 // the lock holder when running; -1: cannot be told (not Linux)
  double time = -1.0;           // s, the last sampled time in timeseries.csv (-1: none)
  double end_time = -1.0;       // s, time.end of case.toml (-1: unreadable)
  double leaked = -1.0;         // fluid particles lost so far (last row's `leaked`; -1: none)
  double wall_per_simulated = -1.0;  // wall s per simulated s: running, since the last (re)start
                                     // (run.json); finished, summary.json's (-1: unknown)
  double remaining_wall_s = -1.0;    // running: an estimate of the wall time to time.end
  bool resumable = false;            // checkpoint.bin is there
  std::string failure;               // summary.json's failure message, if any
};

// The status of the run in `dir` at wall-clock time `now`. Never throws for a missing or
// half-written file: what cannot be read stays unknown (-1).
RunStatus read_run_status(const std::filesystem::path& dir, std::time_t now);

// The run directories an argument names: itself when it holds case.toml, else those of its
// subdirectories that do (a sweep's directory, a folder of long runs), sorted. Empty when none.
std::vector<std::filesystem::path> run_directories(const std::filesystem::path& path);

// One line per run: directory, state, time / end, percent, leaked, wall s per simulated s,
// remaining wall time; with a header.
std::string status_table(const std::vector<RunStatus>& runs);
nlohmann::json status_json(const RunStatus& run);

}  // namespace sloshsph
