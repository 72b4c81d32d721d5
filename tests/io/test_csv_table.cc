// CSV tables: rows on disk before the writer goes away, numbers that read back, clear errors.
#include "io/csv_reader.h"
#include "io/csv_table.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace tightfit {
namespace {

using CsvFile = ScratchDir;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(CsvFile, EachRowIsOnDiskWhileTheWriterIsAlive) {
  const std::string file = path("pressure.csv");
  CsvTable table(file, {"step", "alpha", "p_mean_Pa"});
  EXPECT_EQ(read_text(file), "step,alpha,p_mean_Pa\n");
  table.write_row({1, 1.1, 250.5});
  EXPECT_EQ(read_text(file), "step,alpha,p_mean_Pa\n1,1.1,250.5\n");
  table.write_row({2, 1.2, 512.25});
  EXPECT_EQ(read_text(file), "step,alpha,p_mean_Pa\n1,1.1,250.5\n2,1.2,512.25\n");
  EXPECT_EQ(table.n_rows(), 2u);
}

TEST_F(CsvFile, NumbersKeepTenSignificantDigits) {
  const std::string file = path("numbers.csv");
  const double third = 1.0 / 3.0, large = 6.02214076e23, small = -1.602176634e-19;
  {
    CsvTable table(file, {"a", "b", "c", "d"});
    table.write_row({third, large, small, 123456789012LL});
  }
  const auto lines = lines_of(read_text(file));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], "0.3333333333,6.02214076e+23,-1.602176634e-19,123456789012");
  std::stringstream row(lines[1]);
  std::string cell;
  std::vector<double> back;
  while (std::getline(row, cell, ',')) back.push_back(std::stod(cell));
  // Ten significant digits round to within half a unit of the tenth: relative 5e-10.
  EXPECT_NEAR(back[0], third, 5e-10 * third);
  EXPECT_NEAR(back[1], large, 5e-10 * large);
  EXPECT_NEAR(back[2], small, 5e-10 * std::abs(small));
}

TEST_F(CsvFile, NanIsAnEmptyFieldAndInfinitiesAreSpelledOut) {
  const std::string file = path("nan.csv");
  CsvTable table(file, {"theta_deg", "p_Pa", "n"});
  table.write_row({45.0, std::numeric_limits<double>::quiet_NaN(), 0});
  table.write_row({135.0, std::numeric_limits<double>::infinity(), 1});
  table.write_row({225.0, -std::numeric_limits<double>::infinity(), 2});
  EXPECT_EQ(lines_of(read_text(file)),
            (std::vector<std::string>{"theta_deg,p_Pa,n", "45,,0", "135,inf,1", "225,-inf,2"}));
}

TEST_F(CsvFile, TextIsQuotedOnlyWhenItMustBe) {
  const std::string file = path("text.csv");
  CsvTable table(file, {"garment", "note, with comma"});
  table.write_row({"4 5T", std::string("said \"tight\"")});
  EXPECT_EQ(read_text(file), "garment,\"note, with comma\"\n4 5T,\"said \"\"tight\"\"\"\n");
}

TEST_F(CsvFile, RowOfTheWrongLengthIsRejected) {
  CsvTable table(path("short.csv"), {"a", "b"});
  EXPECT_THROW(table.write_row({1.0}), std::invalid_argument);
  EXPECT_THROW(table.write_row({1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_EQ(table.n_rows(), 0u);
}

TEST(CsvTable, UnopenablePathThrowsNamingIt) {
  const std::string bad = "/nonexistent_tightfit_dir/pressure.csv";
  try {
    CsvTable table(bad, {"a"});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
}

// The reader against text written by hand in the format above (not by the writer alone): quoted
// commas and doubled quotes, a missing number, infinities, a CRLF line end, a row cut short.
TEST_F(CsvFile, ReaderGivesBackFieldsAndNumbers) {
  const std::string file = path("regions.csv");
  {
    std::ofstream out(file);
    out << "step,region,p_mean_Pa\n"
           "1,\"bust, left\",250.5\n"
           "1,\"said \"\"tight\"\"\",\r\n"
           "\n"
           "2,waist,inf\n"
           "3,cut short\n";
  }
  const std::optional<CsvRows> csv = CsvRows::read(file);
  ASSERT_TRUE(csv.has_value());
  EXPECT_EQ(csv->columns(), (std::vector<std::string>{"step", "region", "p_mean_Pa"}));
  ASSERT_EQ(csv->n_rows(), 3u);
  const std::size_t region = csv->column("region"), mean = csv->column("p_mean_Pa");
  EXPECT_EQ(csv->text(0, region), "bust, left");
  EXPECT_EQ(csv->text(1, region), "said \"tight\"");
  EXPECT_DOUBLE_EQ(csv->number(0, mean), 250.5);
  EXPECT_TRUE(std::isnan(csv->number(1, mean)));
  EXPECT_EQ(csv->number(2, mean), std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(csv->number(2, csv->column("step")), 2.0);
}

TEST_F(CsvFile, ReaderNamesTheFileTheRowAndTheColumn) {
  const std::string file = path("bad.csv");
  {
    std::ofstream out(file);
    out << "step,p_mean_Pa\n1,12 Pa\n";
  }
  const std::optional<CsvRows> csv = CsvRows::read(file);
  ASSERT_TRUE(csv.has_value());
  try {
    csv->number(0, csv->column("p_mean_Pa"));
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find("row 1"), std::string::npos) << what;
    EXPECT_NE(what.find("p_mean_Pa"), std::string::npos) << what;
  }
  EXPECT_THROW(csv->column("p_peak_Pa"), std::runtime_error);
  EXPECT_FALSE(CsvRows::read(path("missing.csv")).has_value());
}

}  // namespace
}  // namespace tightfit
