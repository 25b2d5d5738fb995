#include "sloshsph/run/run_status.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <toml++/toml.h>

#include "sloshsph/io/files.hpp"

namespace sloshsph {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) fields.push_back(field);
  return fields;
}

// The header and the last complete row of timeseries.csv (a row still being written, without
// its newline, is skipped). Reads only the first line and the file's last 64 KiB.
struct LastRow {
  std::vector<std::string> names;
  std::vector<std::string> values;
};

LastRow last_row(const fs::path& csv) {
  LastRow row;
  std::ifstream in(csv, std::ios::binary);
  std::string header;
  if (!in || !std::getline(in, header)) return row;
  row.names = split_csv_line(header);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff data_start = static_cast<std::streamoff>(header.size()) + 1;
  const std::streamoff from = std::max(data_start, size - std::streamoff{65536});
  if (from >= size) return row;
  std::string tail(static_cast<std::size_t>(size - from), '\0');
  in.seekg(from);
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  const std::size_t end = tail.rfind('\n');
  if (end == std::string::npos) return row;
  const std::size_t begin = end == 0 ? std::string::npos : tail.rfind('\n', end - 1);
  if (begin == std::string::npos && from != data_start) return row;  // a row longer than 64 KiB
  row.values = split_csv_line(tail.substr(begin == std::string::npos ? 0 : begin + 1, end - (begin + 1)));
  return row;
}

double number_in(const LastRow& row, const std::string& column) {
  const auto it = std::find(row.names.begin(), row.names.end(), column);
  const std::size_t k = static_cast<std::size_t>(it - row.names.begin());
  if (it == row.names.end() || k >= row.values.size()) return -1.0;
  char* end = nullptr;
  const double v = std::strtod(row.values[k].c_str(), &end);
  return end != row.values[k].c_str() && std::isfinite(v) ? v : -1.0;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);  // discarded when malformed
}

double end_time_of(const fs::path& case_toml) {
  try {
    const toml::table root = toml::parse_file(case_toml.string());
    return root["time"]["end"].value<double>().value_or(-1.0);
  } catch (const std::exception&) {
    return -1.0;
  }
}

// "2026-12-04T00:56:11Z" (run.json) as a time_t; -1 when malformed.
std::time_t parse_utc(const std::string& text) {
  std::tm t{};
  std::istringstream s(text);
  s >> std::get_time(&t, "%Y-%m-%dT%H:%M:%SZ");
  return s.fail() ? std::time_t{-1} : timegm(&t);
}

// The wall-clock start and the simulated time of the current process's start (the last resume,
// else the start) from run.json.
bool last_start(const nlohmann::json& run, std::time_t& started, double& at_time) {
  if (!run.is_object()) return false;
  const nlohmann::json* entry = &run;
  at_time = 0.0;
  if (run.contains("resumed") && run["resumed"].is_array() && !run["resumed"].empty()) {
    entry = &run["resumed"].back();
    at_time = entry->value("at_time_s", -1.0);
  }
  started = parse_utc(entry->value("started", std::string()));
  return started >= 0 && at_time >= 0.0;
}

void finished_state(RunStatus& s, const fs::path& dir) {
  const nlohmann::json sum = read_json(dir / "summary.json");
  if (!fs::exists(dir / "timeseries.csv")) {
    s.state = "not started";
    return;
  }
  // Rows beyond the time of the last summary (or no summary at all): the process went on after
  // it, or was resumed, and ended without writing one.
  const double summary_time = sum.is_object() ? sum.value("simulated_time_s", -1.0) : -1.0;
  if (summary_time < 0.0 || s.time > summary_time + 1e-9 * std::max(1.0, summary_time)) {
    s.state = "stopped";
    return;
  }
  s.state = sum.value("status", std::string("unknown"));
  s.failure = sum.value("failure", std::string());
  s.wall_per_simulated = sum.value("wall_seconds_per_simulated_second", -1.0);
}

