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
      : std::runtime_error(format(where, key, what)), where_(std::move(where)), key_(std::move(key)), message_(what) {}
  const std::string& where() const { return where_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }
  // The same error located more precisely: code that checks a value without knowing where it
  // came from throws with an empty `where` (or only the file's name, `vague`), and the caller
  // that has the case's key locations fills in "file:line".
  InputError located(const std::string& where, const std::string& vague = "") const {
    return where_.empty() || where_ == vague ? InputError(where, key_, message_) : *this;
  }

 private:
  static std::string format(const std::string& where, const std::string& key, const std::string& what) {
    std::string s = where.empty() ? std::string() : where + ": ";
    if (!key.empty()) s += "key '" + key + "': ";
    return s + what;
  }
  std::string where_;
  std::string key_;
  std::string message_;
};

// The run failed after it started: non-finite values, too many leaked particles...
class RunFailure : public std::runtime_error {
 public:
  explicit RunFailure(const std::string& what) : std::runtime_error(what) {}
};

// SIGINT/SIGTERM arrived before the run had anything to keep (while the fluid settled, before
// the run directory exists): the command exits 4 and writes nothing.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace sloshsph
