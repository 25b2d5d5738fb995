#pragma once
// Simple statistics of a series, and a reader for the time-series CSV files a run writes
// (io/csv_writer.hpp: one header row of column names, then rows of numbers).
#include <string>
#include <vector>

namespace sloshsph {

double mean(const std::vector<double>& x);
// Root mean square about ZERO: sqrt(mean(x^2)) (the thesis' sigma of a zero-mean response).
double rms(const std::vector<double>& x);
// Standard deviation about the mean (population: divides by n).
double standard_deviation(const std::vector<double>& x);
// Largest |x| (the thesis' peak value chi).
double peak_abs(const std::vector<double>& x);

// A CSV table: column names from the header, and one vector of values per column.
struct CsvTable {
  std::string source;               // the file read (for messages)
  std::vector<std::string> names;   // header, in file order
  std::vector<std::vector<double>> columns;

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  bool has(const std::string& name) const;
  // The column named `name`; InputError(source, "", "no column ...") listing the names otherwise.
  const std::vector<double>& column(const std::string& name) const;
};

// Reads a table: blank lines and lines starting with '#' are skipped; the first other line is the
// header (comma-separated names, surrounding spaces trimmed; empty or repeated names are errors);
// each following line must have as many comma-separated numbers (`nan`, `inf`, `-inf` allowed, as
// CsvWriter writes them). Errors: InputError("file:line", "", what).
CsvTable read_csv_table(const std::string& path);

}  // namespace sloshsph
