#include "sloshsph/io/csv_writer.hpp"

#include "sloshsph/io/files.hpp"

#include <cerrno>
#include <fstream>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace sloshsph {

std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : columns_(columns.size()), path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  std::string header;
  for (std::size_t k = 0; k < columns.size(); ++k) header += (k ? "," : "") + columns[k];
  header += "\n";
  std::fputs(header.c_str(), file_);
  std::fflush(file_);
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, std::size_t keep_rows)
    : columns_(columns.size()), path_(path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path + " to continue it");
  std::string header, line, kept;
  std::getline(in, header);
  std::string expected;
  for (std::size_t k = 0; k < columns.size(); ++k) expected += (k ? "," : "") + columns[k];
  if (header != expected) throw std::runtime_error(path + ": its columns differ from the run's");
  kept = header + "\n";
  for (std::size_t r = 0; r < keep_rows; ++r) {
    if (!std::getline(in, line)) throw std::runtime_error(path + ": fewer rows than the checkpoint recorded");
    kept += line + "\n";
  }
  in.close();
  write_file_atomic(path, kept);
  file_ = std::fopen(path.c_str(), "a");
  if (!file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
}

void CsvWriter::write_row(const std::vector<double>& values) {
  if (values.size() != columns_) throw std::logic_error("CSV row width does not match the header of " + path_);
  std::string row;
  row.reserve(values.size() * 14);
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) row += ',';
    row += format_number(values[k]);
  }
  row += '\n';
  std::fputs(row.c_str(), file_);
  std::fflush(file_);
}

void CsvWriter::flush() { std::fflush(file_); }

}  // namespace sloshsph
