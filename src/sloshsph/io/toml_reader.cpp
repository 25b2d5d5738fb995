#include "sloshsph/io/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

std::string show(const toml::node& n) {
  std::ostringstream s;
  if (n.is_string()) s << '"' << n.value<std::string>().value_or("") << '"';
  else if (n.is_integer()) s << n.value<long long>().value_or(0);
  else if (n.is_floating_point()) s << n.value<double>().value_or(0.0);
  else if (n.is_boolean()) s << (n.value<bool>().value_or(false) ? "true" : "false");
  else return type_name(n);
  return s.str();
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A TOML number as a double. toml++'s value<double>() is empty for an integer beyond 2^53
// (not exactly representable), which .value() would turn into std::bad_optional_access.
double to_double(const toml::node& n) {
  if (const auto i = n.value_exact<std::int64_t>()) return static_cast<double>(*i);
  return n.value<double>().value_or(std::numeric_limits<double>::quiet_NaN());
}

// The value of an index segment; one too long for std::stoul (which would throw
// std::out_of_range, an "internal error") saturates, to be reported as out of range.
std::size_t index_value(const std::string& s) {
  return s.size() > 9 ? std::numeric_limits<std::size_t>::max() : std::stoul(s);
}

}  // namespace

TableReader::TableReader(const toml::table& table, std::string prefix, std::shared_ptr<TomlContext> context)
    : table_(&table), prefix_(std::move(prefix)), context_(std::move(context)) {}

std::string TableReader::location(const std::string& key) const {
  const std::string dotted = path(key);
  if (context_->overridden.count(dotted)) return context_->file + " (--set " + dotted + ")";
  const toml::node* n = key.empty() ? nullptr : table_->get(key);
  const toml::source_region& src = n ? n->source() : table_->source();
  if (src.begin.line > 0) return context_->file + ":" + std::to_string(src.begin.line);
  return context_->file;
}

void TableReader::fail(const std::string& key, const std::string& what) const {
  throw InputError(location(key), path(key), what);
}

bool TableReader::has(const std::string& key) const { return table_->contains(key); }

const toml::node* TableReader::node(const std::string& key) {
  read_.insert(key);
  const toml::node* n = table_->get(key);
  if (n) context_->locations[path(key)] = location(key);
  return n;
}

double TableReader::as_number(const std::string& key, const toml::node& n) const {
  if (!n.is_number()) fail(key, "expected a number, got " + show(n));
  const double v = to_double(n);
  if (!std::isfinite(v)) fail(key, "expected a finite number, got " + show(n));
  return v;
}

double TableReader::number(const std::string& key, double fallback) {
  const toml::node* n = node(key);
  return n ? as_number(key, *n) : fallback;
}

double TableReader::number(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) fail(key, "is required (a number)");
  return as_number(key, *n);
}

std::optional<double> TableReader::optional_number(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return as_number(key, *n);
}

double TableReader::positive(const std::string& key, double fallback) {
  const double v = number(key, fallback);
  if (!(v > 0.0)) fail(key, "expected a positive number, got " + std::to_string(v));
  return v;
}

double TableReader::positive(const std::string& key) {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, "expected a positive number, got " + show(*table_->get(key)));
  return v;
}

std::optional<double> TableReader::optional_positive(const std::string& key) {
  auto v = optional_number(key);
  if (v && !(*v > 0.0)) fail(key, "expected a positive number, got " + show(*table_->get(key)));
  return v;
}

double TableReader::non_negative(const std::string& key, double fallback) {
  const double v = number(key, fallback);
  if (v < 0.0) fail(key, "expected a number >= 0, got " + std::to_string(v));
  return v;
}

double TableReader::in_range(const std::string& key, double fallback, double lo, double hi) {
  const double v = number(key, fallback);
  if (v < lo || v > hi) {
    std::ostringstream s;
    s << "expected a number in [" << lo << ", " << hi << "], got " << v;
    fail(key, s.str());
  }
  return v;
}

long long TableReader::integer(const std::string& key, long long fallback, long long lo, long long hi) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (!n->is_integer()) fail(key, "expected an integer, got " + show(*n));
  const long long v = n->value<long long>().value();
  if (v < lo || v > hi) fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(v));
  return v;
}

bool TableReader::boolean(const std::string& key, bool fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (!n->is_boolean()) fail(key, "expected true or false, got " + show(*n));
  return n->value<bool>().value();
}

std::string TableReader::string(const std::string& key, const std::string& fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (!n->is_string()) fail(key, "expected a string, got " + show(*n));
  return n->value<std::string>().value();
}

std::string TableReader::string(const std::string& key) {
  if (!has(key)) {
    read_.insert(key);
    fail(key, "is required (a string)");
  }
  return string(key, "");
}

std::string TableReader::choice(const std::string& key, const std::string& fallback,
                                const std::vector<std::string>& allowed) {
  const std::string v = string(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
    fail(key, "expected one of " + list + ", got \"" + v + "\"");
  }
  return v;
}