void running_pace(RunStatus& s, const fs::path& dir, std::time_t now) {
  std::time_t started = 0;
  double at_time = 0.0;
  if (!last_start(read_json(dir / "run.json"), started, at_time)) return;
  const double simulated = s.time - at_time;
  if (simulated <= 0.0 || now <= started) return;
  s.wall_per_simulated = static_cast<double>(now - started) / simulated;
  if (s.end_time >= s.time) s.remaining_wall_s = s.wall_per_simulated * (s.end_time - s.time);
}

std::string clock_text(double seconds) {
  if (seconds < 0.0) return "-";
  const long total = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  return buf;
}

std::string number_text(double v, const char* format) {
  if (v < 0.0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

RunStatus read_run_status(const fs::path& dir, std::time_t now) {
  RunStatus s;
  s.dir = dir.string();
  const LastRow row = last_row(dir / "timeseries.csv");
  s.time = number_in(row, "time");
  s.leaked = number_in(row, "leaked");
  s.end_time = end_time_of(dir / "case.toml");
  s.resumable = fs::exists(dir / "checkpoint.bin");
  s.pid = run_directory_lock_holder(dir.string());
  if (s.pid > 0) {
    s.state = "running";
    running_pace(s, dir, now);
  } else {
    finished_state(s, dir);
  }
  return s;
}

std::vector<fs::path> run_directories(const fs::path& path) {
  if (fs::exists(path / "case.toml")) return {path};
  std::vector<fs::path> runs;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(path, error))
    if (entry.is_directory() && fs::exists(entry.path() / "case.toml")) runs.push_back(entry.path());
  std::sort(runs.begin(), runs.end());
  return runs;
}

std::string status_table(const std::vector<RunStatus>& runs) {
  auto state_text = [](const RunStatus& r) {
    if (r.state == "running") return r.state + " (pid " + std::to_string(r.pid) + ")";
    return r.resumable ? r.state + ", resumable" : r.state;
  };
  std::size_t width = 13, state_width = 5;
  for (const RunStatus& r : runs) {
    width = std::max(width, r.dir.size());
    state_width = std::max(state_width, state_text(r).size());
  }
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line, "%-*s  %-*s %10s %10s %6s %7s %10s %10s\n", static_cast<int>(width),
                "run directory", static_cast<int>(state_width), "state", "time (s)", "end (s)", "done", "leaked", "wall/sim", "remaining");
  out << line;
  for (const RunStatus& r : runs) {
    const double done = r.time >= 0.0 && r.end_time > 0.0 ? 100.0 * r.time / r.end_time : -1.0;
    std::snprintf(line, sizeof line, "%-*s  %-*s %10s %10s %6s %7s %10s %10s\n", static_cast<int>(width),
                  r.dir.c_str(), static_cast<int>(state_width), state_text(r).c_str(), number_text(r.time, "%.2f").c_str(),
                  number_text(r.end_time, "%.2f").c_str(), number_text(done, "%.1f%%").c_str(),
                  number_text(r.leaked, "%.0f").c_str(), number_text(r.wall_per_simulated, "%.3g").c_str(),
                  clock_text(r.remaining_wall_s).c_str());
    out << line;
    if (!r.failure.empty()) out << "    failure: " << r.failure << "\n";
  }
  return out.str();
}

nlohmann::json status_json(const RunStatus& r) {
  auto known = [](double v) { return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v); };
  nlohmann::json j = {{"dir", r.dir},
                      {"state", r.state},
                      {"time_s", known(r.time)},
                      {"end_time_s", known(r.end_time)},
                      {"leaked_particles", known(r.leaked)},
                      {"wall_seconds_per_simulated_second", known(r.wall_per_simulated)},
                      {"remaining_wall_s", known(r.remaining_wall_s)},
                      {"resumable", r.resumable}};
  if (r.state == "running") j["pid"] = r.pid;
  if (!r.failure.empty()) j["failure"] = r.failure;
  return j;
}

}  // namespace sloshsph
