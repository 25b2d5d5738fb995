#include <omp.h>

#include "commands.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph::app {

CaseSpec load_case(const std::string& path, const std::vector<std::string>& overrides) {
  CaseSpec spec = path.empty() ? read_case_text(default_case_text(), "<built-in default case>", overrides)
                               : read_case_file(path, overrides);
  if (path.empty()) spec.name = "default";
  return resolve_case(spec);
}

void add_set_option(CLI::App* sub, std::vector<std::string>& sets) {
  sub->add_option("--set", sets, "Override a case key, KEY=VALUE (repeatable), e.g. --set time.end=2")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::string& command_line() {
  static std::string line;
  return line;
}

void set_threads(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

}  // namespace sloshsph::app