Vec2 TableReader::point(const std::string& key) {
  auto p = optional_point(key);
  if (!p) fail(key, "is required (a point [x, y] in m)");
  return *p;
}

std::optional<Vec2> TableReader::optional_point(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
    fail(key, "expected a point [x, y] of two numbers, got " + show(*n));
  const Vec2 p{to_double((*a)[0]), to_double((*a)[1])};
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(key, "expected finite coordinates");
  return p;
}

std::optional<Vec3> TableReader::optional_point3(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3 || !(*a)[0].is_number() || !(*a)[1].is_number() || !(*a)[2].is_number())
    fail(key, "expected [x, y, z], three numbers, got " + show(*n));
  const Vec3 p{to_double((*a)[0]), to_double((*a)[1]), to_double((*a)[2])};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail(key, "expected finite coordinates");
  return p;
}

std::vector<Vec2> TableReader::points(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) fail(key, "is required (a list of points [[x, y], ...])");
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected a list of points [[x, y], ...], got " + show(*n));
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < a->size(); ++k) {
    const toml::array* p = (*a)[k].as_array();
    if (!p || p->size() != 2 || !(*p)[0].is_number() || !(*p)[1].is_number())
      fail(key, "point " + std::to_string(k + 1) + " is not [x, y] with two numbers");
    out.push_back({to_double((*p)[0]), to_double((*p)[1])});
  }
  return out;
}

std::optional<TableReader> TableReader::table(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (!n->is_table()) fail(key, "expected a table [" + path(key) + "], got " + show(*n));
  return TableReader(*n->as_table(), path(key), context_);
}

std::vector<TableReader> TableReader::array_of_tables(const std::string& key) {
  std::vector<TableReader> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of tables [[" + path(key) + "]], got " + show(*n));
  for (std::size_t k = 0; k < a->size(); ++k) {
    if (!(*a)[k].is_table()) fail(key, "entry " + std::to_string(k + 1) + " is not a table");
    out.emplace_back(*(*a)[k].as_table(), path(key) + "." + std::to_string(k), context_);
  }
  return out;
}

void TableReader::finish() const {
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (read_.count(key)) continue;
    std::string best;
    std::size_t best_d = 3;
    for (const auto& r : read_) {
      const std::size_t d = edit_distance(key, r);
      if (d < best_d) {
        best_d = d;
        best = r;
      }
    }
    std::string known;
    for (const auto& r : read_) known += (known.empty() ? "" : ", ") + r;
    std::string what = "unknown key";
    if (!best.empty()) what += " (did you mean '" + path(best) + "'?)";
    what += "; known keys here: " + known;
    const std::string where = context_->overridden.count(path(key)) ? context_->file + " (--set " + path(key) + ")"
                              : v.source().begin.line > 0
                                  ? context_->file + ":" + std::to_string(v.source().begin.line)
                                  : context_->file;
    throw InputError(where, path(key), what);
  }
}

void apply_override(toml::table& root, const std::string& assignment, TomlContext& context) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(context.file + " (--set " + assignment + ")", "", "expected KEY=VALUE, e.g. --set time.end=2");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  const std::vector<std::string> parts = split(key, '.');
  for (const auto& p : parts)
    if (p.empty()) throw InputError(context.file + " (--set " + assignment + ")", key, "malformed key (empty segment)");

  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed = toml::table{};
    parsed.insert("v", text);  // not TOML: a bare string
  }

  toml::node* cur = &root;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& seg = parts[k];
    std::string parent;
    for (std::size_t m = 0; m < k; ++m) parent += (m ? "." : "") + parts[m];
    parent = k == 0 ? std::string("the case") : "'" + parent + "'";
    if (is_index(seg) && !cur->is_array())
      throw InputError(context.file + " (--set " + assignment + ")", key, parent + " is not an array of tables, so '" + seg + "' cannot index it");
    if (toml::table* t = cur->as_table()) {
      if (!t->contains(seg)) t->insert(seg, toml::table{});
      cur = t->get(seg);
    } else if (toml::array* a = cur->as_array(); a && is_index(seg)) {
      const std::size_t idx = index_value(seg);
      if (idx >= a->size())
        throw InputError(context.file + " (--set " + assignment + ")", key, "index " + seg + " is out of range (" + std::to_string(a->size()) + " entries)");
      cur = a->get(idx);
    } else {
      throw InputError(context.file + " (--set " + assignment + ")", key, "'" + seg + "' does not name a table");
    }
  }
  const std::string& last = parts.back();
  if (toml::table* t = cur->as_table()) {
    t->insert_or_assign(last, *parsed.get("v"));
  } else if (toml::array* a = cur->as_array(); a && is_index(last) && index_value(last) < a->size()) {
    a->replace(a->begin() + static_cast<std::ptrdiff_t>(index_value(last)), *parsed.get("v"));
  } else {
    throw InputError(context.file + " (--set " + assignment + ")", key, "the parent of '" + last + "' is not a table");
  }
  context.overridden.insert(key);
}

}  // namespace sloshsph
