// RAL-GZ 387's compression classes by the pressure at B (cases/compression_class.h): the
// standard's ranges, I 18-21, II 23-32, III 34-46, IV 49 mmHg and more, their edges included,
// and the gaps between them named as such.
#include "cases/compression_class.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

TEST(CompressionClass, TheStandardsRanges) {
  EXPECT_EQ(ral_gz_387_class(17.9).number, 0.0);
  EXPECT_EQ(ral_gz_387_class(18.0).number, 1.0);
  EXPECT_EQ(ral_gz_387_class(21.0).number, 1.0);
  EXPECT_EQ(ral_gz_387_class(22.0).number, 1.5);
  EXPECT_EQ(ral_gz_387_class(23.0).number, 2.0);
  EXPECT_EQ(ral_gz_387_class(32.0).number, 2.0);
  EXPECT_EQ(ral_gz_387_class(33.0).number, 2.5);
  EXPECT_EQ(ral_gz_387_class(34.0).number, 3.0);
  EXPECT_EQ(ral_gz_387_class(46.0).number, 3.0);
  EXPECT_EQ(ral_gz_387_class(47.5).number, 3.5);
  EXPECT_EQ(ral_gz_387_class(49.0).number, 4.0);
  EXPECT_EQ(ral_gz_387_class(80.0).number, 4.0);
  EXPECT_EQ(ral_gz_387_class(25.4).text, "class II (23-32 mmHg)");
  EXPECT_EQ(ral_gz_387_class(60.0).text, "class IV (49 mmHg and more)");
  EXPECT_EQ(ral_gz_387_class(33.0).text, "between class II and class III: neither");
  EXPECT_EQ(ral_gz_387_class(5.0).text, "below class I (18-21 mmHg)");
}

}  // namespace
}  // namespace tightfit
