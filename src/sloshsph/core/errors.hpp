#pragma once
#include <stdexcept>
#include <string>

namespace sloshsph {

// Process exit codes, documented in README.md and docs/case-format.md.
enum ExitCode : int {
  kExitSuccess = 0,
  kExitInternal = 1,     // a bug: an exception nobody expected
  kExitBadInput = 2,     // bad case file, bad key, bad command line
  kExitRunFailed = 3,    // the simulation itself failed (NaN, leaks, ...)
  kExitInterrupted = 4,  // SIGINT/SIGTERM: outputs are consistent up to the stop
};

// A problem with the input: the case file, a key, a record file, the command line.
// `where` is "file:line" or "file" or "--set"; `key` is the dotted key when there is one.
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, std::string key, const std::string& what)
      : std::runtime_error(format(where, key, what)), where_(std::move(where)), key_(std::move(key)) {}
  const std::string& where() const { return where_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& where, const std::string& key, const std::string& what) {
    std::string s = where.empty() ? std::string() : where + ": ";
    if (!key.empty()) s += "key '" + key + "': ";
    return s + what;
  }
  std::string where_;
  std::string key_;
};

// The run failed after it started: non-finite values, too many leaked particles...
class RunFailure : public std::runtime_error {
 public:
  explicit RunFailure(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace sloshsph
