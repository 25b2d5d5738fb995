#pragma once
// Readers for excitation records: PEER AT2 strong-motion files and two-column CSV files.
// Every problem is an InputError naming "file:line" and the case key that gave the file
// (e.g. `excitation.file`), so the user sees which key and which line to fix.
#include <string>
#include <vector>

#include "sloshsph/signals/time_series.hpp"

namespace sloshsph {

// A ground-motion record as read from a file.
struct GroundRecord {
  TimeSeries acceleration;          // t_i = i * dt from 0 s; value in m/s^2 (already scaled)
  double dt = 0.0;                  // s
  std::vector<std::string> header;  // the text lines before the NPTS/DT line (event, station, units)
};

// PEER AT2 file: text lines (3 in the PEER formats), then a line giving NPTS and DT, then NPTS
// accelerations in g, any count per line. Accepted NPTS/DT lines (case-insensitive, any spacing):
//   `NPTS=  1559, DT= .02000 SEC`        (PEER strong-motion database, old format)
//   `NPTS=   5000, DT=   .0050 SEC,`     (PEER NGA format)
//   `  1559    0.0200    NPTS, DT`       (older PEER format: numbers first)
// Numbers are Fortran style: `.123`, `-1.2E-02`, `1.2D-02`, and fixed-width fields that run
// together (`-0.12345-0.23456`). Values are converted with g = kStandardGravity = 9.80665 m/s^2
// and multiplied by `scale`. Errors (InputError, key = `key`): missing file, no NPTS/DT line in
// the first 10 lines, a non-numeric token (with its line), fewer or more values than NPTS.
GroundRecord read_peer_at2(const std::string& path, const std::string& key, double scale = 1.0);

struct CsvRecordOptions {
  double time_factor = 1.0;   // multiplies the first column to give seconds (e.g. 1e-3 for ms)
  double value_factor = 1.0;  // multiplies the second column to give SI (e.g. kStandardGravity for g)
  double scale = 1.0;         // extra user scale on the values
};

// Two-column file `time, value`: optional header line (the first data line if it is not
// numeric), `#` comments (whole line or trailing), blank lines ignored, separators comma
// and/or whitespace. Checks (InputError with the line): exactly two fields a row, finite
// numbers, strictly increasing time, at least 2 rows.
TimeSeries read_two_column_csv(const std::string& path, const std::string& key,
                               const CsvRecordOptions& options = {});

// A file of rows `time, value_1, ..., value_k`, read as read_two_column_csv reads two columns.
struct RecordTable {
  std::vector<double> t;                    // s (the first column times time_factor)
  std::vector<std::vector<double>> values;  // values[j][i]: column j + 2 of row i, times value_factor and scale
};

// The same rules and checks as read_two_column_csv, with any field count of `field_counts`
// (every row the count of the first one). `expected` describes them in the messages, e.g.
// "2 fields (time, value)": "expected 2 fields (time, value), found 3".
RecordTable read_record_table(const std::string& path, const std::string& key, const std::vector<std::size_t>& field_counts,
                        const std::string& expected, const CsvRecordOptions& options = {});

// Parses one whitespace-free token that may hold several Fortran fixed-width numbers run
// together; appends them to `out`. Returns false if the token is not made of numbers.
bool parse_fortran_numbers(const std::string& token, std::vector<double>& out);

}  // namespace sloshsph
