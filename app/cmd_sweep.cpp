// sloshsph sweep CASE [--beta A:B:N] [--jobs J] [--threads T] [--out DIR] [--set KEY=VALUE]...
// One `sloshsph run` child process per point (frequency ratio times the values of every ranged
// --set KEY=A:B:N or KEY=a,b,c), J at a time; each point keeps its run directory
// (DIR/beta_X.XXXX, or with ranged sets DIR/beta_X.XXXX__KEY_VALUE..., and its .log). A failed
// point is reported and the sweep goes on; re-running the same command skips the points already
// finished.
#include <fcntl.h>
#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/io/files.hpp"
#include "sloshsph/run/run_case.hpp"
#include "sloshsph/run/sweep.hpp"
#include "sweep_ranks.hpp"

namespace sloshsph::app {
namespace fs = std::filesystem;
namespace {

struct SweepOptions {
  std::string case_path, out_dir, beta;
  std::vector<std::string> sets;
  int jobs = 1, threads = 0;
  bool retry_failed = false, quiet = false, report = false;
};

std::string self_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the sloshsph executable: " + ec.message());
  return p.string();
}

// Every --set of one point: those that hold for every point, then the point's frequency and
// axis values (the ranged --set texts are replaced by the point's values).
std::vector<std::string> point_sets(const SweepOptions& o, const SweepPoint& p) {
  std::vector<std::string> sets = split_sweep_sets(o.sets).fixed;
  sets.insert(sets.end(), p.overrides.begin(), p.overrides.end());
  return sets;
}

// Starts `sloshsph run` for one point, its output going to DIR/<label>.log.
pid_t start_point(const SweepOptions& o, const SweepPoint& p, int threads, bool force) {
  std::vector<std::string> args;
  if (point_resumable(p)) {
    // An interrupted point continues from its checkpoint (same results as an unbroken run).
    args = {self_executable(), "resume", p.directory, "--quiet", "--threads", std::to_string(threads)};
  } else {
    args = {self_executable(), "run", o.case_path, "--out", p.directory, "--quiet", "--threads", std::to_string(threads)};
    for (const std::string& s : point_sets(o, p)) args.insert(args.end(), {"--set", s});
    if (force) args.push_back("--force");
  }
  const std::string log = p.directory + ".log";
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(kExitInternal);
  }
  return pid;
}

// A finished point is skipped, but only if it was run from the same resolved case: a sweep
// directory reused with another case or other --set values is refused, not silently mixed.
bool already_done(const SweepOptions& o, const SweepPoint& p) {
  return point_finished(p, o.retry_failed, [&] { return resolved_case_toml(load_case(o.case_path, point_sets(o, p))); });
}

// "sweep:" or, under mpirun, "sweep[rank/size]:".
std::string prefix(const SweepRanks& ranks) {
  if (ranks.size() == 1) return "sweep:";
  return "sweep[" + std::to_string(ranks.rank()) + "/" + std::to_string(ranks.size()) + "]:";
}

void report(const SweepOptions& o, const SweepRanks& ranks, const char* what, const SweepPoint& p, std::size_t done,
            std::size_t running, std::size_t left) {
  if (o.quiet) return;
  std::fprintf(stderr, "%s %-9s %s   [%zu done, %zu running, %zu left]\n", prefix(ranks).c_str(), what,
               p.label.c_str(), done, running, left);
}

// Under mpirun without a shared file system rank 0 lacks the other ranks' run directories:
// it receives their summary.json texts and writes those it does not have, so that
// frequency_response.csv is complete either way.
void collect_remote_summaries(const SweepRanks& ranks, const std::vector<SweepPoint>& points) {
  std::vector<std::string> mine;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (ranks.mine(k)) {
      std::ifstream in(fs::path(points[k].directory) / "summary.json");
      std::ostringstream text;
      if (in) text << in.rdbuf();
      mine.push_back(text.str());
    }
  const std::vector<std::string> received = ranks.gather_to_root(mine, points.size());
  for (std::size_t k = 0; k < received.size(); ++k) {
    const fs::path summary = fs::path(points[k].directory) / "summary.json";
    if (received[k].empty() || fs::exists(summary)) continue;
    fs::create_directories(points[k].directory);
    write_file_atomic(summary.string(), received[k]);
  }
}

