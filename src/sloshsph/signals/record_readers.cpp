#include "sloshsph/signals/record_readers.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

std::string at_line(const std::string& path, std::size_t line) { return path + ":" + std::to_string(line); }

std::ifstream open_or_throw(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(path, key, "cannot open the record file");
  return in;
}

bool read_line(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();  // files written on Windows
  return true;
}

// One number at the start of `s` (locale-independent: std::from_chars). Accepts a leading '+'
// and the Fortran exponent letter D. Returns the number of characters consumed (0: none).
std::size_t parse_one_number(std::string_view s, double& value) {
  std::string buf(s);
  for (char& c : buf)
    if (c == 'D' || c == 'd') c = 'E';
  std::size_t skip = (!buf.empty() && buf[0] == '+') ? 1 : 0;
  const char* first = buf.data() + skip;
  const char* last = buf.data() + buf.size();
  // from_chars rejects "+-1": a '+' must be followed by a digit or '.'.
  if (skip && (first == last || !(std::isdigit(static_cast<unsigned char>(*first)) || *first == '.'))) return 0;
  auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc()) return 0;
  return static_cast<std::size_t>(ptr - buf.data());
}

std::vector<std::string> split_fields(const std::string& line, bool commas) {
  std::vector<std::string> fields;
  std::string cur;
  for (char c : line) {
    const bool sep = std::isspace(static_cast<unsigned char>(c)) || (commas && c == ',');
    if (sep) {
      if (!cur.empty()) fields.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) fields.push_back(cur);
  return fields;
}

// A single number filling the whole token.
bool parse_exact(const std::string& token, double& value) {
  return !token.empty() && parse_one_number(token, value) == token.size();
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The number after the first '=' that follows `name` in `line`; false if absent.
bool value_after(const std::string& line, const std::string& name, double& value) {
  std::size_t p = line.find(name);
  if (p == std::string::npos) return false;
  p = line.find_first_not_of(" \t", p + name.size());
  if (p == std::string::npos || line[p] != '=') return false;
  p = line.find_first_not_of(" \t", p + 1);
  if (p == std::string::npos) return false;
  return parse_one_number(std::string_view(line).substr(p), value) > 0;
}

// NPTS and DT from a header line (see the formats in the header file).
bool parse_npts_dt(const std::string& raw, double& npts, double& dt) {
  const std::string line = upper(raw);
  if (line.find("NPTS") == std::string::npos) return false;
  if (value_after(line, "NPTS", npts)) return value_after(line, "DT", dt);
  // Older format: the two numbers come first, then the words "NPTS, DT".
  std::vector<double> numbers;
  for (const auto& f : split_fields(line.substr(0, line.find("NPTS")), true)) {
    double v;
    if (!parse_exact(f, v)) return false;
    numbers.push_back(v);
  }
  if (numbers.size() != 2) return false;
  npts = numbers[0];
  dt = numbers[1];
  return true;
}

}  // namespace

bool parse_fortran_numbers(const std::string& token, std::vector<double>& out) {
  std::string_view rest(token);
  const std::size_t before = out.size();
  while (!rest.empty()) {
    double v;
    const std::size_t n = parse_one_number(rest, v);
    if (n == 0) {
      out.resize(before);
      return false;
    }
    out.push_back(v);
    rest.remove_prefix(n);
    // Only a sign may start the next run-together field.
    if (!rest.empty() && rest[0] != '-' && rest[0] != '+') {
      out.resize(before);
      return false;
    }
  }
  return true;
}

GroundRecord read_peer_at2(const std::string& path, const std::string& key, double scale) {
  std::ifstream in = open_or_throw(path, key);
  GroundRecord rec;
  std::string line;
  std::size_t line_no = 0;
  double npts_d = 0.0, dt = 0.0;
  bool found = false;
  constexpr std::size_t kMaxHeaderLines = 10;
  while (line_no < kMaxHeaderLines && read_line(in, line)) {
    ++line_no;
    if (parse_npts_dt(line, npts_d, dt)) {
      found = true;
      break;
    }
    rec.header.push_back(line);
  }
  if (!found)
    throw InputError(path, key,
                     "not a PEER AT2 file: no 'NPTS= n, DT= dt' line in the first " +
                         std::to_string(kMaxHeaderLines) + " lines (expected 3 text lines, then NPTS and DT)");
  const std::string where = at_line(path, line_no);
  // At least 2 samples, as a CSV record (a single sample has no time step to integrate).
  if (!(npts_d >= 2.0) || npts_d != std::floor(npts_d) || npts_d > 1e9)
    throw InputError(where, key, "NPTS must be an integer from 2 to 1e9");
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError(where, key, "DT must be a positive time step in seconds");
  // The sample times i DT must be finite (a DT of 1e308 overflows).
  if (!std::isfinite(dt * npts_d)) throw InputError(where, key, "NPTS x DT is not a finite duration");
  const auto npts = static_cast<std::size_t>(npts_d);

  std::vector<double> values;
  // NPTS comes from the file: a hostile header (NPTS = 999999999) must not reserve gigabytes
  // up front (bad_alloc where memory is not overcommitted); the vector grows as values come.
  values.reserve(std::min<std::size_t>(npts, std::size_t{1} << 20));
  while (read_line(in, line)) {
    ++line_no;
    for (const auto& token : split_fields(line, true)) {
      const std::size_t before = values.size();
      if (!parse_fortran_numbers(token, values))
        throw InputError(at_line(path, line_no), key, "'" + token + "' is not a number");
      for (std::size_t i = before; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
          throw InputError(at_line(path, line_no), key, "'" + token + "' is not a finite number");
      if (values.size() > npts)
        throw InputError(at_line(path, line_no), key,
                         "more values than NPTS = " + std::to_string(npts) + " given in the header");
    }
  }
  if (values.size() < npts)
    throw InputError(at_line(path, line_no), key,
                     "the file ends after " + std::to_string(values.size()) + " values, but NPTS = " +
                         std::to_string(npts));
  const double factor = kStandardGravity * scale;  // record in g -> m/s^2
  for (double& v : values) {
    v *= factor;
    // A value that is finite in g can overflow once converted (1e308 g).
    if (!std::isfinite(v)) throw InputError(path, key, "a value times g (and the scale) is not a finite number");
  }
  rec.dt = dt;
  rec.acceleration = uniform_series(dt, std::move(values));
  return rec;
}

RecordTable read_record_table(const std::string& path, const std::string& key, const std::vector<std::size_t>& field_counts,
                        const std::string& expected, const CsvRecordOptions& options) {
  std::ifstream in = open_or_throw(path, key);
  RecordTable s;
  std::string line;
  std::size_t line_no = 0;
  bool first_data_line = true;
  const auto allowed = [&](std::size_t n) {
    if (!s.t.empty()) return n == s.values.size() + 1;  // every row as the first one
    return std::find(field_counts.begin(), field_counts.end(), n) != field_counts.end();
  };
  std::vector<double> row;
  while (read_line(in, line)) {
    ++line_no;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const auto fields = split_fields(line, true);
    if (fields.empty()) continue;
    const std::string where = at_line(path, line_no);
    row.assign(fields.size(), 0.0);
    bool numeric = allowed(fields.size());
    for (std::size_t j = 0; numeric && j < fields.size(); ++j) numeric = parse_exact(fields[j], row[j]);
    if (!numeric) {
      double v;
      bool any_number = false;
      for (const auto& f : fields) any_number = any_number || parse_exact(f, v);
      if (first_data_line && !any_number) {  // a header line of names
        first_data_line = false;
        continue;
      }
      if (!allowed(fields.size()))
        throw InputError(where, key,
                         s.t.empty() || field_counts.size() == 1
                             ? "expected " + expected + ", found " + std::to_string(fields.size())
                             : "found " + std::to_string(fields.size()) + " fields, but the first row has " +
                                   std::to_string(s.values.size() + 1));
      for (const auto& f : fields)
        if (!parse_exact(f, v)) throw InputError(where, key, "'" + f + "' is not a number");
    }
    first_data_line = false;
    for (double x : row)
      if (!std::isfinite(x)) throw InputError(where, key, "non-finite number");
    const double t = row[0] * options.time_factor;
    for (std::size_t j = 1; j < row.size(); ++j) row[j] *= options.value_factor * options.scale;
    for (double x : row)
      if (!std::isfinite(x) || !std::isfinite(t))
        throw InputError(where, key, "a number is not finite once converted to SI (time or value too large)");
    if (!s.t.empty() && !(t > s.t.back()))
      throw InputError(where, key, "time " + std::to_string(t) + " s is not after the previous row's time");
    if (s.t.empty()) s.values.resize(row.size() - 1);
    s.t.push_back(t);
    for (std::size_t j = 1; j < row.size(); ++j) s.values[j - 1].push_back(row[j]);
  }
  if (s.t.size() < 2)
    throw InputError(path, key, "a record needs at least 2 rows, found " + std::to_string(s.t.size()));
  return s;
}

TimeSeries read_two_column_csv(const std::string& path, const std::string& key, const CsvRecordOptions& options) {
  RecordTable table = read_record_table(path, key, {2}, "2 fields (time, value)", options);
  return {std::move(table.t), std::move(table.values[0])};
}

}  // namespace sloshsph
