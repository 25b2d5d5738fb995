#pragma once
// `sloshsph run`: a simulation written to a run directory.
//   case.toml        the resolved case (every key, defaults filled in)
//   run.json         provenance: version, git revision, command, threads, host, start time
//   timeseries.csv   one row per output.sample_interval (columns in docs/case-format.md)
//   summary.json     status, counts, timings, throughput, failure details
//   particles.pvd + particles/particles_NNNNNN.vtu   snapshots for ParaView
#include <string>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

struct RunOptions {
  std::string out_dir;       // empty: out/<case name>
  bool force = false;        // allow writing into an existing, non-empty directory
  bool progress = true;      // progress to stderr (a bar on a terminal, lines otherwise)
  std::string command_line;  // recorded in run.json
};

// Runs `spec` (already resolved) and returns the process exit code: 0 completed,
// 3 the run failed, 4 interrupted by SIGINT/SIGTERM. Throws InputError (exit 2) for
// problems found before anything is written.
int run_case(const CaseSpec& spec, const RunOptions& options);

// Installs SIGINT/SIGTERM handlers that ask the running simulation to stop after the
// current step and write consistent outputs.
void install_stop_handlers();
bool stop_requested();

}  // namespace sloshsph
