#include "cases/compression_class.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace tightfit {

namespace {

struct ClassRange {
  const char* name;
  double low_mmHg, high_mmHg;  // inclusive
};

// RAL-GZ 387/1, the pressure at B of each class.
constexpr ClassRange classes[] = {{"I", 18, 21},
                                  {"II", 23, 32},
                                  {"III", 34, 46},
                                  {"IV", 49, std::numeric_limits<double>::infinity()}};

}  // namespace

CompressionClass ral_gz_387_class(double p_mmHg) {
  if (p_mmHg < classes[0].low_mmHg) return {0.0, "below class I (18-21 mmHg)"};
  for (int k = 0; k < 4; ++k) {
    const ClassRange& c = classes[k];
    if (p_mmHg >= c.low_mmHg && p_mmHg <= c.high_mmHg) {
      const std::string range = k == 3 ? "49 mmHg and more"
                                       : std::to_string(int(c.low_mmHg)) + "-" +
                                             std::to_string(int(c.high_mmHg)) + " mmHg";
      return {double(k + 1), std::string("class ") + c.name + " (" + range + ")"};
    }
    if (k < 3 && p_mmHg > c.high_mmHg && p_mmHg < classes[k + 1].low_mmHg)
      return {k + 1.5, std::string("between class ") + c.name + " and class " +
                           classes[k + 1].name + ": neither"};
  }
  return {0.0, "not a pressure"};  // NaN
}

CompressionClassRange ral_gz_387_range(int number) {
  if (number < 1 || number > 4)
    throw std::invalid_argument("no compression class " + std::to_string(number) +
                                " in RAL-GZ 387 (I to IV)");
  return {classes[number - 1].low_mmHg, classes[number - 1].high_mmHg};
}

}  // namespace tightfit
