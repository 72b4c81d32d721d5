// whole_number (core/number_text.h): the text must spell one finite number and nothing else.
#include <gtest/gtest.h>

#include "core/number_text.h"

namespace tightfit {
namespace {

TEST(WholeNumber, ReadsNumbersWrittenInFull) {
  EXPECT_EQ(whole_number("12"), 12.0);
  EXPECT_EQ(whole_number("-0.5"), -0.5);
  EXPECT_EQ(whole_number("1e-3"), 1e-3);
  EXPECT_EQ(whole_number("+7.25"), 7.25);
}

TEST(WholeNumber, RefusesTextThatIsNotOneFiniteNumber) {
  for (const char* text : {"", " ", "cm", "12 cm", "12cm", "1,5", "nan", "inf", "-inf", "1e400",
                           "0x", "--1"})
    EXPECT_FALSE(whole_number(text).has_value()) << "'" << text << "'";
}

}  // namespace
}  // namespace tightfit
