#include "sloshsph/analysis/stats.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

void check_not_empty(const std::vector<double>& x, const char* what) {
  if (x.empty()) throw std::invalid_argument(std::string(what) + " of an empty series");
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

// A whole-field number (locale-independent; a leading '+' is accepted).
bool parse_number(const std::string& field, double& v) {
  const char* first = field.data();
  const char* last = field.data() + field.size();
  if (first != last && *first == '+') ++first;
  if (first == last) return false;
  auto [ptr, ec] = std::from_chars(first, last, v);
  return ec == std::errc() && ptr == last;
}

}  // namespace

double mean(const std::vector<double>& x) {
  check_not_empty(x, "mean");
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double rms(const std::vector<double>& x) {
  check_not_empty(x, "rms");
  double s = 0.0;
  for (double v : x) s += v * v;
  return std::sqrt(s / static_cast<double>(x.size()));
}

double standard_deviation(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size()));
}

double peak_abs(const std::vector<double>& x) {
  check_not_empty(x, "peak");
  double p = 0.0;
  for (double v : x) p = std::max(p, std::abs(v));
  return p;
}

bool CsvTable::has(const std::string& name) const {
  for (const auto& n : names)
    if (n == name) return true;
  return false;
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return columns[k];
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError(source, "", "no column '" + name + "' (columns: " + list + ")");
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the CSV file");
  CsvTable table;
  table.source = path;
  std::string line;
  std::size_t line_no = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    const std::string where = path + ":" + std::to_string(line_no);
    const auto fields = split_commas(content);
    if (!have_header) {
      for (const auto& name : fields) {
        if (name.empty()) throw InputError(where, "", "empty column name in the header");
        if (table.has(name)) throw InputError(where, "", "column '" + name + "' appears twice in the header");
        table.names.push_back(name);
      }
      table.columns.resize(table.names.size());
      have_header = true;
      continue;
    }
    if (fields.size() != table.names.size())
      throw InputError(where, "", "expected " + std::to_string(table.names.size()) + " values, found " +
                                      std::to_string(fields.size()));
    for (std::size_t k = 0; k < fields.size(); ++k) {
      double v;
      if (!parse_number(fields[k], v))
        throw InputError(where, "", "'" + fields[k] + "' in column '" + table.names[k] + "' is not a number");
      table.columns[k].push_back(v);
    }
  }
  if (!have_header) throw InputError(path, "", "no header line (the file is empty)");
  return table;
}

}  // namespace sloshsph
