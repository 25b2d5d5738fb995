// `sloshsph status` (run/run_status.hpp): the state, progress and pace of a run read from the
// files of its run directory, built here by hand for each state.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sloshsph/io/files.hpp"
#include "sloshsph/run/run_status.hpp"

namespace sloshsph {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / "sloshsph_run_status_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A run directory of a 10 s case with rows every 2 s up to `last_time`.
fs::path run_dir(const std::string& name, int last_time) {
  const fs::path dir = fresh_dir(name);
  write(dir / "case.toml", "title = \"t\"\n[time]\nend = 10.0\ndt = 0.001\n");
  std::string csv = "time,eta:right,leaked\n";
  for (int t = 0; t <= last_time; t += 2) csv += std::to_string(t) + ",0.01," + (t >= 6 ? "3" : "0") + "\n";
  write(dir / "timeseries.csv", csv);
  write(dir / "run.json", R"({"started": "2026-12-04T01:00:00Z"})");
  return dir;
}

constexpr std::time_t kStart = 1796346000;  // 2026-12-04T01:00:00Z

TEST(RunStatus, LockHolderIsTheProcessThatHoldsRunLock) {
  const fs::path dir = fresh_dir("lock");
  EXPECT_EQ(run_directory_lock_holder(dir.string()), 0) << "no run.lock";
  {
    RunDirectoryLock lock(dir.string());
    const long holder = run_directory_lock_holder(dir.string());
    if (holder == -1) GTEST_SKIP() << "no /proc/locks on this system";
    EXPECT_EQ(holder, static_cast<long>(::getpid()));
  }
  EXPECT_EQ(run_directory_lock_holder(dir.string()), 0) << "released when the lock object ends";
}

TEST(RunStatus, NotStartedWithoutTimeSeries) {
  const fs::path dir = fresh_dir("not_started");
  write(dir / "case.toml", "[time]\nend = 5\n");
  const RunStatus s = read_run_status(dir, kStart);
  EXPECT_EQ(s.state, "not started");
  EXPECT_EQ(s.time, -1.0);
  EXPECT_EQ(s.end_time, 5.0);  // an integer end is read as a number too
}

TEST(RunStatus, CompletedRunTakesItsPaceFromTheSummary) {
  const fs::path dir = run_dir("completed", 10);
  write(dir / "summary.json",
        R"({"status": "completed", "simulated_time_s": 10.0, "wall_seconds_per_simulated_second": 2.5})");
  const RunStatus s = read_run_status(dir, kStart + 1000);
  EXPECT_EQ(s.state, "completed");
  EXPECT_EQ(s.time, 10.0);
  EXPECT_EQ(s.end_time, 10.0);
  EXPECT_EQ(s.leaked, 3.0);
  EXPECT_EQ(s.wall_per_simulated, 2.5);
  EXPECT_EQ(s.remaining_wall_s, -1.0);
  EXPECT_FALSE(s.resumable);
}

TEST(RunStatus, RowsBeyondTheSummaryMeanTheProcessWasKilled) {
  // Interrupted at 4 s, resumed, then killed at 8 s with no summary of its own: "stopped".
  const fs::path dir = run_dir("killed", 8);
  write(dir / "summary.json", R"({"status": "interrupted", "simulated_time_s": 4.0})");
  write(dir / "checkpoint.bin", "x");
  RunStatus s = read_run_status(dir, kStart);
  EXPECT_EQ(s.state, "stopped");
  EXPECT_TRUE(s.resumable);
  EXPECT_EQ(s.time, 8.0);
  // The same directory as the interruption left it: "interrupted".
  write(dir / "summary.json", R"({"status": "interrupted", "simulated_time_s": 8.0})");
  s = read_run_status(dir, kStart);
  EXPECT_EQ(s.state, "interrupted");
  // No summary at all (killed before its first end): "stopped" as well.
  fs::remove(dir / "summary.json");
  EXPECT_EQ(read_run_status(dir, kStart).state, "stopped");
}

TEST(RunStatus, FailedRunKeepsItsMessage) {
  const fs::path dir = run_dir("failed", 4);
  write(dir / "summary.json", R"({"status": "failed", "simulated_time_s": 4.0, "failure": "non-finite velocity"})");
  const RunStatus s = read_run_status(dir, kStart);
  EXPECT_EQ(s.state, "failed");
  EXPECT_EQ(s.failure, "non-finite velocity");
  EXPECT_NE(status_table({s}).find("failure: non-finite velocity"), std::string::npos);
}

TEST(RunStatus, RunningPaceCountsFromTheLastResume) {
  // Resumed at 2 s at 01:00:00, at 6 s 100 wall seconds later: 25 wall s per simulated s, and
  // 4 simulated seconds (100 wall seconds) left. A row still being written is not read.
  const fs::path dir = run_dir("running", 6);
  write(dir / "run.json", R"({"started": "2026-12-03T20:00:00Z",
      "resumed": [{"at_time_s": 2.0, "started": "2026-12-04T01:00:00Z"}]})");
  std::ofstream(dir / "timeseries.csv", std::ios::app) << "8,0.0";
  RunDirectoryLock lock(dir.string());
  const RunStatus s = read_run_status(dir, kStart + 100);
  if (s.pid == -1) GTEST_SKIP() << "no /proc/locks on this system";
  EXPECT_EQ(s.state, "running");
  EXPECT_EQ(s.pid, static_cast<long>(::getpid()));
  EXPECT_EQ(s.time, 6.0);
  EXPECT_DOUBLE_EQ(s.wall_per_simulated, 25.0);
  EXPECT_DOUBLE_EQ(s.remaining_wall_s, 100.0);
  const nlohmann::json j = status_json(s);
  EXPECT_EQ(j["state"], "running");
  EXPECT_EQ(j["pid"], static_cast<long>(::getpid()));
  EXPECT_DOUBLE_EQ(j["remaining_wall_s"].get<double>(), 100.0);
}

TEST(RunStatus, FindsTheRunDirectoriesOfAFolder) {
  const fs::path parent = fresh_dir("folder");
  for (const char* name : {"b_run", "a_run"}) {
    fs::create_directories(parent / name);
    write(parent / name / "case.toml", "[time]\nend = 1\n");
  }
  fs::create_directories(parent / "not_a_run");
  const auto runs = run_directories(parent);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].filename(), "a_run");
  EXPECT_EQ(runs[1].filename(), "b_run");
  EXPECT_EQ(run_directories(parent / "a_run").size(), 1u) << "a run directory names itself";
  EXPECT_TRUE(run_directories(parent / "not_a_run").empty());
  EXPECT_TRUE(run_directories(parent / "no_such_dir").empty());
}

}  // namespace
}  // namespace sloshsph
