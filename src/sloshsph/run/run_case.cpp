#include "sloshsph/run/run_case.hpp"

#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/core/version.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/io/csv_writer.hpp"
#include "sloshsph/io/files.hpp"
#include "sloshsph/io/vtk_writer.hpp"
#include "sloshsph/run/progress.hpp"
#include "sloshsph/run/response.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace fs = std::filesystem;
namespace {

std::atomic<bool> g_stop{false};

void on_signal(int) { g_stop.store(true); }

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string host_name() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// Refuses to write into a non-empty directory unless forced; creates it.
void prepare_directory(const std::string& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw InputError("--out " + dir, "", "exists and is not a directory");
    if (!fs::is_empty(dir, ec) && !force)
      throw InputError("--out " + dir, "", "the run directory exists and is not empty; choose another --out or pass --force");
    if (force) {
      for (const char* name : {"timeseries.csv", "summary.json", "run.json", "case.toml", "particles.pvd"})
        fs::remove(fs::path(dir) / name, ec);
      fs::remove_all(fs::path(dir) / "particles", ec);
    }
  }
  fs::create_directories(fs::path(dir) / "particles", ec);
  if (ec) throw InputError("--out " + dir, "", "cannot create the run directory: " + ec.message());
}

nlohmann::json run_metadata(const CaseSpec& spec, const RunOptions& o) {
  return {{"program", "sloshsph"},
          {"version", kVersion},
          {"git_revision", kGitRevision},
          {"command", o.command_line},
          {"case", spec.source},
          {"threads", omp_get_max_threads()},
          {"host", host_name()},
          {"started", now_iso8601()}};
}

// The sampled rows, kept for the analysis written at the end of the run.
struct SampledSeries {
  std::vector<std::vector<double>> columns;
  void add(const std::vector<double>& row) {
    if (columns.empty()) columns.resize(row.size());
    for (std::size_t k = 0; k < row.size(); ++k) columns[k].push_back(row[k]);
  }
};

// Steady-state response (response.hpp) for periodic excitation; null for other runs.
nlohmann::json analyse_response(const CaseSpec& spec, const Simulation& sim, const SampledSeries& series,
                                const std::string& dir) {
  const ExcitationSpec& e = spec.excitation;
  if ((e.type != ExcitationType::harmonic && e.type != ExcitationType::pitch) || !(e.omega > 0.0) ||
      series.columns.empty())
    return nullptr;
  std::vector<std::string> names, units;
  for (const Column& c : sim.columns()) {
    names.push_back(c.name);
    units.push_back(c.unit);
  }
  ResponseOptions o;
  o.period = 2.0 * M_PI / e.omega;
  o.cycles = spec.output.response_cycles;
  o.cutoff_hz = spec.output.lowpass_hz;
  o.water_mass = sim.scene().initial_fluid_mass;
  o.amplitude = e.amplitude;
  o.energy = e.type == ExcitationType::harmonic;  // pitch does its work through a moment, not F_w dX
  const Response r = steady_state_response(names, units, series.columns, o);
  if (r.note.empty()) write_file_atomic((fs::path(dir) / "response.csv").string(), response_csv(r));
  return response_json(r);
}

struct Snapshots {
  std::string dir;
  bool walls;
  PvdIndex index;
  int count = 0;
  void write(const Particles& p, double time) {
    char name[64];
    std::snprintf(name, sizeof name, "particles/particles_%06d.vtu", count++);
    write_vtu((fs::path(dir) / name).string(), p, walls);
    index.add(time, name);
  }
};

}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool stop_requested() { return g_stop.load(); }

