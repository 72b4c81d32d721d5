// The compression classes of medical compression stockings in the German quality standard
// RAL-GZ 387 (the pressure at the ankle, measuring point B, in mmHg): I 18-21, II 23-32,
// III 34-46, IV 49 and more. A pressure between two classes meets neither.
#pragma once

#include <string>

namespace tightfit {

struct CompressionClass {
  // 1 to 4 for a class met; between two classes the mean of the two (1.5, 2.5, 3.5); 0 below
  // class I.
  double number = 0.0;
  std::string text;  // "class II (23-32 mmHg)", "between class I and class II", ...
};

CompressionClass ral_gz_387_class(double ankle_pressure_mmHg);

// The pressure range at B of class `number` (1 to 4), mmHg; class IV has no upper bound
// (infinity). Throws std::invalid_argument for another number.
struct CompressionClassRange {
  double low_mmHg = 0.0, high_mmHg = 0.0;
};
CompressionClassRange ral_gz_387_range(int number);

}  // namespace tightfit
