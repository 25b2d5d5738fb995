#pragma once
// The sloshsph subcommands. Each lives in its own cmd_<name>.cpp and registers itself on the
// CLI11 app; main() parses, runs the chosen one, and maps exceptions to exit codes.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph::app {

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;  // returns the exit code; may throw InputError / RunFailure
};

// Reads CASE (or the built-in default when empty), applies --set overrides, resolves it.
CaseSpec load_case(const std::string& path, const std::vector<std::string>& overrides);

// The repeatable --set KEY=VALUE option.
void add_set_option(CLI::App* sub, std::vector<std::string>& sets);

// The whole command line, recorded in run.json.
std::string& command_line();

// Sets the OpenMP thread count (0: leave the default).
void set_threads(int threads);

Command add_run_command(CLI::App& app);
Command add_modes_command(CLI::App& app);
Command add_linear_command(CLI::App& app);
Command add_tune_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_resume_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_status_command(CLI::App& app);

// Runs the report script on a run or sweep directory (cmd_report.cpp); returns an exit code.
int write_report(const std::string& dir, const std::vector<std::string>& extra = {});

// The folder of the Python tools: $SLOSHSPH_TOOLS_DIR, else the source tree's tools/.
std::filesystem::path tools_dir();

// Runs tools/<script> with Python (python_tool.cpp) and returns its exit code; stdio inherited.
int run_python_tool(const std::filesystem::path& script, const std::vector<std::string>& args);

}  // namespace sloshsph::app