int run_case(const CaseSpec& spec, const RunOptions& options) {
  const std::string dir = options.out_dir.empty() ? (fs::path("out") / spec.name).string() : options.out_dir;
  // Everything that can reject the case happens before the directory is touched.
  Simulation sim(spec);
  prepare_directory(dir, options.force);
  for (const std::string& w : sim.scene().warnings) std::fprintf(stderr, "sloshsph: warning: %s\n", w.c_str());

  const auto start = std::chrono::steady_clock::now();
  write_file_atomic((fs::path(dir) / "case.toml").string(), resolved_case_toml(spec));
  nlohmann::json meta = run_metadata(spec, options);
  write_file_atomic((fs::path(dir) / "run.json").string(), meta.dump(2) + "\n");

  std::vector<std::string> names;
  nlohmann::json units = nlohmann::json::object();
  for (const Column& c : sim.columns()) {
    names.push_back(c.name);
    units[c.name] = c.unit;
  }
  CsvWriter csv((fs::path(dir) / "timeseries.csv").string(), names);
  Snapshots snaps{dir, spec.output.snapshot_walls, PvdIndex((fs::path(dir) / "particles.pvd").string())};
  Progress progress(spec.time.end, options.progress);

  SampledSeries series;
  auto write_sample = [&] {
    const std::vector<double> row = sim.sample();
    csv.write_row(row);
    series.add(row);
  };
  write_sample();
  const bool snapshots = spec.output.snapshot_interval > 0.0;
  if (snapshots) snaps.write(sim.particles(), 0.0);
  double next_sample = spec.output.sample_interval;
  double next_snapshot = spec.output.snapshot_interval;
  const double tol = 1e-9;

  std::string status = "completed", failure;
  int code = kExitSuccess;
  try {
    while (!sim.finished()) {
      if (stop_requested()) {
        status = "interrupted";
        code = kExitInterrupted;
        break;
      }
      sim.step();
      if (sim.time() >= next_sample - tol || sim.finished()) {
        write_sample();
        while (next_sample <= sim.time() + tol) next_sample += spec.output.sample_interval;
      }
      if (snapshots && sim.time() >= next_snapshot - tol) {
        snaps.write(sim.particles(), sim.time());
        while (next_snapshot <= sim.time() + tol) next_snapshot += spec.output.snapshot_interval;
      }
      progress.update(sim.time(), sim.steps());
    }
  } catch (const RunFailure& e) {
    status = "failed";
    failure = e.what();
    code = kExitRunFailed;
    write_sample();  // the last good state
    if (snapshots) snaps.write(sim.particles(), sim.time());
  }
  progress.finish(sim.time(), sim.steps());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const Particles& p = sim.particles();
  const double total_particles = static_cast<double>(p.size() + sim.leaked());
  nlohmann::json s;
  s["status"] = status;
  s["steps"] = sim.steps();
  s["simulated_time_s"] = sim.time();
  s["wall_time_s"] = wall;
  s["fluid_particles"] = sim.scene().initial_fluid_count;
  s["wall_particles"] = p.n_wall();
  s["leaked_particles"] = sim.leaked();
  s["particle_steps_per_second"] = wall > 0 ? total_particles * sim.steps() / wall : 0.0;
  s["fluid_particle_steps_per_second"] =
      wall > 0 ? static_cast<double>(sim.scene().initial_fluid_count) * sim.steps() / wall : 0.0;
  s["wall_seconds_per_simulated_second"] = sim.time() > 0 ? wall / sim.time() : 0.0;
  s["threads"] = omp_get_max_threads();
  s["dp_m"] = spec.particles.dp;
  s["h_m"] = sim.scene().h;
  s["dt_s"] = spec.time.dt;
  s["dt_adaptive"] = spec.time.adaptive;
  s["fluid_mass_kg_per_m"] = sim.scene().initial_fluid_mass;
  s["final_fluid_mass_kg_per_m"] = sim.fluid_mass();
  s["omega1_linear_rad_s"] = first_sloshing_omega(spec);
  if (spec.excitation.type != ExcitationType::none) s["excitation_omega_rad_s"] = spec.excitation.omega;
  s["neighbour_list_builds"] = sim.scheme().neighbours().builds();
  s["memory_bytes_per_particle"] = static_cast<double>(sim.scheme().memory_bytes()) / total_particles;
  s["columns"] = units;
  s["version"] = kVersion;
  s["git_revision"] = kGitRevision;
  if (nlohmann::json response = analyse_response(spec, sim, series, dir); !response.is_null())
    s["response"] = response;
  if (!failure.empty()) s["failure"] = failure;
  if (!sim.scene().warnings.empty()) s["warnings"] = sim.scene().warnings;
  if (sim.leaked() > 0) {
    nlohmann::json leaks = nlohmann::json::array();
    for (const LeakRecord& l : sim.leaks()) {
      if (leaks.size() >= 100) break;
      leaks.push_back({{"time_s", l.time}, {"id", l.id}, {"x", l.position.x}, {"y", l.position.y}});
    }
    s["leaks_first_100"] = leaks;
  }
  write_file_atomic((fs::path(dir) / "summary.json").string(), s.dump(2) + "\n");
  meta["finished"] = now_iso8601();
  meta["status"] = status;
  write_file_atomic((fs::path(dir) / "run.json").string(), meta.dump(2) + "\n");

  if (code == kExitRunFailed) std::fprintf(stderr, "sloshsph: run failed: %s\n", failure.c_str());
  if (code == kExitInterrupted)
    std::fprintf(stderr, "sloshsph: interrupted at t = %.4f s; outputs are consistent up to that time\n", sim.time());
  std::fprintf(stderr, "sloshsph: %s %s in %s (%zu steps, %.3g particle-steps/s) -> %s\n", status.c_str(),
               spec.name.c_str(), format_duration(wall).c_str(), sim.steps(),
               s["particle_steps_per_second"].get<double>(), dir.c_str());
  return code;
}

}  // namespace sloshsph
