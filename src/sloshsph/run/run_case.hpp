#pragma once
// `sloshsph run`: a simulation written to a run directory.
//   case.toml        the resolved case (every key, defaults filled in)
//   run.json         provenance: version, git revision, command, threads, host, start time
//   timeseries.csv   one row per output.sample_interval (columns in docs/case-format.md)
//   summary.json     status, counts, timings, throughput, failure details
//   particles.pvd + particles/particles_NNNNNN.vtu   snapshots for ParaView
//   checkpoint.bin   the state to resume from (written every --checkpoint-every and when
//                    interrupted; removed when the run completes)
#include <csignal>
#include <cstddef>
#include <functional>
#include <string>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

struct RunOptions {
  std::string out_dir;       // empty: out/<case name>
  bool force = false;        // allow writing into an existing, non-empty directory
  bool progress = true;      // progress to stderr (a bar on a terminal, lines otherwise)
  std::string command_line;  // recorded in run.json
  double checkpoint_every = 0.0;  // s of simulated time between checkpoints (0: only on SIGINT/SIGTERM)
  // Called after every row the run loop writes to timeseries.csv (the last one at the end) with the
  // simulated time, the case's time.end and the steps so far: the Python module's progress
  // callback. It may call request_stop().
  std::function<void(double time, double end_time, std::size_t steps)> on_sample;
};

// Runs `spec` (already resolved) and returns the process exit code: 0 completed,
// 3 the run failed, 4 interrupted by SIGINT/SIGTERM. Throws InputError (exit 2) for
// problems found before anything is written.
int run_case(const CaseSpec& spec, const RunOptions& options);

// `sloshsph resume DIR`: continues the run in DIR from its checkpoint.bin (written every
// options.checkpoint_every and when a run is interrupted). The resumed run appends to the same
// files and, for the same thread count, writes exactly what the uninterrupted run would have
// (the run-loop state is in the checkpoint). InputError (exit 2) when DIR has no checkpoint,
// or its case.toml changed. Returns the exit code as run_case does.
int resume_run(const std::string& dir, const RunOptions& options);

// Installs SIGINT/SIGTERM handlers that ask the running simulation to stop after the
// current step and write consistent outputs.
void install_stop_handlers();
bool stop_requested();
// What the handlers do: the running simulation stops after its current step (async-signal-safe).
void request_stop();

// The same handlers for one scope (the Python module, whose interpreter has its own): an earlier
// stop request is forgotten at its start, and the handlers before it are put back at its end.
class ScopedStopHandlers {
 public:
  ScopedStopHandlers();
  ~ScopedStopHandlers();
  ScopedStopHandlers(const ScopedStopHandlers&) = delete;
  ScopedStopHandlers& operator=(const ScopedStopHandlers&) = delete;

 private:
  struct sigaction before_int_ {};
  struct sigaction before_term_ {};
};

}  // namespace sloshsph