int run_sweep(const SweepOptions& o) {
  const SweepSets sets = split_sweep_sets(o.sets);
  const CaseSpec spec = load_case(o.case_path, sets.fixed);
  const std::string dir = o.out_dir.empty() ? (fs::path("out") / (spec.name + "_sweep")).string() : o.out_dir;
  std::vector<SweepPoint> points =
      plan_sweep(spec, o.beta.empty() ? std::vector<double>{} : parse_beta_range(o.beta), sets.axes, dir);
  const SweepRanks ranks;
  // Every point's case is read before anything runs: a bad point fails the sweep at once.
  std::vector<const SweepPoint*> queue;
  std::size_t owned = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const CaseSpec point_spec = load_case(o.case_path, point_sets(o, points[k]));
    if (o.beta.empty()) points[k].beta = excitation_beta(point_spec);  // the case's own, per point
    if (!ranks.mine(k)) continue;
    ++owned;
    if (!already_done(o, points[k])) queue.push_back(&points[k]);
  }
  fs::create_directories(dir);
  const int threads = o.threads > 0 ? o.threads : std::max(1, omp_get_num_procs() / std::max(1, o.jobs));
  std::size_t done = owned - queue.size(), failed = 0, next = 0;
  if (!o.quiet && done > 0)
    std::fprintf(stderr, "%s %zu of %zu points already finished, skipped\n", prefix(ranks).c_str(), done, owned);
  std::map<pid_t, const SweepPoint*> running;
  while (next < queue.size() || !running.empty()) {
    while (!stop_requested() && next < queue.size() && running.size() < static_cast<std::size_t>(o.jobs)) {
      const SweepPoint& p = *queue[next++];
      const bool force = fs::exists(p.directory);  // an interrupted or failed earlier attempt
      running[start_point(o, p, threads, force)] = &p;
      report(o, ranks, "started", p, done, running.size(), queue.size() - next);
    }
    if (running.empty()) break;  // stopped before starting the rest
    int wstatus = 0;
    const pid_t pid = waitpid(-1, &wstatus, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const SweepPoint& p = *it->second;
    running.erase(it);
    ++done;
    const int code = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : kExitInternal;
    if (code != kExitSuccess && code != kExitInterrupted) ++failed;
    report(o, ranks, code == kExitSuccess ? "completed" : code == kExitInterrupted ? "stopped" : "FAILED", p, done,
           running.size(), queue.size() - next);
    if (code != kExitSuccess && code != kExitInterrupted && !o.quiet)
      std::fprintf(stderr, "%s %s exited with code %d; see %s.log\n", prefix(ranks).c_str(), p.label.c_str(), code,
                   p.directory.c_str());
  }
  collect_remote_summaries(ranks, points);
  std::vector<SweepPoint> considered;  // rank 0: every point; other ranks: their own
  for (std::size_t k = 0; k < points.size(); ++k)
    if (ranks.rank() == 0 || ranks.mine(k)) considered.push_back(points[k]);
  if (ranks.rank() == 0) {
    write_file_atomic((fs::path(dir) / "frequency_response.csv").string(), frequency_response_csv(spec, sets.axes, points));
    if (!o.quiet)
      std::fprintf(stderr, "%s %zu points, %zu failed here -> %s/frequency_response.csv\n", prefix(ranks).c_str(),
                   points.size(), failed, dir.c_str());
  }
  if (stop_requested()) return kExitInterrupted;
  const int report_code = o.report && ranks.rank() == 0 ? write_report(dir) : kExitSuccess;
  for (const SweepPoint& p : considered)
    if (point_status(p.directory) != "completed") return kExitRunFailed;
  return report_code;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "Run one simulation per frequency ratio (and per value of ranged --set keys) and tabulate the response");
  sub->add_option("case", o->case_path, "Case file (TOML) with a harmonic or pitch excitation")->required();
  sub->add_option("--beta", o->beta,
                  "Frequency ratios: A:B:N (N points from A to B), a,b,c, or one value (default: the case's own)");
  sub->add_option("--jobs", o->jobs, "Points run at the same time (default 1)")->check(CLI::PositiveNumber);
  sub->add_option("--threads", o->threads, "OpenMP threads per point (default: cores / jobs)")->check(CLI::PositiveNumber);
  sub->add_option("--out", o->out_dir, "Sweep directory (default: out/<case name>_sweep)");
  sub->add_option("--set", o->sets,
                  "Override a case key, KEY=VALUE (repeatable); KEY=A:B:N or KEY=a,b,c sweeps the key over those "
                  "values (every combination with the other swept keys and --beta)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_flag("--retry-failed", o->retry_failed, "Run again the points that failed in an earlier attempt");
  sub->add_flag("--quiet", o->quiet, "No progress output");
  sub->add_flag("--report", o->report, "Write plots and report.html into the sweep directory at the end");
  return {sub, [o]() {
            install_stop_handlers();
            return run_sweep(*o);
          }};
}

}  // namespace sloshsph::app
