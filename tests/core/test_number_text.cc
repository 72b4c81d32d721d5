// whole_number and auto_or_count (core/number_text.h): the text must spell one finite number
// (or count, or auto) and nothing else.
#include <gtest/gtest.h>

#include "core/number_text.h"

#include <stdexcept>

namespace tightfit {
namespace {

TEST(WholeNumber, ReadsNumbersWrittenInFull) {
  EXPECT_EQ(whole_number("12"), 12.0);
  EXPECT_EQ(whole_number("-0.5"), -0.5);
  EXPECT_EQ(whole_number("1e-3"), 1e-3);
  EXPECT_EQ(whole_number("+7.25"), 7.25);
}

TEST(WholeNumber, RefusesTextThatIsNotOneFiniteNumber) {
  for (const char* text :
       {"", " ", "cm", "12 cm", "12cm", "1,5", "nan", "inf", "-inf", "1e400", "0x", "--1"})
    EXPECT_FALSE(whole_number(text).has_value()) << "'" << text << "'";
}

TEST(AutoOrCount, ReadsAutoOrDigitsWithinTheBound) {
  EXPECT_FALSE(auto_or_count("auto", "E", 100).has_value());
  EXPECT_EQ(auto_or_count("0", "E", 100), 0);
  EXPECT_EQ(auto_or_count("100", "E", 100), 100);
  for (const char* text :
       {"", "101", "-1", "+2", "2.5", "2 ", " 2", "two", "Auto", "1e2", "99999999999"})
    EXPECT_THROW(auto_or_count(text, "E", 100), std::invalid_argument) << "'" << text << "'";
}

}  // namespace
}  // namespace tightfit
