#pragma once
// A checked view of one TOML table: every read names its key, every value is
// type- and range-checked, and finish() rejects keys that nobody read.
// Errors are InputError("file:line", "dotted.key", "what was expected, what was found").
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

// Shared by all readers of one case: where it came from and which keys --set changed.
struct TomlContext {
  std::string file;
  std::set<std::string> overridden;  // dotted keys set on the command line
  std::map<std::string, std::string> locations;  // dotted key -> "file:line", for every key read
};

class TableReader {
 public:
  TableReader(const toml::table& table, std::string prefix, std::shared_ptr<TomlContext> context);

  bool has(const std::string& key) const;

  double number(const std::string& key, double fallback);
  double number(const std::string& key);  // required
  std::optional<double> optional_number(const std::string& key);
  double positive(const std::string& key, double fallback);
  double positive(const std::string& key);  // required
  double non_negative(const std::string& key, double fallback);
  double in_range(const std::string& key, double fallback, double lo, double hi);
  std::optional<double> optional_positive(const std::string& key);
  long long integer(const std::string& key, long long fallback, long long lo, long long hi);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string string(const std::string& key);  // required
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed);
  Vec2 point(const std::string& key);  // [x, y]
  std::optional<Vec2> optional_point(const std::string& key);
  std::optional<Vec3> optional_point3(const std::string& key);  // [x, y, z] (3D cases)
  std::vector<Vec2> points(const std::string& key);  // [[x, y], ...]

  std::optional<TableReader> table(const std::string& key);
  std::vector<TableReader> array_of_tables(const std::string& key);

  // Rejects keys of this table that were not read (with a suggestion when one is close).
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  std::string path(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  std::string location(const std::string& key) const;
  const std::string& file() const { return context_->file; }

 private:
  const toml::node* node(const std::string& key);
  double as_number(const std::string& key, const toml::node& n) const;

  const toml::table* table_;
  std::string prefix_;
  std::shared_ptr<TomlContext> context_;
  std::set<std::string> read_;
};

// Applies one "--set KEY=VALUE" to a parsed case. VALUE is read as a TOML value
// (number, boolean, string, array); anything that is not valid TOML is taken as a
// bare string, so --set tank.shape=rectangle works without quotes. KEY is dotted;
// a numeric segment indexes an array of tables (probes.gauge.0.x).
void apply_override(toml::table& root, const std::string& assignment, TomlContext& context);

}  // namespace sloshsph
