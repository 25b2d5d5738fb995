#pragma once
// Time-series CSV: one header row of column names (exactly as documented, e.g.
// `time`, `eta:right`, `p:P1`, `F_w`), then one row per sample. Numbers are written
// with 10 significant digits. Rows are flushed as they are written, so a run that
// stops early leaves every sample up to the stop.
#include <cstdio>
#include <string>
#include <vector>

namespace sloshsph {

class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);
  // Continues an existing file (a resumed run): keeps the header, which must name `columns`,
  // and the first `keep_rows` rows, drops any later ones (written after the checkpoint),
  // then appends. Throws std::runtime_error when the file is missing or shorter.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, std::size_t keep_rows);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void write_row(const std::vector<double>& values);
  void flush();

 private:
  std::FILE* file_ = nullptr;
  std::size_t columns_ = 0;
  std::string path_;
};

// Formats a double as the CSV does (shortest form up to 10 significant digits; nan, inf).
std::string format_number(double v);

}  // namespace sloshsph
