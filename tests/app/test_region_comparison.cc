// `tightfit compare`'s region table (app/region_comparison.h), read from two regions.csv files
// written here with known numbers: the last step's rows side by side, the relative difference
// of the means in percent, and no table where the runs cannot be compared.
#include "app/region_comparison.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace tightfit {
namespace {

class RegionComparison : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("tightfit_region_comparison_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (folder_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  std::filesystem::path folder_;
};

const char* kHeader = "step,alpha,region,contact_area_m2,p_mean_Pa,p_peak_Pa,note\n";

TEST_F(RegionComparison, LastStepSideBySideWithTheDifferenceInPercent) {
  // Step 0's rows must be left out; at step 1 the second run reads 2 % more at "B" and 0.5 %
  // less at "calf, left" (a quoted name with a comma).
  const std::string first = write("a.csv", std::string(kHeader) +
                                               "0,1,B,1,999,9999,\n"
                                               "1,1.1,B,1,1000,1500,\n"
                                               "1,1.1,\"calf, left\",1,400,800,\n");
  const std::string second = write("b.csv", std::string(kHeader) +
                                                "0,1,B,1,1,1,\n"
                                                "1,1.1,\"calf, left\",1,398,790,\n"
                                                "1,1.1,B,1,1020,1490,\n");
  const auto table = region_comparison(first, "massspring", second, "fem");
  ASSERT_TRUE(table.has_value());
  EXPECT_EQ(table->n_rows(), 2u);
  const std::string text = table->render();
  EXPECT_NE(text.find("load step 1"), std::string::npos) << text;
  EXPECT_NE(text.find("2.000"), std::string::npos) << text;   // (1020 - 1000) / 1000
  EXPECT_EQ(text.find("-2.000"), std::string::npos) << text;  // not (1000 - 1020) / 1000
  EXPECT_NE(text.find("-0.500"), std::string::npos) << text;  // (398 - 400) / 400
  EXPECT_NE(text.find("calf, left"), std::string::npos) << text;
  EXPECT_EQ(text.find("999"), std::string::npos) << "step 0 is not the last step:\n" << text;
}

TEST_F(RegionComparison, NoTableWhereTheRunsCannotBeCompared) {
  const std::string one_step = write("a.csv", std::string(kHeader) + "1,1.1,B,1,1000,1500,\n");
  const std::string other_step = write("b.csv", std::string(kHeader) + "2,1.2,B,1,1000,1500,\n");
  EXPECT_FALSE(region_comparison(one_step, "a", other_step, "b").has_value());
  EXPECT_FALSE(
      region_comparison(one_step, "a", (folder_ / "missing.csv").string(), "b").has_value());
}

TEST_F(RegionComparison, AFileWithoutTheMeanColumnIsNamed) {
  const std::string good = write("a.csv", std::string(kHeader) + "1,1.1,B,1,1000,1500,\n");
  const std::string bad = write("b.csv", "step,region,p_peak_Pa\n1,B,1500\n");
  try {
    region_comparison(good, "a", bad, "b");
    FAIL() << "a regions.csv without p_mean_Pa was read";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("b.csv"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("p_mean_Pa"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace tightfit
