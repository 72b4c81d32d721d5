// The region table of `tightfit compare`: each named region's mean and peak pressure at the
// last load step both backends finished, side by side, with their difference. Read from the
// regions.csv each backend's run wrote (the "regions" measurement, docs/measurements.md).
#pragma once

#include "io/text_table.h"

#include <optional>
#include <string>

namespace tightfit {

// The table from DIR/<first>/regions.csv and DIR/<second>/regions.csv; empty when either file
// is missing (the case lists no regions) or they share no step. Throws std::runtime_error
// naming the file when one lacks the columns it needs.
std::optional<TextTable> region_comparison(const std::string& first_csv, const std::string& first,
                                           const std::string& second_csv,
                                           const std::string& second);

}  // namespace tightfit
