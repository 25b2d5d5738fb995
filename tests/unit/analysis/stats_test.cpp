// Series statistics and the CSV table reader (src/sloshsph/analysis/stats.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "sloshsph_analysis_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

TEST(Stats, MeanRmsStdPeak) {
  const std::vector<double> x{1.0, -3.0, 2.0, 4.0};
  EXPECT_DOUBLE_EQ(mean(x), 1.0);
  EXPECT_DOUBLE_EQ(rms(x), std::sqrt(30.0 / 4));
  EXPECT_DOUBLE_EQ(standard_deviation(x), std::sqrt((0 + 16 + 1 + 9) / 4.0));
  EXPECT_DOUBLE_EQ(peak_abs(x), 4.0);
  EXPECT_THROW(mean({}), std::invalid_argument);
}

TEST(CsvTable, ReadsRunTimeSeries) {
  // The format CsvWriter writes (io/csv_writer.hpp), with a comment and a nan.
  const std::string path = write_temp("ts.csv",
                                      "# written by a test\n"
                                      "time,eta:right,F_w\n"
                                      "0,0.001,-2.5\n"
                                      "0.01, 0.002 ,nan\n"
                                      "0.02,1e-3,-inf\n");
  const CsvTable t = read_csv_table(path);
  ASSERT_EQ(t.names.size(), 3u);
  EXPECT_EQ(t.names[1], "eta:right");
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_DOUBLE_EQ(t.column("time")[2], 0.02);
  EXPECT_DOUBLE_EQ(t.column("eta:right")[1], 0.002);
  EXPECT_TRUE(std::isnan(t.column("F_w")[1]));
  EXPECT_TRUE(std::isinf(t.column("F_w")[2]));
  EXPECT_TRUE(t.has("F_w"));
  try {
    t.column("p:P1");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("eta:right"), std::string::npos);  // lists the columns
  }
}

TEST(CsvTable, ErrorsNameTheLine) {
  auto where = [](const std::string& text) {
    const std::string path = write_temp("bad.csv", text);
    try {
      read_csv_table(path);
    } catch (const InputError& e) {
      return e.where().substr(path.size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(where("a,b\n1,2\n3,x\n"), ":3");
  EXPECT_EQ(where("a,b\n1,2\n3\n"), ":3");
  EXPECT_EQ(where("a,a\n1,2\n"), ":1");
  EXPECT_EQ(where("a,,b\n"), ":1");
  EXPECT_EQ(where(""), "");  // no header: the file itself
  EXPECT_THROW(read_csv_table("/nonexistent/t.csv"), InputError);
}

}  // namespace
}  // namespace sloshsph
